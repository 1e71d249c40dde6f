// The axis section's picture zoomed and panned, see app/panels/section_window.h.
#include "app/panels/section_window.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/actions.h"
#include "app/measure.h"
#include "app/panels/panels.h"  // imageAxes
#include "app/ui.h"

namespace vox::app {

SectionWindow::SectionWindow(const SectionUi& ui, ImVec2 at, ImVec2 whole, int32_t w, int32_t h)
    : origin(at), size(whole), iw(w), ih(h), zoom(ui.zoom) {
  const double half = 0.5 / zoom;
  u0 = (ui.centre.x - half) * iw;
  r0 = (1.0 - ui.centre.y - half) * ih;
  px = float(double(size.x) / double(iw) * zoom);
}

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

glm::ivec2 cellUnderMouse(const SectionWindow& win) {
  const glm::dvec2 at = win.cellAt(ImGui::GetIO().MousePos);
  return {std::clamp(int32_t(std::floor(at.x)), 0, win.iw - 1), std::clamp(int32_t(std::floor(at.y)), 0, win.ih - 1)};
}

glm::ivec3 sectionVoxel(Axis axis, int32_t index, const SectionWindow& win, glm::ivec2 cell) {
  const ImageAxes ax = imageAxes(axis);
  glm::ivec3 v(0);
  v[int(axis)] = index;
  v[ax.right] = cell.x;
  v[ax.up] = win.ih - 1 - cell.y;
  return v;
}

void pickOnClick(AppState& state, const Section& section, const SectionWindow& win, bool clicked) {
  const glm::ivec2 under = cellUnderMouse(win);
  const glm::ivec2 snapped =
      ImGui::GetIO().KeyAlt ? under : snapToEdge(section.mask, under.x, under.y, kSnapPixels / double(win.px));
  if (snapped != under) {  // where a click would pick: a yellow square on the edge voxel
    const ImVec2 p = win.screenOf(snapped.x, snapped.y);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRect(p, ImVec2(p.x + win.px, p.y + win.px), IM_COL32(0, 0, 0, 255), 0.0f, 0, 3.0f);
    dl->AddRect(p, ImVec2(p.x + win.px, p.y + win.px), IM_COL32(255, 220, 60, 255), 0.0f, 0, 1.5f);
  }
  if (clicked && !ImGui::GetIO().KeyShift)
    addMeasurePick(state, sectionVoxel(section.axis, section.index, win, snapped));
}

void drawMeasurePicks(const AppState& state, Axis axis, int32_t index, const SectionWindow& win) {
  const ImageAxes ax = imageAxes(axis);
  const std::vector<glm::ivec3>& picks = measurePicks(state);
  for (size_t i = 0; i < picks.size(); ++i) {
    if (picks[i][int(axis)] != index) continue;
    const ImVec2 c = win.screenOf(picks[i][ax.right] + 0.5, double(win.ih - 1 - picks[i][ax.up]) + 0.5);
    if (!win.shows(c)) continue;
    ImDrawList* dl = ImGui::GetWindowDrawList();  // outlined in black: seen on the thickness colours' yellow too
    dl->AddCircle(c, std::max(5.0f, win.px), IM_COL32(0, 0, 0, 255), 0, 4.0f);
    dl->AddCircle(c, std::max(5.0f, win.px), IM_COL32(255, 220, 60, 255), 0, 2.0f);
    const char label[2] = {char('A' + i), 0};
    dl->AddText(ImVec2(c.x + 8.0f, c.y - 15.0f), IM_COL32(0, 0, 0, 255), label);
    dl->AddText(ImVec2(c.x + 7.0f, c.y - 16.0f), IM_COL32(255, 220, 60, 255), label);
  }
}

void zoomButtons(AppState& state, const char* id) {
  const double zoom = state.section.zoom;
  const std::string in = std::string("Zoom in##") + id, out = std::string("Zoom out##") + id;
  const std::string whole = std::string("Whole section##") + id;
  if (widget::SmallButton(in.c_str())) {
    dispatchValues(state, ActionId::kSectionZoom, {std::to_string(std::min(zoom * 2.0, kMaxSectionZoom))});
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(zoom <= 1.0);
  if (widget::SmallButton(out.c_str())) {
    dispatchValues(state, ActionId::kSectionZoom, {std::to_string(std::max(zoom / 2.0, 1.0))});
  }
  ImGui::SameLine();
  if (widget::SmallButton(whole.c_str())) dispatch(state, ActionId::kSectionZoom);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled("%.3gx", zoom);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The wheel zooms about the mouse; a right-drag pans.");
}

}  // namespace vox::app
