// Section panel (thesis 5.2.1 and 6.3): a plane normal to X, Y or Z moved through the model with a slider or played
// as successive sections, or a plane at any angle (its normal and offset, or through picked voxels); the 2D section
// image sits beside the 3D cut-away.
#include <algorithm>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>
#include <imgui.h>

#include "app/actions.h"
#include "app/full_section.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"
#include "vox/io/figure.h"

namespace vox::app {
namespace {

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

// A coarse view's section at full resolution, from the file (full_section.h): a button, the progress, the image.
void drawFullResolution(AppState& state) {
  heading("Full resolution");
  const SectionUi& s = state.section;
  const int32_t full = fullResolutionIndex(state, s.axis, s.index);
  ImGui::TextWrapped(
      "This is a coarse view (level %d) of %s. The file's own section %s = %d runs through the middle "
      "of this section's blocks.",
      state.doc.coarse_level, state.doc.path.filename().string().c_str(), axisName(s.axis), full);
  if (state.full_section_job.running()) {
    ImGui::ProgressBar(float(state.full_section_job.progress()), ImVec2(-1.0f, 0.0f), "reading the file");
    if (widget::Button("Cancel##full_section")) state.full_section_job.cancel();
  } else if (widget::Button("Read it from the file")) {
    startFullSection(state);
  }
  markWidget("full_section_button");
  if (!state.full_section_error.empty()) ImGui::TextWrapped("%s", state.full_section_error.c_str());
  if (!state.full_section) return;
  const Section& f = *state.full_section;
  if (state.full_section_texture.empty()) state.full_section_texture.upload(io::sectionPicture(f.mask, 1));
  ImGui::Text("%s = %d of the file: %s filled voxels", axisName(f.axis), f.index, groupDigits(f.filled).c_str());
  const float w = std::max(1.0f, ImGui::GetContentRegionAvail().x);
  const float scale = std::min(1.0f, w / float(std::max(f.mask.width, 1)));
  ImGui::Image(textureId(state.full_section_texture.id()),
               ImVec2(float(f.mask.width) * scale, float(f.mask.height) * scale));
}

std::string numberWord(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Whether and which half the 3D view cuts away at the section (axis or any angle), and the section's export when
// there is a section.
void drawCutAwayControls(AppState& state, bool can_export = true) {
  heading("3D view");
  actionCheckbox(state, ActionId::kViewCut, "Cut away the model at the section");
  if (state.view.cut_away) {
    int keep = state.view.keep_above ? 1 : 0;
    widget::RadioButton("Keep below", &keep, 0);
    ImGui::SameLine();
    widget::RadioButton("Keep above", &keep, 1);
    state.view.keep_above = keep == 1;
  }
  if (!can_export) return;
  ImGui::Spacing();
  if (widget::Button("Export section PNG...")) dispatch(state, ActionId::kExportSectionPng);
}

// The plane through picked voxels (clicked in an axis section or the 3D view, as for measuring): the last one, the
// normal kept, or the last three.
void drawPlaneThroughPicks(AppState& state) {
  const std::vector<glm::ivec3>& recent = recentPicks(state);
  std::vector<std::string> words;
  std::string listed;
  for (const glm::ivec3& v : recent) {
    for (int k = 0; k < 3; ++k) words.push_back(std::to_string(v[k]));
    listed += (listed.empty() ? "" : ", ") + std::string("(") + std::to_string(v.x) + ", " + std::to_string(v.y) +
              ", " + std::to_string(v.z) + ")";
  }
  ImGui::TextWrapped("Picked voxels: %s",
                     recent.empty() ? "none (click them in an X, Y or Z section)" : listed.c_str());
  ImGui::BeginDisabled(recent.empty());
  if (widget::Button("Through the last pick")) {
    dispatchValues(state, ActionId::kSectionPlaneThrough, std::vector<std::string>(words.end() - 3, words.end()));
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(recent.size() < 3);
  if (widget::Button("Through the last 3 picks")) dispatchValues(state, ActionId::kSectionPlaneThrough, words);
  ImGui::EndDisabled();
}

// A section at any angle: the plane's normal and its offset from the centre of the model's box (each edit is the
// section-plane action), and what the section holds.
void drawObliqueControls(AppState& state) {
  SectionUi& s = state.section;
  glm::dvec3 normal = s.normal;
  double offset = s.offset;
  bool edited = false;
  const char* labels[3] = {"X##normal", "Y##normal", "Z##normal"};
  ImGui::TextUnformatted("Plane normal");
  for (int k = 0; k < 3; ++k) {
    ImGui::SetNextItemWidth(70.0f);
    if (k > 0) ImGui::SameLine();
    widget::InputDouble(labels[k], &normal[k], 0.0, 0.0, "%.3g");
    edited = edited || ImGui::IsItemDeactivatedAfterEdit();
  }
  const GridFrame& f = state.model.frame();
  const float reach =
      float(0.5 * f.voxel_size * glm::length(glm::dvec3(state.model.nx(), state.model.ny(), state.model.nz())));
  float off = float(offset);
  ImGui::SetNextItemWidth(-1.0f);
  if (widget::SliderFloat("##offset", &off, -reach, reach, "offset %.4g")) {
    offset = double(off);
    edited = true;
  }
  markWidget("section_offset");
  if (ImGui::IsItemActive()) state.viewport.interacting = true;  // coarse 3D points while dragging
  if (edited && normal != glm::dvec3(0.0)) {
    dispatchValues(state, ActionId::kSectionPlane,
                   {numberWord(normal.x), numberWord(normal.y), numberWord(normal.z), numberWord(offset)});
  }
  drawPlaneThroughPicks(state);
  const ObliqueSection* o = currentObliqueSection(state);
  if (!o) {
    if (!state.oblique_error.empty()) ImGui::TextWrapped("%s", state.oblique_error.c_str());
    drawCutAwayControls(state, false);
    return;
  }
  heading("This section");
  const std::string units = unitsLabel(f.units);
  if (beginFactTable("oblique_facts")) {
    tableRow("Filled samples", groupDigits(o->filled));
    char text[96];
    std::snprintf(text, sizeof text, "%.5g %s^2", o->area, units.c_str());
    tableRow("Area", text);
    tableRow("Sample spacing", formatLength(o->pixel, f.units));
    std::snprintf(text, sizeof text, "(%.3f, %.3f, %.3f)", o->point.x, o->point.y, o->point.z);
    tableRow("Through", text);
    ImGui::EndTable();
  }
  drawCutAwayControls(state);
}

}  // namespace

void drawSectionPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to see its sections.");
    return;
  }
  peeledNotice(state);
  SectionUi& s = state.section;
  int axis = s.oblique ? 3 : int(s.axis);
  ImGui::TextUnformatted("Normal to");
  for (int a = 0; a < 3; ++a) {
    ImGui::SameLine();
    const std::string label = std::string(1, char('X' + a)) + "##axis";
    if (widget::RadioButton(label.c_str(), &axis, a)) {
      const Axis to = Axis(a);
      dispatchValues(state, ActionId::kSectionAt, {axisName(to), std::to_string(axisLength(state, to) / 2)});
    }
  }
  ImGui::SameLine();
  if (widget::RadioButton("any##axis", &axis, 3) && !s.oblique) {
    dispatchValues(state, ActionId::kSectionPlane,
                   {numberWord(s.normal.x), numberWord(s.normal.y), numberWord(s.normal.z), numberWord(s.offset)});
  }
  if (s.oblique) {
    drawObliqueControls(state);
    return;
  }
  const int32_t n = axisLength(state, s.axis);
  advancePlayback(state, n);
  s.index = std::clamp(s.index, 0, std::max(n - 1, 0));

