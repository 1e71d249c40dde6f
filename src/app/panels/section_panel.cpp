// Section panel (thesis 5.2.1 and 6.3): a plane normal to X, Y or Z moved through the model with a slider or played
// as successive sections; the 2D section image sits beside the 3D cut-away.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"
#include "vox/io/figure.h"

namespace vox::app {
namespace {

// Image axes of a section (vox/analysis/analysis.h): which grid axis runs right and which runs up.
struct ImageAxes {
  int right, up;
};
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

void advancePlayback(AppState& state, int32_t n) {
  SectionUi& s = state.section;
  if (!s.playing || n <= 0) return;
  s.play_accumulator += state.frame_time_s * double(s.play_speed);
  const int32_t steps = int32_t(s.play_accumulator);
  if (steps <= 0) return;
  s.play_accumulator -= steps;
  int32_t next = s.index + steps * std::max(1, s.step);
  if (next >= n) next = 0;  // loop, like the thesis's "successive incremental sections"
  s.index = next;
  state.viewport.interacting = true;
}

}  // namespace

void drawSectionPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to see its sections.");
    return;
  }
  peeledNotice(state);
  SectionUi& s = state.section;
  int axis = int(s.axis);
  ImGui::TextUnformatted("Normal to");
  for (int a = 0; a < 3; ++a) {
    ImGui::SameLine();
    const std::string label = std::string(1, char('X' + a)) + "##axis";
    if (ImGui::RadioButton(label.c_str(), &axis, a)) {
      const Axis to = Axis(a);
      dispatchValues(state, ActionId::kSectionAt, {axisName(to), std::to_string(axisLength(state, to) / 2)});
    }
  }
  const int32_t n = axisLength(state, s.axis);
  advancePlayback(state, n);
  s.index = std::clamp(s.index, 0, std::max(n - 1, 0));

  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderInt("##section_index", &s.index, 0, std::max(n - 1, 0), "index %d");
  markWidget("section_slider");
  if (ImGui::IsItemActive()) {
    s.playing = false;
    state.viewport.interacting = true;  // coarse 3D points while dragging
  }
  const Section* section = currentSection(state);
  const std::string units = state.model.frame().units;
  if (section) {
    ImGui::Text("%s = %s  (index %d of 0..%d)", axisName(s.axis), formatLength(section->position, units).c_str(),
                s.index, n - 1);
  }

  // Step and play: the buttons dispatch the same actions as the Section menu and PgUp / PgDn / Space.
  if (ImGui::Button("|<")) dispatchValues(state, ActionId::kSectionAt, {axisName(s.axis), "0"});
  ImGui::SameLine();
  if (ImGui::Button("<")) dispatch(state, ActionId::kSectionPrev);
  ImGui::SameLine();
  if (ImGui::Button(s.playing ? "Pause" : "Play", ImVec2(60.0f, 0.0f))) dispatch(state, ActionId::kSectionPlay);
  ImGui::SameLine();
  if (ImGui::Button(">")) dispatch(state, ActionId::kSectionNext);
  ImGui::SameLine();
  if (ImGui::Button(">|")) {
    dispatchValues(state, ActionId::kSectionAt, {axisName(s.axis), std::to_string(n - 1)});
  }
  ImGui::SetNextItemWidth(120.0f);
  if (ImGui::InputInt("Step", &s.step)) s.step = std::clamp(s.step, 1, std::max(1, n));
  ImGui::SetNextItemWidth(120.0f);
  ImGui::SliderFloat("Sections / s", &s.play_speed, 1.0f, 60.0f, "%.0f");

  if (section) {
    heading("This section");
    const double h = state.model.voxelSize();
    if (beginFactTable("section_facts")) {
      tableRow("Filled voxels", groupDigits(section->filled));
      char area[64];
      std::snprintf(area, sizeof area, "%.5g %s^2", double(section->filled) * h * h,
                    unitsLabel(state.model.frame().units).c_str());
      tableRow("Area", area);
      const ImageAxes ax = imageAxes(s.axis);
      tableRow("Image", std::string(axisName(Axis(ax.right))) + " to the right, " + axisName(Axis(ax.up)) + " up");
      ImGui::EndTable();
    }
  } else if (!state.section_error.empty()) {
    ImGui::TextWrapped("%s", state.section_error.c_str());
  }

  heading("3D view");
  actionCheckbox(state, ActionId::kViewCut, "Cut away the model at the section");
  if (state.view.cut_away) {
    int keep = state.view.keep_above ? 1 : 0;
    ImGui::RadioButton("Keep below", &keep, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Keep above", &keep, 1);
    state.view.keep_above = keep == 1;
  }
  ImGui::Spacing();
  if (ImGui::Button("Export section PNG...")) dispatch(state, ActionId::kExportSectionPng);
}

