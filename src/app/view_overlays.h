#pragma once
// What the 3D view draws over its image with ImGui (viewport.cpp): the measured voxels, the clearance of two parts,
// the axis triad.
#include <glm/mat4x4.hpp>
#include <imgui.h>

#include "app/app_state.h"

namespace vox::app {

// The picked voxels as rings at their centres, lettered, and what they measure, at the view's left from `top` down
// (below what other read-outs wrote there), each line wrapped to the view's width.
void drawMeasureOverlay(const AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect, float top);
// The two voxels realising the clearance of two parts (parts.h, clearanceVoxels) as cyan rings joined by a line,
// with the gap written beside the line.
void drawClearanceOverlay(const AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect);
// Text with a dark shadow, readable over any colour of the model.
void shadowText(ImDrawList* dl, ImVec2 p, ImU32 colour, const char* text);
// Screen position of a point in voxel-index space (vp: the camera's view-projection); false behind the camera.
bool projectToView(const glm::dmat4& vp, glm::dvec3 p, ImVec2 pos, int w, int h, ImVec2& out);
// X, Y and Z as the camera sees them, from `origin`.
void drawAxisTriad(const render::Camera& camera, ImVec2 origin, float length);

}  // namespace vox::app
