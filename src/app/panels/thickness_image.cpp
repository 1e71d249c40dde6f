// The section image while the Thickness panel is open: the section (Section panel's axis and index) coloured by
// local thickness, red under the minimum wall, with a colour bar and the thickness under the mouse; zoomed and panned
// with the Section panel's picture (section-zoom).
#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>  // SetItemUsingMouseWheel

#include "app/measure.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/panels/section_window.h"
#include "app/thickness_view.h"
#include "app/ui.h"
#include "vox/analysis/thickness_map.h"
#include "vox/io/figure.h"

namespace vox::app {
namespace {

// Colours the section's thickness map (tenths of a voxel) into the texture when the section, the model or the
// minimum wall changed. Returns the map's size, or false when there is no section.
bool uploadThicknessSection(AppState& state, const ThicknessResult& r, int32_t& iw, int32_t& ih) {
  ThicknessUi& ui = state.thickness_ui;
  const SectionKey key{state.model_version, state.section.axis, state.section.index};
  const double wall = minWall(state), max = r.thickness.stats.max, h = state.model.voxelSize();
  const RayThicknessResult* ray = shownRay(state, r);
  const SectionParams sp{state.section.axis, state.section.index};
  auto map = ray ? fieldSection(ray->field, sp) : thicknessSection(r.thickness, sp);
  if (!map) return false;
  iw = map->width;
  ih = map->height;
  if (key == ui.image_key && wall == ui.image_min_wall && (ray != nullptr) == ui.image_ray && !ui.image_texture.empty())
    return true;
  const Walls* walls = currentThinWalls(state);
  const ImageAxes ax = imageAxes(state.section.axis);
  ImageRgb picture(iw, ih);
  for (int32_t v = 0; v < ih; ++v) {
    for (int32_t u = 0; u < iw; ++u) {
      const int32_t tenths = map->at(u, v);
      if (tenths <= 0) {
        picture.at(u, v) = io::kNoMaterialColour;
        continue;
      }
      const double t = double(tenths) / kThicknessTenths * h;
      glm::ivec3 voxel(0);
      voxel[int(state.section.axis)] = state.section.index;
      voxel[ax.right] = u;
      voxel[ax.up] = ih - 1 - v;
      // under the minimum wall but in no wall: an edge or corner, grey
      const bool edge = !ray && t < wall && walls && !walls->inWall(voxel.x, voxel.y, voxel.z);
      const ImU32 c = edge ? kEdgeColour : thicknessColour(t, max, wall);
      picture.at(u, v) = Rgb8{uint8_t(c & 0xff), uint8_t((c >> 8) & 0xff), uint8_t((c >> 16) & 0xff)};
    }
  }
  ui.image_texture.upload(picture);
  ui.image_key = key;
  ui.image_min_wall = wall;
  ui.image_ray = ray != nullptr;
  return true;
}

}  // namespace

void drawThicknessImage(AppState& state) {
  const ThicknessResult* r = currentThickness(state);
  if (!r) {
    ImGui::TextUnformatted("Computing thickness...");
    return;
  }
  const Section* section = currentSection(state);  // clamps the index to the model
  int32_t iw = 0, ih = 0;
  if (!uploadThicknessSection(state, *r, iw, ih) || iw <= 0 || ih <= 0) {
    ImGui::TextUnformatted("No section.");
    return;
  }
  const Axis axis = state.section.axis;
  const std::string units = state.model.frame().units;
  ImGui::Text("%s in the section %s = %d (Section panel's slider)",
              shownRay(state, *r) ? "Ray thickness" : "Local thickness (spheres)", axisName(axis), state.section.index);
  zoomButtons(state, "thickness");
  const ImageAxes ax = imageAxes(axis);
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float bar_room = 230.0f;  // the colour bar and its labels ("min wall 0.125 model units")
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  float scale = std::min(std::max(1.0f, avail.x - bar_room - 24.0f) / float(iw),
                         std::max(1.0f, avail.y - 3.0f * line) / float(ih));
  if (scale >= 1.0f) scale = std::floor(scale);
  scale = std::max(scale, 0.05f);
  const ImVec2 size(float(iw) * scale, float(ih) * scale);
  ImGui::Text("%s ^", axisName(Axis(ax.up)));
  const ImVec2 origin(ImGui::GetCursorScreenPos().x + 20.0f, ImGui::GetCursorScreenPos().y);
  ImGui::SetCursorScreenPos(origin);
  const SectionWindow win(state.section, origin, size, iw, ih);
  ImGui::Image(textureId(state.thickness_ui.image_texture.id()), size, win.uvMin(), win.uvMax());
  ImGui::SetItemUsingMouseWheel();  // (the picture's window scrolls with no wheel anyway: NoScrollWithMouse)
  markWidget("thickness_image");
  const bool hovered = ImGui::IsItemHovered();
  const bool clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float bar_h = std::max(size.y, 6.0f * line);
  drawThicknessBar(dl, ImVec2(origin.x + size.x + 16.0f, origin.y), bar_h, r->thickness.stats.max, minWall(state),
                   units);
  ImGui::SetCursorScreenPos(ImVec2(origin.x + size.x - 40.0f, origin.y + size.y + 2.0f));
  ImGui::Text("%s >", axisName(Axis(ax.right)));
  drawScaleBar(ImVec2(origin.x, origin.y + size.y + 2.0f + line), win.px / float(state.model.voxelSize()), units,
               std::max(size.x * 0.5f, 60.0f));
  ImGui::Dummy(ImVec2(0.0f, std::max(0.0f, bar_h - size.y) + line));
  // The place clicked in the panel's lists, where the section cuts it: the thin-wall region's box, the hot spot's
  // inscribed ball.
  auto screen = [&](double right, double up) {  // voxel coordinates in the image's plane (corners)
    return win.screenOf(right, double(ih) - up);
  };
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);  // the marks of a zoomed picture
  auto mark = [&](auto&& draw) {
    draw(IM_COL32(0, 0, 0, 255), 4.0f);
    draw(IM_COL32(255, 255, 255, 255), 2.0f);
  };
  const int a = int(axis);
  if (const ThinWallRegion* g = selectedRegion(state);
      g && state.section.index >= g->bbox_min_ijk[a] && state.section.index <= g->bbox_max_ijk[a]) {
    const ImVec2 p0 = screen(g->bbox_min_ijk[ax.right], g->bbox_max_ijk[ax.up] + 1.0);
    const ImVec2 p1 = screen(g->bbox_max_ijk[ax.right] + 1.0, g->bbox_min_ijk[ax.up]);
    mark([&](ImU32 c, float t) {
      dl->AddRect(ImVec2(p0.x - 2.0f, p0.y - 2.0f), ImVec2(p1.x + 2.0f, p1.y + 2.0f), c, 0, 0, t);
    });
  }
  if (const HotSpot* spot = selectedHotSpot(state)) {
    const double rv = spot->radius / state.model.voxelSize(), off = double(state.section.index - spot->voxel[a]);
    if (std::abs(off) < rv) {
      const ImVec2 c = screen(spot->voxel[ax.right] + 0.5, spot->voxel[ax.up] + 0.5);
      const float radius = std::max(6.0f, float(std::sqrt(rv * rv - off * off)) * win.px);
      mark([&](ImU32 col, float t) { dl->AddCircle(c, radius, col, 0, t); });
    }
  }
  dl->PopClipRect();
  drawMeasurePicks(state, axis, state.section.index, win);
  if (!hovered) return;
  const glm::ivec2 at = cellUnderMouse(win);
  const glm::ivec3 v = sectionVoxel(axis, state.section.index, win, at);
  const ImVec2 cell = win.screenOf(at.x, at.y);
  markCell(origin, ImVec2(origin.x + size.x, origin.y + size.y), cell, ImVec2(cell.x + win.px, cell.y + win.px));
  const double t = shownThickness(state, *r, v);  // the thickness the picture shows
  ImGui::SetTooltip("voxel (%d, %d, %d): %s\n%s", v.x, v.y, v.z,
                    t > 0.0 ? ("thickness " + formatLength(t, units)).c_str() : "empty", kClickToMeasure);
  if (section && section->mask.width == iw && section->mask.height == ih) pickOnClick(state, *section, win, clicked);
  zoomAndPan(state, win);
}

}  // namespace vox::app