void drawSectionImage(AppState& state) {
  const Section* section = currentSection(state);
  if (!section) {
    ImGui::TextWrapped("%s", state.section_error.empty() ? "No section." : state.section_error.c_str());
    return;
  }
  if (state.section_texture.empty()) state.section_texture.upload(io::sectionPicture(section->mask, 1));
  const std::string units = state.model.frame().units;
  ImGui::Text("Section %s = %s, index %d: %s voxels", axisName(section->axis),
              formatLength(section->position, units).c_str(), section->index, groupDigits(section->filled).c_str());

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
  ImGui::Image(textureId(state.section_texture.id()), size);
  markWidget("section_image");
  const bool hovered = ImGui::IsItemHovered();
  const bool clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
  ImGui::SetCursorScreenPos(ImVec2(origin.x + size.x - 40.0f, origin.y + size.y + 2.0f));
  ImGui::Text("%s >", axisName(Axis(ax.right)));
  // The scale bar on its own line, under the axis label, so the two never run into each other.
  drawScaleBar(ImVec2(origin.x, origin.y + size.y + 2.0f + label_h), scale / float(state.model.voxelSize()), units,
               std::max(size.x * 0.5f, 60.0f));
  ImGui::Dummy(ImVec2(0.0f, label_h));
  // Picked voxels in this section: rings at their cells (the 3D view says what they measure).
  const auto cellOf = [&](const glm::ivec3& v) {
    return ImVec2(origin.x + (float(v[ax.right]) + 0.5f) * scale, origin.y + (float(ih - 1 - v[ax.up]) + 0.5f) * scale);
  };
  const std::vector<glm::ivec3>& picks = measurePicks(state);
  for (size_t i = 0; i < picks.size(); ++i) {
    if (picks[i][int(section->axis)] != section->index) continue;
    const ImVec2 c = cellOf(picks[i]);
    ImGui::GetWindowDrawList()->AddCircle(c, std::max(5.0f, scale), IM_COL32(255, 220, 60, 255), 0, 2.0f);
    const char label[2] = {char('A' + i), 0};
    ImGui::GetWindowDrawList()->AddText(ImVec2(c.x + 7.0f, c.y - 16.0f), IM_COL32(255, 220, 60, 255), label);
  }

  if (hovered) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const int32_t u = std::clamp(int32_t((m.x - origin.x) / scale), 0, iw - 1);
    const int32_t row = std::clamp(int32_t((m.y - origin.y) / scale), 0, ih - 1);
    const int32_t v = ih - 1 - row;  // row 0 holds the largest "up" index
    int32_t voxel[3];
    voxel[int(section->axis)] = section->index;
    voxel[ax.right] = u;
    voxel[ax.up] = v;
    const glm::dvec3 c = state.model.frame().voxelCentre(voxel[0], voxel[1], voxel[2]);
    const ImVec2 cell(origin.x + float(u) * scale, origin.y + float(row) * scale);
    markCell(origin, ImVec2(origin.x + size.x, origin.y + size.y), cell, ImVec2(cell.x + scale, cell.y + scale));
    ImGui::SetTooltip("voxel (%d, %d, %d): %s\ncentre (%.4g, %.4g, %.4g) %s\nclick to measure", voxel[0], voxel[1],
                      voxel[2], section->mask.at(u, row) ? "material" : "empty", c.x, c.y, c.z,
                      units == "model" ? "model units" : units.c_str());
    if (clicked) addMeasurePick(state, glm::ivec3(voxel[0], voxel[1], voxel[2]));
  }
}

}  // namespace vox::app
