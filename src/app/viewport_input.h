#pragma once
// The 3D view's input (viewport.cpp draws the view): the mouse over the view and the view buttons over it.
#include <imgui.h>

#include "app/app_state.h"

namespace vox::app {

// Mouse: an invisible button over the view at `pos` (w x h pixels) takes the drags, so they never reach the panels
// below it. Drags orbit or pan, the wheel zooms, a double-click fits and Ctrl+click picks a voxel (a click places a
// feeder or lays a face on the plate while the Casting or Print panel waits for one). Returns whether a drag is on.
bool handleViewMouse(AppState& state, ImVec2 pos, int w, int h, double aspect);
// The view buttons (Fit, Iso, +X ... -Z, Ortho) at `pos`, with their shortcuts as tooltips.
void drawViewToolbar(AppState& state, ImVec2 pos);

}  // namespace vox::app
