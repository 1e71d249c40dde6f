#pragma once
// The Print panel's state (print.h): the build direction and overhang angle the user chose, the background result
// they key, and what the 3D view holds of it.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/voxel_grid.h"
#include "vox/workflow/print_check.h"

namespace vox::app {

// What one printability result was computed for.
struct PrintKey {
  uint64_t model_version = 0;
  glm::dvec3 up{0.0, 0.0, 1.0};
  double overhang_angle = 45.0;
  bool orient = false;  // the build directions searched too
  bool operator==(const PrintKey&) const = default;
};

struct PrintResult {
  uint64_t id = 0;  // this computation's (takeId): what the 3D view's fields are keyed by
  PrintKey key;
  workflow::PrintCheck check;
  double seconds = 0.0;
  // The overhangs as the renderer's scalar volume over their box (1 where a voxel hangs, else 0), made on the worker;
  // empty, with `overhang_problem` saying why, when the box is too large to show.
  glm::ivec3 overhang_min{0};
  Dims overhang_dims{};
  std::vector<uint8_t> overhang_values;
  std::string overhang_problem;
};

struct PrintUi {
  glm::dvec3 up{0.0, 0.0, 1.0};  // the build direction: away from the plate
  double overhang_angle = 45.0;  // degrees from the vertical
  bool orient = false;           // search the build directions (asked for with "Find the best way up")
  bool lay_face = false;         // the next click on the 3D view lays the face clicked on the plate
  float angle_drag = -1.0f;      // the angle slider's value while it is dragged (< 0: not); applied when let go
  PrintKey cancelled;            // the computation the user cancelled (not asked again until "Compute")
  bool was_cancelled = false;
  int32_t selected_cavity = -1;  // in the result selected_result (PrintResult::id)
  uint64_t selected_result = 0;
  uint64_t volume_key = 0;     // the result whose overhangs the 3D view's volume holds (0: none)
  uint64_t support_key = 0;    // the result whose support the support renderer holds (0: none)
  std::string volume_problem;  // why the 3D view cannot show the overhangs in red (empty: it can)
};

}  // namespace vox::app
