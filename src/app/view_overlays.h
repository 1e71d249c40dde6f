#pragma once
// What the 3D view draws over its image with ImGui (viewport.cpp): the measured voxels, the clearance of two parts,
// the axis triad.
#include <imgui.h>

#include "app/app_state.h"

namespace vox::app {

// The picked voxels as rings at their centres, lettered, and what they measure, at the view's left from `top` down
// (below what other read-outs wrote there), each line wrapped to the view's width.
void drawMeasureOverlay(const AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect, float top);
// The two voxels realising the clearance of two parts (parts.h, clearanceVoxels) as cyan rings joined by a line,
// with the gap written beside the line.
void drawClearanceOverlay(const AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect);
// X, Y and Z as the camera sees them, from `origin`.
void drawAxisTriad(const render::Camera& camera, ImVec2 origin, float length);

}  // namespace vox::app
