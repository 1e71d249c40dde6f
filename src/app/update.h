#pragma once
// What the document does each frame, and the derived results the panels show: the section and the X-ray. No ImGui
// and no GL here.
#include <cstdint>

#include "app/app_state.h"

namespace vox::app {

// Moves finished background results in, applies queued peels, asks for the derived results the open panel needs,
// and recomputes the section when its key changed.
void updateDocument(AppState& state);
// The section for the current params (null when there is no model).
const Section* currentSection(AppState& state);
// The section at an angle the Section panel shows (SectionUi::oblique), computed when its plane or the model
// changes; null when it is not shown or could not be made (oblique_error says why).
const ObliqueSection* currentObliqueSection(AppState& state);
// The X-ray for the current params, once computed (null before, and without a model).
const XrayResult* currentXray(const AppState& state);
// Number of voxels along an axis of the model (0 without one).
int32_t axisLength(const AppState& state, Axis axis);
// Zooms the axis section's picture `zoom` times (1 to kMaxSectionZoom) about the voxel `uv` of the picture (along its
// right and up axes, fractions allowed), kept within the picture.
void zoomSection(AppState& state, double zoom, glm::dvec2 uv);
// Turns the 3D view about `centre` (voxel coordinates of the model) from where it looks, and comes near enough to see
// a place `extent` voxels wide well (never farther than it was).
void centreView(AppState& state, glm::dvec3 centre, double extent);

}  // namespace vox::app
