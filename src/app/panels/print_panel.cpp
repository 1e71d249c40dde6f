// Print panel (docs/conventions.md, "Printability"): whether the part prints along a build direction chosen from a
// list, from the search over directions or by clicking a face to lay on the plate; the overhangs past the overhang
// angle (red in 3D), the support under them (translucent blue columns), the trapped cavities (a click takes the section
// there) and the build directions ranked by support (a click applies one). Computed in the background while the panel
// is open.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/panels/panels.h"
#include "app/print.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

constexpr int kMostOrientationRows = 20;

// "+z", or a direction off the axes to two decimals: "(0.62, 0.37, -0.69)".
std::string shortDirection(glm::dvec3 d) {
  const std::string name = printDirectionName(d);
  if (name.size() <= 2) return name;
  char text[48];
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", d.x, d.y, d.z);
  return text;
}

void directionChoice(AppState& state) {
  heading("Build direction (up)");
  static const char* const axes[] = {"+z", "-z", "+x", "-x", "+y", "-y"};
  const std::string now = printDirectionName(state.print_ui.up);
  for (int i = 0; i < 6; ++i) {
    if (i > 0) ImGui::SameLine();
    if (widget::RadioButton(axes[i], now == axes[i])) dispatchValues(state, ActionId::kPrintDirection, {axes[i]});
  }
  if (now.size() > 2) ImGui::Text("Up: %s", shortDirection(state.print_ui.up).c_str());
  const bool laying = state.print_ui.lay_face;
  if (widget::Button(laying ? "Click a face in the 3D view... (cancel)" : "Lay a face on the plate")) {
    dispatch(state, ActionId::kPrintLayFace);
  }
  markWidget("print_lay_face");
  helpMarker("Click the face the part should stand on: the build direction becomes the opposite of its normal.");

  heading("Overhang angle", state, "overhang");
  // applied when the slider is let go: each angle on the way would check the part again
  PrintUi& ui = state.print_ui;
  float angle = ui.angle_drag >= 0.0f ? ui.angle_drag : float(ui.overhang_angle);
  ImGui::SetNextItemWidth(-1.0f);
  if (widget::SliderFloat("##overhang_angle", &angle, 0.0f, 89.0f, "%.0f deg from the vertical")) {
    ui.angle_drag = angle;
  }
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    dispatchValues(state, ActionId::kOverhangAngle, {std::to_string(angle)});
    ui.angle_drag = -1.0f;
  } else if (!ImGui::IsItemActive()) {
    ui.angle_drag = -1.0f;
  }
  markWidget("overhang_angle_slider");
}

// While computing, after a cancel or a failure: says so; returns the result when there is one.
const PrintResult* printOrStatus(AppState& state) {
  if (const PrintResult* r = currentPrint(state)) return r;
  if (const Error* e = state.print.error(wantedPrintKey(state))) {
    wrappedColoured(kErrorColour, "Printability could not be checked: " + e->message);
  } else if (printCancelled(state)) {
    ImGui::TextUnformatted("Cancelled.");
    if (widget::Button("Check printability")) dispatch(state, ActionId::kComputePrint);
  } else {
    ImGui::TextUnformatted(state.print_ui.orient ? "Checking printability and the build directions..."
                                                 : "Checking printability...");
    ImGui::ProgressBar(float(state.print.progress()), ImVec2(-1.0f, 0.0f));
    if (widget::Button("Cancel")) dispatch(state, ActionId::kCancelPrint);
    markWidget("print_cancel");
  }
  return nullptr;
}

