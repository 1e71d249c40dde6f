#pragma once
// The 3D view while the Casting panel is open: the part coloured by the field chosen (solidification time with the
// freezing front, the still-liquid metal red; Niyama; the modulus) through the renderer's scalar volume, the hot
// spots as rings (isolated red, fed white, in a feeder blue) with the feeding paths of the fed ones (through the
// saddle to the spot they feed from), and a legend. The feeders are parts of the scene: their metal is coloured
// with the part's.
#include <imgui.h>

#include "app/app_state.h"
#include "vox/render/point_renderer.h"

namespace vox::app {

// The run the 3D view shows: the model's, while the Casting panel is open (null otherwise or before one).
const CastingOutcome* shownCasting(const AppState& state);
// Uploads the colours of the run, field and front shown when they change, and drops them when none is shown.
void syncCastingView(AppState& state);
// Turns the colours on while the panel shows a run.
void castingDrawParams(const AppState& state, render::DrawParams& p);
// The legend and the hot spots' rings over the view at `pos`; returns the y below the legend.
float drawCastingOverlay(AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect);

}  // namespace vox::app
