#pragma once
// The parts of a scene in the 3D view: one point renderer per part, each holding the placed part on its own box and
// drawn moved to where that box lies in the model's frame (the assembly's extent), in the part's colour. A move or
// turn of one part refills that part's renderer alone: the others' points do not change when the extent does.
// Selected parts stand out (the others are dimmed); while an interference pair or the selected part alone is shown,
// the other parts are drawn faint around it. GL, no ImGui.
#include <optional>
#include <vector>

#include "app/app_state.h"
#include "vox/render/point_renderer.h"

namespace vox::app {

// Brings the part renderers up to date with the current parts (none when the document is one model): a renderer that
// holds a part's voxels and placement as they are stays as it is; the others are filled again (Viewport::part_fills
// counts them). Cost O(points of the parts that changed) plus O(layers) per part to compare.
void syncPartRenderers(AppState& state);
// True when the 3D view draws the parts (instead of the model as one grid): a scene of parts, unless the Thickness
// panel colours the model by its thickness.
bool drawsParts(const AppState& state);
// The box of the parts' surface points (the selected part's alone when the scope is the selected part) in the
// model's voxel-index space, for the camera's fit and depth range; nullopt while the parts are not drawn.
std::optional<render::Box3> partsBounds(const AppState& state);
// Draws the visible parts with `params` (their colour and opacity set per part); returns the summed statistics.
render::DrawStats drawParts(AppState& state, int w, int h, const render::DrawParams& params);
// What the parts' image depends on besides the model (visibility, selection, the pair shown), for the view's
// redraw signature.
void appendPartsSignature(const AppState& state, std::vector<double>& signature);

}  // namespace vox::app
