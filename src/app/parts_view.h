#pragma once
// The parts of a scene in the 3D view: one point renderer per part, each on the model's frame (the assembly's
// extent), drawn in the part's colour. Selected parts stand out (the others are dimmed); while an interference pair
// or the selected part alone is shown, the other parts are drawn faint around it. GL, no ImGui.
#include <vector>

#include "app/app_state.h"
#include "vox/render/point_renderer.h"

namespace vox::app {

// Brings the part renderers up to date with the current parts (none when the document is one model).
void syncPartRenderers(AppState& state);
// True when the 3D view draws the parts (instead of the model as one grid).
bool drawsParts(const AppState& state);
// Draws the visible parts with `params` (their colour and opacity set per part); returns the summed statistics.
render::DrawStats drawParts(AppState& state, int w, int h, const render::DrawParams& params);
// What the parts' image depends on besides the model (visibility, selection, the pair shown), for the view's
// redraw signature.
void appendPartsSignature(const AppState& state, std::vector<double>& signature);

}  // namespace vox::app
