#pragma once
// Measuring in the window: Ctrl+click a voxel in the 3D view, or click one in the section or thickness picture, to
// pick it; a second pick gives the distance between the two voxel centres; a third starts again. Each pick also reads
// the wall thickness there when the Thickness panel has it (a probe). No GL or ImGui here.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/app_state.h"
#include "vox/core/image.h"

namespace vox::app {

void addMeasurePick(AppState& state, const glm::ivec3& voxel);
void clearMeasure(MeasureUi& measure);  // the pair and the recent picks
// The picks that belong to the current model's lattice (none after it changed dims).
const std::vector<glm::ivec3>& measurePicks(const AppState& state);
// The last three picks (fewer when fewer were made) on the current model's lattice, oldest first.
const std::vector<glm::ivec3>& recentPicks(const AppState& state);
// What the picks say, a line each: "A  voxel (12, 40, 7)  at (1.25, 4.05, 0.75) mm", then B, then
// "distance 3.1 mm  (dx 1.2, dy -2.8, dz 0)". With the Thickness panel's result for the model, a filled voxel's line
// ends with the wall thickness the panel shows there: "  wall 2 mm (spheres)" or "(rays)".
std::vector<std::string> measureLines(const AppState& state);
// Where a click at the cell (u, row) of a section's mask picks, snapped to the material's edge: the nearest filled
// cell (centre to centre) that has an empty or outside 4-neighbour, within `reach` cells of the click; the cell
// clicked when none is that near. So a pick on either face of a wall lands on the wall's surface voxel.
glm::ivec2 snapToEdge(const Image2D<uint8_t>& mask, int32_t u, int32_t row, double reach);

}  // namespace vox::app
