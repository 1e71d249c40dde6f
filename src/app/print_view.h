#pragma once
// The 3D view while the Print panel is open: the overhangs in red (the renderer's scalar volume), the support as
// translucent columns (a renderer of its own), the build direction as an arrow, the trapped cavities as rings, and a
// legend.
#include <imgui.h>

#include "app/app_state.h"
#include "vox/render/point_renderer.h"

namespace vox::app {

// The printability the 3D view shows: the model's, while the Print panel is open (null otherwise or before it is
// computed).
const PrintResult* shownPrint(const AppState& state);
// Uploads the overhangs and the support of the result shown (once per result) and drops them when none is shown.
void syncPrintView(AppState& state);
// Turns the red of the overhangs on while the panel shows a result.
void printDrawParams(const AppState& state, render::DrawParams& p);
// Draws the support over the model (translucent, depth-tested) when the panel shows it.
void drawPrintSupport(AppState& state, int w, int h, const render::DrawParams& params);
// The legend, the build direction's arrow and the cavities' rings over the view at `pos`; returns the y below the
// legend.
float drawPrintOverlay(AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect);

}  // namespace vox::app
