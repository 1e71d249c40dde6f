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
#include "app/panels/section_window.h"
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

// The voxel under the mouse: outlined and read out; a click picks it to measure, snapped to the material's edge.
void hoverReadout(AppState& state, const Section& section, const SectionWindow& win, bool clicked) {
  const glm::ivec2 at = cellUnderMouse(win);
  const glm::ivec3 voxel = sectionVoxel(section.axis, section.index, win, at);
  const std::string units = state.model.frame().units;
  const glm::dvec3 c = state.model.frame().voxelCentre(voxel.x, voxel.y, voxel.z);
  const ImVec2 cell = win.screenOf(at.x, at.y);
  markCell(win.origin, ImVec2(win.origin.x + win.size.x, win.origin.y + win.size.y), cell,
           ImVec2(cell.x + win.px, cell.y + win.px));
  ImGui::SetTooltip("voxel (%d, %d, %d): %s\ncentre (%.4g, %.4g, %.4g) %s\n%s", voxel.x, voxel.y, voxel.z,
                    section.mask.at(at.x, at.y) ? "material" : "empty", c.x, c.y, c.z,
                    units == "model" ? "model units" : units.c_str(), kClickToMeasure);
  pickOnClick(state, section, win, clicked);
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
  zoomButtons(state, "section");

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
  drawMeasurePicks(state, section->axis, section->index, win);
  if (hovered) {
    hoverReadout(state, *section, win, clicked);
    zoomAndPan(state, win);
  }
}

}  // namespace vox::app