void cavityList(AppState& state, const PrintResult& r, const std::string& units) {
  heading("Trapped cavities", state, "trapped-cavity");
  const auto& cavities = r.check.cavities;
  if (cavities.empty()) {
    ImGui::TextWrapped("None: every empty space inside reaches the outside, so powder or resin can drain.");
    return;
  }
  ImGui::TextWrapped("%s, %s in all, from which powder or resin cannot drain. Click one to see its section.",
                     countOf(int64_t(cavities.size()), "cavity").c_str(),
                     formatVolume(r.check.trapped_volume, units).c_str());
  const int rows = std::min(int(cavities.size()), 200);
  if (!beginScrollList("print_cavities", 3, rows, 5)) return;
  ImGui::TableSetupColumn(columnHeader("Volume", units, 3).c_str());
  ImGui::TableSetupColumn("Centre");
  ImGui::TableSetupColumn(columnHeader("Shortest drain", units).c_str());
  ImGui::TableHeadersRow();
  for (int i = 0; i < rows; ++i) {
    const TrappedCavity& c = cavities[size_t(i)];
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::PushID(i);
    if (widget::Selectable(columnNumber(c.volume).c_str(), selectedCavity(state) == &c,
                           ImGuiSelectableFlags_SpanAllColumns)) {
      dispatchValues(state, ActionId::kPrintCavity, {std::to_string(i + 1)});
    }
    ImGui::PopID();
    ImGui::TableSetColumnIndex(1);
    ImGui::Text("%.4g, %.4g, %.4g", c.centre.x, c.centre.y, c.centre.z);
    ImGui::TableSetColumnIndex(2);
    ImGui::TextUnformatted(c.drain ? columnNumber(c.drain->length).c_str() : "none straight");
  }
  ImGui::EndTable();
}

void orientationList(AppState& state, const PrintResult& r, const std::string& units) {
  heading("Best way up");
  if (!r.key.orient) {
    if (widget::Button("Find the best way up")) dispatch(state, ActionId::kPrintOrient);
    markWidget("print_orient");
    helpMarker("Checks the six axes and 100 directions spread over the sphere, least support first.");
    return;
  }
  const auto& list = r.check.orientations;
  ImGui::TextWrapped("%zu directions, least support first. Click one to print that way up.", list.size());
  const int rows = std::min(int(list.size()), kMostOrientationRows);
  if (!beginScrollList("print_orientations", 3, rows, 8)) return;
  ImGui::TableSetupColumn("Up", ImGuiTableColumnFlags_WidthFixed, 135.0f);
  ImGui::TableSetupColumn(columnHeader("Support", units, 3).c_str());
  ImGui::TableSetupColumn(columnHeader("Height", units).c_str());
  ImGui::TableHeadersRow();
  const std::string now = printDirectionName(state.print_ui.up);
  for (int i = 0; i < rows; ++i) {
    const PrintSupport& s = list[size_t(i)];
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::PushID(i);
    const std::string name = shortDirection(s.direction);
    if (widget::Selectable(name.c_str(), printDirectionName(s.direction) == now, ImGuiSelectableFlags_SpanAllColumns)) {
      dispatchValues(state, ActionId::kPrintOrientation, {std::to_string(i + 1)});
    }
    ImGui::PopID();
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(columnNumber(s.support_volume).c_str());
    ImGui::TableSetColumnIndex(2);
    ImGui::TextUnformatted(columnNumber(s.height).c_str());
  }
  ImGui::EndTable();
}

}  // namespace

void drawPrintPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to check whether it prints.");
    return;
  }
  directionChoice(state);
  heading("Support");
  const PrintResult* r = printOrStatus(state);
  if (!r) return;
  const std::string units = state.model.frame().units;
  const PrintSupport& s = r->check.support;
  if (beginFactTable("print_facts")) {
    tableRow("Overhang area", formatArea(s.overhang_area, units));
    tableRow("Support volume", formatVolume(s.support_volume, units));
    tableRow("Build height", formatLength(s.height, units));
    tableRow("Surface", r->check.from_mesh ? "the mesh's own normals" : "the voxels' smooth surface");
    tableRow("Checked in", formatSeconds(r->seconds));
    ImGui::EndTable();
  }
  cavityList(state, *r, units);
  orientationList(state, *r, units);
  if (!state.print_ui.volume_problem.empty()) wrappedColoured(kWarningColour, state.print_ui.volume_problem);
}

}  // namespace vox::app
