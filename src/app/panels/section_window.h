#pragma once
// The axis section's picture zoomed and panned (section-zoom): which of its voxels a panel shows, and the mouse and
// buttons that zoom and pan it. The Section panel's picture and the Thickness panel's (the same section, coloured by
// thickness) share the zoom, as they share the slider.
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/ext/vector_int2.hpp>
#include <imgui.h>

#include "app/app_state.h"

namespace vox::app {

// What of an axis section's picture (iw x ih voxels) is shown, zoomed as `ui` says, in `whole` pixels from `at`: the
// picture's voxels from (u0, r0) (column, row from the top), `px` pixels each.
struct SectionWindow {
  ImVec2 origin, size;
  int32_t iw = 1, ih = 1;
  double zoom = 1.0, u0 = 0.0, r0 = 0.0;
  float px = 1.0f;
  SectionWindow(const SectionUi& ui, ImVec2 at, ImVec2 whole, int32_t w, int32_t h);
  // The texture's corners shown (row 0 of the texture is the top row).
  ImVec2 uvMin() const { return ImVec2(float(u0 / iw), float(r0 / ih)); }
  ImVec2 uvMax() const { return ImVec2(float((u0 + iw / zoom) / iw), float((r0 + ih / zoom) / ih)); }
  // The picture's column and row (from the top) under a screen point, and the screen point of a column and row.
  glm::dvec2 cellAt(ImVec2 p) const { return {u0 + (p.x - origin.x) / px, r0 + (p.y - origin.y) / px}; }
  ImVec2 screenOf(double u, double row) const {
    return ImVec2(origin.x + float((u - u0) * px), origin.y + float((row - r0) * px));
  }
  bool shows(ImVec2 p) const {
    return p.x >= origin.x && p.y >= origin.y && p.x <= origin.x + size.x && p.y <= origin.y + size.y;
  }
};

// While the mouse is over the picture `win`: the wheel zooms about the point under the mouse; the right or middle
// button (or Shift and the left) drags the picture. Both dispatch section-zoom, as a script would.
void zoomAndPan(AppState& state, const SectionWindow& win);
// The cell (column, row from the top) of the picture under the mouse, kept within the picture.
glm::ivec2 cellUnderMouse(const SectionWindow& win);
// The voxel of the section (axis, index) at a cell of its picture (row 0 holds the largest "up" index).
glm::ivec3 sectionVoxel(Axis axis, int32_t index, const SectionWindow& win, glm::ivec2 cell);
// Measuring by clicking the picture of `section`: the cell under the mouse snapped to the material's edge (snapToEdge,
// within kSnapPixels of the mouse), or as it is while Alt is held. The cell it snaps to is marked while it is another
// than the one under the mouse; a click (without Shift, which pans) picks it.
inline constexpr double kSnapPixels = 10.0;
inline constexpr const char* kClickToMeasure = "click to measure (at the edge, marked; Alt: this voxel)";
void pickOnClick(AppState& state, const Section& section, const SectionWindow& win, bool clicked);
// The voxels picked to measure that lie in the section (axis, index) shown by `win`: a ring and its letter each (the
// 3D view says what they measure).
void drawMeasurePicks(const AppState& state, Axis axis, int32_t index, const SectionWindow& win);
// The line over a picture: Zoom in, Zoom out, Whole section and the zoom. `id` tells one panel's buttons from
// another's ("section", "thickness").
void zoomButtons(AppState& state, const char* id);

}  // namespace vox::app
