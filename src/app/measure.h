#pragma once
// Measuring in the window: Ctrl+click a voxel in the 3D view, or click one in the section image, to pick it; a
// second pick gives the distance between the two voxel centres; a third starts again. No GL or ImGui here.
#include <string>
#include <vector>

#include "app/app_state.h"

namespace vox::app {

void addMeasurePick(AppState& state, const glm::ivec3& voxel);
void clearMeasure(AppState& state);
// The picks that belong to the current model's lattice (none after it changed dims).
const std::vector<glm::ivec3>& measurePicks(const AppState& state);
// What the picks say, a line each: "A  voxel (12, 40, 7)  at (1.25, 4.05, 0.75) mm", then B, then
// "distance 3.1 mm  (dx 1.2, dy -2.8, dz 0)".
std::vector<std::string> measureLines(const AppState& state);

}  // namespace vox::app
