#pragma once
// The view cube in the 3D view's corner: the cube turned as the camera sees the model, its faces named by the axis
// they face (+X ... -Z); clicking a face looks at the model from that side (the From +X ... actions).
#include <imgui.h>

#include "app/app_state.h"

namespace vox::app {

// Draws the cube about `centre` (half its side `half` pixels) and takes a click on a face. Each face seen is recorded
// as a button "view cube +X" ... (ui.h, recordAt), so a test presses it where it is drawn.
void drawViewCube(AppState& state, ImVec2 centre, float half);

}  // namespace vox::app
