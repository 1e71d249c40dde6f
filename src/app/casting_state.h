#pragma once
// The Casting panel's state (casting.h): the alloy, mould and temperatures the user chose (the feeders are parts), the
// simulation they key, and what the views show of it (which field, the time of the freezing front).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/texture.h"
#include "vox/analysis/casting.h"
#include "vox/workflow/casting_run.h"

namespace vox::app {

// What one simulation was run for.
struct CastingKey {
  uint64_t model_version = 0;
  std::string units;  // the model's length units (the Mass panel can change them without a new model version)
  std::string alloy = "a356", mould = "silica-sand";
  double superheat_k = 50.0;
  double mould_temperature_c = -1000.0;  // below -273: the mould's own
  std::vector<Feeder> feeders;           // the scene's feeder parts, placed (wantedCastingKey fills them in)
  bool operator==(const CastingKey&) const = default;
};

struct CastingOutcome {
  uint64_t id = 0;  // this run's (takeId): what the views are keyed by
  CastingKey key;
  workflow::CastingRun run;
  double seconds = 0.0;
  double first_solid_s = 0.0;  // the earliest a metal voxel is solid: where the time colours and the slider start
  // Each voxel of the model's grid: 0 outside the metal, else 2..255 for its solidification time from first_solid_s
  // to the last (made on the worker: the freezing front recolours from it cheaply).
  std::vector<uint8_t> time_bytes;
  double niyama_scale = 1.0;  // the Niyama colours' top: the 95th percentile of the metal's (a pure metal's runs high)
};

// What the views colour the metal by.
enum class CastingField { kTime, kNiyama, kModulus };

struct CastingUi {
  CastingKey chosen;   // the settings in the panel (model_version filled in when asked)
  bool asked = false;  // "Simulate" pressed for `asked_key`: the run is started, and not again
  CastingKey asked_key;
  bool placing_feeder = false;  // the next click on the 3D view places a feeder there
  CastingField field = CastingField::kTime;
  double time_shown = -1.0;  // the freezing front's time, s (< 0: the end, all solid)
  bool playing = false;
  int32_t selected_spot = -1;  // in the result selected_result
  uint64_t selected_result = 0;
  uint64_t seen_result = 0;        // the last run shown: a new one starts with the front at its end
  uint64_t volume_key = 0;         // the result whose colours the 3D view's volume holds (0: none)
  std::vector<double> volume_sig;  // and for which field and front
  std::string volume_problem;      // why the 3D view cannot colour the part (empty: it can)
  std::vector<double> image_sig;   // what the section image's texture shows: result, field, front, section
  Texture image_texture;
};

}  // namespace vox::app