  ImGui::SetNextItemWidth(-1.0f);
  widget::SliderInt("##section_index", &s.index, 0, std::max(n - 1, 0), "index %d");
  markWidget("section_slider");
  if (ImGui::IsItemActive()) {
    s.playing = false;
    state.viewport.interacting = true;  // coarse 3D points while dragging
  }
  const Section* section = currentSection(state);
  const std::string units = state.model.frame().units;
  if (section) {
    ImGui::Text("%s = %s  (index %d of 0..%d)", axisName(s.axis),
                formatCoordinate(section->position, units, state.model.voxelSize()).c_str(), s.index, n - 1);
  }

  // Step and play: the buttons dispatch the same actions as the Section menu and PgUp / PgDn / Space.
  if (widget::Button("|<")) dispatchValues(state, ActionId::kSectionAt, {axisName(s.axis), "0"});
  ImGui::SameLine();
  if (widget::Button("<")) dispatch(state, ActionId::kSectionPrev);
  ImGui::SameLine();
  if (widget::Button(s.playing ? "Pause" : "Play", ImVec2(60.0f, 0.0f))) dispatch(state, ActionId::kSectionPlay);
  ImGui::SameLine();
  if (widget::Button(">")) dispatch(state, ActionId::kSectionNext);
  ImGui::SameLine();
  if (widget::Button(">|")) {
    dispatchValues(state, ActionId::kSectionAt, {axisName(s.axis), std::to_string(n - 1)});
  }
  ImGui::SetNextItemWidth(120.0f);
  if (widget::InputInt("Step", &s.step)) s.step = std::clamp(s.step, 1, std::max(1, n));
  ImGui::SetNextItemWidth(120.0f);
  widget::SliderFloat("Sections / s", &s.play_speed, 1.0f, 60.0f, "%.0f");

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

  if (state.doc.coarse_level > 1) drawFullResolution(state);

  drawCutAwayControls(state);
}

}  // namespace vox::app
