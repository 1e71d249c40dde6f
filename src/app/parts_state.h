#pragma once
// The Parts panel's state (app/parts.h): the selection, what Section, X-ray and mass work on, the interference and
// clearance found for the current parts, and the fields being edited.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/analysis/assembly.h"
#include "vox/core/assembly.h"
#include "vox/core/voxel_grid.h"

namespace vox::app {

// The Parts panel (app/parts.h): which parts are selected, what Section, X-ray and mass work on, and the
// interference of the current parts.
struct PartsUi {
  std::vector<size_t> selected;  // part indices, in the order clicked (a Boolean takes the first two)
  bool scope_selected = false;   // Section, X-ray and mass on the selected part (else on the union of the parts)
  Connectivity connectivity = Connectivity::kFace;  // splitting a voxel model into components
  PartOp op = PartOp::kUnion;
  uint64_t interference_version = 0;  // the model version `interference` was found for (0: none)
  std::optional<Interference> interference;
  double interference_s = 0.0;
  int32_t pair = -1;       // the interference pair shown (index into interference->pairs); -1: none
  double contact = 0.0;    // overlaps at most this thick (model units) only touch: listed as contact, not interference
  VoxelGrid pair_overlap;  // its shared voxels on the model's frame
  uint64_t pair_key = 0;   // changes with the pair shown (the overlay renderer's key)
  std::vector<int64_t> voxel_counts;            // filled voxels of each part (partVoxelCounts)
  uint64_t counts_version = 0;                  // the model version they were counted for
  uint64_t interference_cancelled_version = 0;  // the model version whose interference search was cancelled
  // The clearance between two parts (parts_clearance.cpp): the parts and model version it was found for.
  std::optional<Clearance> clearance;
  size_t clearance_a = 0, clearance_b = 0;
  uint64_t clearance_version = 0;
  std::string clearance_error;  // why it could not be found (e.g. too large a box), for the same parts and version
  // The placement fields while they are edited (model units; committed when an edit ends).
  glm::dvec3 translation_edit{0.0};
  size_t translation_edit_part = SIZE_MAX;
  uint64_t translation_edit_version = 0;
  // The colour picker: the part whose swatch was active in the last frame (a drag goes on while it stays so), and the
  // undo step the last colour change made (setPartColour joins a drag's changes into it) with its part.
  size_t colour_drag_part = SIZE_MAX;
  std::shared_ptr<const Assembly> colour_step;
  size_t colour_step_part = SIZE_MAX;
};

}  // namespace vox::app
