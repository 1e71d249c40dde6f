// Section image (thesis 5.2.1 and 6.3): the 2D section beside the 3D cut-away, with its axes, scale bar, the picked
// voxels of this section and a read-out of the voxel under the mouse (a click picks it to measure); the wheel zooms
// it and a right-drag pans it (section-zoom).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <imgui.h>
#include <imgui_internal.h>  // SetItemUsingMouseWheel

#include "app/actions.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/parts.h"
#include "app/ui.h"
#include "vox/io/figure.h"

namespace vox::app {

ImageAxes imageAxes(Axis a) {
  switch (a) {
    case Axis::kX:
      return {1, 2};
    case Axis::kY:
      return {0, 2};
    case Axis::kZ:
      return {0, 1};
  }
  return {0, 1};
}

// The section at an angle: its picture, right and up as the plane's axes say, a scale bar in model units.
static void drawObliqueImage(AppState& state) {
  const ObliqueSection* o = currentObliqueSection(state);
  if (!o) {
    ImGui::TextWrapped("%s", state.oblique_error.empty() ? "No section." : state.oblique_error.c_str());
    return;
  }
  if (state.oblique_texture.empty()) state.oblique_texture.upload(io::sectionPicture(o->mask, 1));
  const std::string units = state.model.frame().units;
  ImGui::TextWrapped("Section normal to (%.3g, %.3g, %.3g), %s from the centre: %s samples", o->normal.x, o->normal.y,
                     o->normal.z, formatLength(state.section.offset, units).c_str(), groupDigits(o->filled).c_str());
  const int32_t iw = o->mask.width, ih = o->mask.height;
  const float label_h = ImGui::GetTextLineHeightWithSpacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float room_w = std::max(1.0f, avail.x - 24.0f), room_h = std::max(1.0f, avail.y - 3.0f * label_h);
  float scale = std::min(room_w / float(iw), room_h / float(ih));
  if (scale >= 1.0f) scale = std::floor(scale);
  const ImVec2 size(float(iw) * scale, float(ih) * scale);
  const ImVec2 origin(ImGui::GetCursorScreenPos().x + 20.0f, ImGui::GetCursorScreenPos().y);
  ImGui::SetCursorScreenPos(origin);
  ImGui::Image(textureId(state.oblique_texture.id()), size);
  markWidget("section_image");
  ImGui::SetCursorScreenPos(ImVec2(origin.x, origin.y + size.y + 2.0f));
  ImGui::TextDisabled("right (%.2f, %.2f, %.2f), up (%.2f, %.2f, %.2f)", o->u.x, o->u.y, o->u.z, o->v.x, o->v.y,
                      o->v.z);
  drawScaleBar(ImVec2(origin.x, origin.y + size.y + 2.0f + label_h), scale / float(o->pixel), units,
               std::max(size.x * 0.5f, 60.0f));
  ImGui::Dummy(ImVec2(0.0f, label_h));
}

namespace {

// What of the axis section's picture (iw x ih voxels) is shown, zoomed, in `size` pixels from `origin`: the picture's
// voxels from (u0, r0) (column, row from the top), `px` pixels each.
struct SectionWindow {
  ImVec2 origin, size;
  int32_t iw = 1, ih = 1;
  double zoom = 1.0, u0 = 0.0, r0 = 0.0;
  float px = 1.0f;
  SectionWindow(const SectionUi& ui, ImVec2 at, ImVec2 whole, int32_t w, int32_t h)
      : origin(at), size(whole), iw(w), ih(h), zoom(ui.zoom) {
    const double half = 0.5 / zoom;
    u0 = (ui.centre.x - half) * iw;
    r0 = (1.0 - ui.centre.y - half) * ih;
    px = float(double(size.x) / double(iw) * zoom);
  }
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

// The wheel zooms about the point under the mouse; the right or middle button (or Shift and the left) drags the
// picture. Both go through section-zoom, as a script would give them.
void zoomAndPan(AppState& state, const SectionWindow& win) {
  const ImGuiIO& io = ImGui::GetIO();
  const SectionUi& ui = state.section;
  double zoom = ui.zoom;
  glm::dvec2 centre = ui.centre;
  if (io.MouseWheel != 0.0f) {
    const glm::dvec2 at = win.cellAt(io.MousePos);  // stays under the mouse
    zoom = std::clamp(zoom * std::pow(1.25, double(io.MouseWheel)), 1.0, kMaxSectionZoom);
    const glm::dvec2 off((io.MousePos.x - win.origin.x) / win.size.x, (io.MousePos.y - win.origin.y) / win.size.y);
    centre = glm::dvec2(at.x / win.iw - (off.x - 0.5) / zoom, 1.0 - (at.y / win.ih - (off.y - 0.5) / zoom));
  }
  const bool pan = ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle) ||
                   (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift);
  if (pan && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) && zoom > 1.0) {
    centre -= glm::dvec2(io.MouseDelta.x / win.size.x, -io.MouseDelta.y / win.size.y) / zoom;
  }
  if (zoom == ui.zoom && centre == ui.centre) return;
  dispatchValues(
      state, ActionId::kSectionZoom,
      {std::to_string(zoom), std::to_string(centre.x * win.iw - 0.5), std::to_string(centre.y * win.ih - 0.5)});
}

// The line over the picture: its buttons to zoom (the wheel does too) and to show it whole.
void zoomButtons(AppState& state) {
  const double zoom = state.section.zoom;
  if (widget::SmallButton("Zoom in##section")) {
    dispatchValues(state, ActionId::kSectionZoom, {std::to_string(std::min(zoom * 2.0, kMaxSectionZoom))});
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(zoom <= 1.0);
  if (widget::SmallButton("Zoom out##section")) {
    dispatchValues(state, ActionId::kSectionZoom, {std::to_string(std::max(zoom / 2.0, 1.0))});
  }
  ImGui::SameLine();
  if (widget::SmallButton("Whole section")) dispatch(state, ActionId::kSectionZoom);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled("%.3gx", zoom);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The wheel zooms about the mouse; a right-drag pans.");
}

// The voxel under the mouse: outlined, read out, and picked to measure on a click.
void hoverReadout(AppState& state, const Section& section, const SectionWindow& win, bool clicked) {
  const ImageAxes ax = imageAxes(section.axis);
  const glm::dvec2 at = win.cellAt(ImGui::GetIO().MousePos);
  const int32_t u = std::clamp(int32_t(std::floor(at.x)), 0, win.iw - 1);
  const int32_t row = std::clamp(int32_t(std::floor(at.y)), 0, win.ih - 1);
  int32_t voxel[3];
  voxel[int(section.axis)] = section.index;
  voxel[ax.right] = u;
  voxel[ax.up] = win.ih - 1 - row;  // row 0 holds the largest "up" index
  const std::string units = state.model.frame().units;
  const glm::dvec3 c = state.model.frame().voxelCentre(voxel[0], voxel[1], voxel[2]);
  const ImVec2 cell = win.screenOf(u, row);
  markCell(win.origin, ImVec2(win.origin.x + win.size.x, win.origin.y + win.size.y), cell,
           ImVec2(cell.x + win.px, cell.y + win.px));
  ImGui::SetTooltip("voxel (%d, %d, %d): %s\ncentre (%.4g, %.4g, %.4g) %s\nclick to measure", voxel[0], voxel[1],
                    voxel[2], section.mask.at(u, row) ? "material" : "empty", c.x, c.y, c.z,
                    units == "model" ? "model units" : units.c_str());
  if (clicked && !ImGui::GetIO().KeyShift) addMeasurePick(state, glm::ivec3(voxel[0], voxel[1], voxel[2]));
}

}  // namespace

void drawSectionImage(AppState& state) {
  if (state.section.oblique) {
    drawObliqueImage(state);
    return;
  }
  const Section* section = currentSection(state);
  if (!section) {
    ImGui::TextWrapped("%s", state.section_error.empty() ? "No section." : state.section_error.c_str());
    return;
  }
  if (state.section_texture.empty()) state.section_texture.upload(partsSectionPicture(state, *section));
  const std::string units = state.model.frame().units;
  ImGui::TextWrapped("Section %s = %s, index %d: %s voxels", axisName(section->axis),
                     formatCoordinate(section->position, units, state.model.voxelSize()).c_str(), section->index,
                     groupDigits(section->filled).c_str());
  zoomButtons(state);

  const ImageAxes ax = imageAxes(section->axis);
  const int32_t iw = section->mask.width, ih = section->mask.height;
  const float label_h = ImGui::GetTextLineHeightWithSpacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float room_w = std::max(1.0f, avail.x - 24.0f), room_h = std::max(1.0f, avail.y - 3.0f * label_h);
  float scale = std::min(room_w / float(iw), room_h / float(ih));
  if (scale >= 1.0f) scale = std::floor(scale);  // whole pixels per voxel keep the voxel grid regular
  const ImVec2 size(float(iw) * scale, float(ih) * scale);

  ImGui::TextUnformatted(axisName(Axis(ax.up)));
  ImGui::SameLine();
  ImGui::TextDisabled("^");
  const ImVec2 origin(ImGui::GetCursorScreenPos().x + 20.0f, ImGui::GetCursorScreenPos().y);
  ImGui::SetCursorScreenPos(origin);
  const SectionWindow win(state.section, origin, size, iw, ih);
  ImGui::Image(textureId(state.section_texture.id()), size, win.uvMin(), win.uvMax());
  ImGui::SetItemUsingMouseWheel();  // (the picture's window scrolls with no wheel anyway: NoScrollWithMouse)
  markWidget("section_image");
  const bool hovered = ImGui::IsItemHovered();
  const bool clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
  ImGui::SetCursorScreenPos(ImVec2(origin.x + size.x - 40.0f, origin.y + size.y + 2.0f));
  ImGui::Text("%s >", axisName(Axis(ax.right)));
  // The scale bar on its own line, under the axis label, so the two never run into each other.
  drawScaleBar(ImVec2(origin.x, origin.y + size.y + 2.0f + label_h), win.px / float(state.model.voxelSize()), units,
               std::max(size.x * 0.5f, 60.0f));
  ImGui::Dummy(ImVec2(0.0f, label_h));
  // Picked voxels in this section: rings at their cells (the 3D view says what they measure).
  const std::vector<glm::ivec3>& picks = measurePicks(state);
  for (size_t i = 0; i < picks.size(); ++i) {
    if (picks[i][int(section->axis)] != section->index) continue;
    const ImVec2 c = win.screenOf(picks[i][ax.right] + 0.5, double(ih - 1 - picks[i][ax.up]) + 0.5);
    if (!win.shows(c)) continue;
    ImGui::GetWindowDrawList()->AddCircle(c, std::max(5.0f, win.px), IM_COL32(255, 220, 60, 255), 0, 2.0f);
    const char label[2] = {char('A' + i), 0};
    ImGui::GetWindowDrawList()->AddText(ImVec2(c.x + 7.0f, c.y - 16.0f), IM_COL32(255, 220, 60, 255), label);
  }
  if (hovered) {
    hoverReadout(state, *section, win, clicked);
    zoomAndPan(state, win);
  }
}

}  // namespace vox::app
