#pragma once
// The 3D view while the Thickness panel is open: the model coloured by local thickness (a scalar volume in the
// renderer), thin walls red, a colour bar, the thickness under the mouse and the hot spots as rings.
#include <string>

#include <imgui.h>

#include "app/app_state.h"
#include "vox/render/point_renderer.h"

namespace vox::app {

// The thickness the 3D view shows: the model's, while the Thickness panel is open (null otherwise, or before it is
// computed). The view then draws the model, coloured, even where it is a scene of parts.
const ThicknessResult* shownThickness(const AppState& state);
// The height the colour scale takes at the top of the 3D view while the Thickness panel is open (0 otherwise): a fit
// puts the model below it.
float thicknessLegendHeight(const AppState& state);
// Uploads the thickness of the model shown to the main renderer while the panel is open (once per model
// version), and clears it otherwise. A box too large for the GL's 3D textures is refused, with a note for the panel.
void syncThicknessVolume(AppState& state);
// Turns the colouring on (and the red below the minimum wall) while the panel shows a thickness.
void thicknessDrawParams(const AppState& state, render::DrawParams& p);
// The colour bar, the hot spots, the place clicked in the panel's lists and the read-out of the thickness under the
// mouse, over the view at `pos`. Returns the y below what it wrote at the view's top left (pos.y when nothing).
float drawThicknessOverlay(AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect);
// The same legend on an exported picture of the view (the Thickness panel open): the colour scale with the method's
// name and the minimum wall, and the hot spots' numbered rings.
void drawThicknessLegendOnImage(AppState& state, ImageRgba& image);
// A vertical colour bar of `height` pixels at `at`: 0 at the bottom, `max` at the top (model units), red under
// `min_wall`, labelled. Returns its width with the labels.
float drawThicknessBar(ImDrawList* dl, ImVec2 at, float height, double max, double min_wall, const std::string& units);
// The colour of a thickness in the views: red under the minimum wall, else the ramp over 0..max.
ImU32 thicknessColour(double thickness, double max, double min_wall);
// Under the minimum wall but in no wall (a convex edge or corner): grey in the section, the model's colour in 3D.
inline constexpr ImU32 kEdgeColour = IM_COL32(150, 150, 150, 255);

}  // namespace vox::app
