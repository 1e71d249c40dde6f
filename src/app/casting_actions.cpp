// The Casting entries of the action table (actions.cpp): the panel, the alloy, mould and temperatures, the feeders
// (parts of the scene: typed, clicked on the part, deleted), the run and its cancel, the field the views colour by, the
// freezing front's time and its play, the hot spots' list. Row numbers in scripts count from 1, as the panel shows
// them.
#include <algorithm>
#include <cmath>
#include <string>

#include "app/action_functions.h"
#include "app/casting.h"
#include "app/parts.h"
#include "app/update.h"  // centreView, axisLength
#include "vox/core/text.h"

namespace vox::app::actions {
void panelCasting(AppState& s) { showPanel(s, Panel::kCasting); }
bool onCasting(const AppState& s) { return s.panel == Panel::kCasting; }
bool hasCasting(const AppState& s) { return currentCasting(s) != nullptr; }
bool canSimulateCasting(const AppState& s) { return !s.model.empty() && !castingComputing(s); }
bool castingComputingNow(const AppState& s) { return castingComputing(s); }
bool isCastingPlaying(const AppState& s) { return s.casting_ui.playing; }

Status castingAlloyAt(AppState& s, const ActionArgs& a) {
  if (Status st = setCastingAlloy(s, a.words[0]); !st) return badValues(st.error().message);
  showPanel(s, Panel::kCasting);
  return Ok{};
}

Status castingMouldAt(AppState& s, const ActionArgs& a) {
  if (Status st = setCastingMould(s, a.words[0]); !st) return badValues(st.error().message);
  showPanel(s, Panel::kCasting);
  return Ok{};
}

Status castingSuperheatAt(AppState& s, const ActionArgs& a) {
  double v = 0.0;
  if (!parseNumber(a.words[0], v) || !(v >= 0.0 && v <= 1000.0)) {
    return badValues("casting-superheat takes kelvin above the liquidus, 0 to 1000");
  }
  s.casting_ui.chosen.superheat_k = v;
  showPanel(s, Panel::kCasting);
  return Ok{};
}

Status castingMouldTemperatureAt(AppState& s, const ActionArgs& a) {
  double v = 0.0;
  if (a.words[0] == "default") {
    v = -1000.0;
  } else if (!parseNumber(a.words[0], v) || !(v > -273.0 && v < 3000.0)) {
    return badValues("casting-mould-temperature takes degrees C (above -273), or 'default'");
  }
  s.casting_ui.chosen.mould_temperature_c = v;
  showPanel(s, Panel::kCasting);
  return Ok{};
}

Status castingFeederAt(AppState& s, const ActionArgs& a) {
  std::string text = "cylinder:";
  for (size_t k = 0; k < 5; ++k) text += (k ? "," : "") + a.words[k];
  auto f = parseFeeder(text);
  if (!f) return badValues(f.error().message);
  if (Status st = addFeederPart(s, *f); !st) return st;
  showPanel(s, Panel::kCasting);
  return Ok{};
}

void castingPlaceFeederMode(AppState& s) {
  s.casting_ui.placing_feeder = !s.casting_ui.placing_feeder;
  showPanel(s, Panel::kCasting);
}

Status castingPlaceFeederAt(AppState& s, const ActionArgs& a) {
  glm::ivec3 v(0);
  for (int k = 0; k < 3; ++k) {
    if (!parseNumber(a.words[size_t(k)], v[k])) return badValues("casting-place-feeder takes I J K, a voxel index");
  }
  if (Status st = placeFeederAt(s, v); !st) return st;
  showPanel(s, Panel::kCasting);
  return Ok{};
}

Status castingDeleteFeederAt(AppState& s, const ActionArgs& a) {
  const std::vector<size_t> feeders = feederParts(s);
  const auto i = listRow(a, feeders.size(), "casting-delete-feeder", "Casting", "there is no feeder");
  if (!i) return i.error();
  if (Status st = removePart(s, feeders[*i]); !st) return st;
  showPanel(s, Panel::kCasting);
  return Ok{};
}

void simulateCastingNow(AppState& s) {
  simulateCasting(s);
  showPanel(s, Panel::kCasting);
}

void cancelCastingNow(AppState& s) { cancelCasting(s); }

Status castingFieldChoice(AppState& s, const ActionArgs& a) {
  const std::string& w = a.words[0];
  if (w == "time") {
    s.casting_ui.field = CastingField::kTime;
  } else if (w == "niyama") {
    s.casting_ui.field = CastingField::kNiyama;
  } else if (w == "modulus") {
    s.casting_ui.field = CastingField::kModulus;
  } else {
    return badValues("casting-field takes time, niyama or modulus");
  }
  showPanel(s, Panel::kCasting);
  return Ok{};
}

Status castingTimeAt(AppState& s, const ActionArgs& a) {
  double v = 0.0;
  if (a.words[0] == "end") {
    v = -1.0;
  } else if (!parseNumber(a.words[0], v) || !(v >= 0.0)) {
    return badValues("casting-time takes seconds from pouring, or 'end'");
  }
  s.casting_ui.time_shown = v;
  s.casting_ui.playing = false;
  s.casting_ui.field = CastingField::kTime;
  showPanel(s, Panel::kCasting);
  return Ok{};
}

void castingPlay(AppState& s) {
  s.casting_ui.playing = !s.casting_ui.playing;
  if (s.casting_ui.playing) s.casting_ui.field = CastingField::kTime;
  showPanel(s, Panel::kCasting);
}

Status castingHotSpotAt(AppState& s, const ActionArgs& a) {
  const CastingOutcome* r = currentCasting(s);
  const auto i =
      listRow(a, r ? r->run.result.hot_spots.size() : 0, "casting-hot-spot", "Casting", "there is no hot spot");
  if (!i) return i.error();
  const CastingHotSpot& spot = r->run.result.hot_spots[*i];
  // the section through it along the section's axis, the 3D view about it
  const GridFrame& frame = s.model.frame();
  const glm::dvec3 v = (spot.centre - frame.origin) / frame.voxel_size - 0.5;
  const int axis = int(s.section.axis);
  s.section.index = std::clamp(int32_t(std::lround(v[axis])), 0, std::max(axisLength(s, s.section.axis) - 1, 0));
  s.section.oblique = false;
  s.section.playing = false;
  const double size = std::cbrt(double(std::max<int64_t>(spot.voxels, 1)));
  centreView(s, v + 0.5, 3.0 * std::max(size, 8.0));
  s.casting_ui.selected_spot = int32_t(*i);
  s.casting_ui.selected_result = r->id;
  showPanel(s, Panel::kCasting);
  return Ok{};
}

}  // namespace vox::app::actions
