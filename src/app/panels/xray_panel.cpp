// X-ray panel (thesis 5.2.3 and 6.5): thickness of material along rays parallel to an axis, per ray the thinnest
// run (min), the thickest run (max) or the sum of the runs (total). The map beside the 3D view is xray_image.cpp.
#include <string>
#include <utility>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {

void drawXrayPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to X-ray it.");
    return;
  }
  peeledNotice(state);
  const XrayParams& p = state.xray.params;
  // The buttons dispatch the X-ray action with the axis and mode they stand for, as a script's "xray y max" does.
  const auto choose = [&state](Axis axis, XrayMode mode) {
    dispatchValues(state, ActionId::kXray, {axisName(axis), xrayModeName(mode)});
  };
  ImGui::TextUnformatted("Rays along");
  for (int a = 0; a < 3; ++a) {
    ImGui::SameLine();
    const std::string label = std::string(1, char('X' + a)) + "##xray_axis";
    if (widget::RadioButton(label.c_str(), int(p.axis) == a)) choose(Axis(a), p.mode);
  }
  const std::pair<XrayMode, const char*> modes[] = {
      {XrayMode::kMin, "Minimum"}, {XrayMode::kMax, "Maximum"}, {XrayMode::kTotal, "Total"}};
  for (const auto& [mode, label] : modes) {
    if (mode != XrayMode::kMin) ImGui::SameLine();
    if (widget::RadioButton(label, p.mode == mode)) choose(p.axis, mode);
    markWidget(std::string("xray_") + xrayModeName(mode));
  }
  ImGui::TextWrapped("%s", p.mode == XrayMode::kMin   ? "Per ray: the thinnest wall it crosses."
                           : p.mode == XrayMode::kMax ? "Per ray: the thickest wall it crosses."
                                                      : "Per ray: all the material it crosses, added up.");

  const XrayResult* x = currentXray(state);
  const XrayKey key{state.model_version, p.axis, p.mode};
  if (!x) {
    if (const Error* e = state.xray_result.error(key)) {
      ImGui::TextWrapped("The X-ray failed: %s", e->message.c_str());
    } else {
      ImGui::TextUnformatted("Computing...");
    }
    return;
  }
  heading("Statistics over rays that hit material");
  const double h = x->voxel_size;
  const std::string units = state.model.frame().units;
  if (ImGui::BeginTable("xray_facts", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("");
    ImGui::TableSetupColumn("voxels");
    ImGui::TableSetupColumn(units == "model" ? "model units" : units.c_str());
    ImGui::TableHeadersRow();
    auto row = [&](const char* label, double v, const char* vfmt) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextDisabled("%s", label);
      ImGui::TableSetColumnIndex(1);
      ImGui::Text(vfmt, v);
      ImGui::TableSetColumnIndex(2);
      ImGui::Text("%.4g", v * h);
    };
    row("Minimum", double(x->min), "%.0f");
    row("Maximum", double(x->max), "%.0f");
    row("Mean", x->mean, "%.2f");
    ImGui::EndTable();
  }
  ImGui::Text("Rays hitting material: %s of %s", groupDigits(x->rays_hit).c_str(),
              groupDigits(int64_t(x->thickness.width) * x->thickness.height).c_str());
  ImGui::Spacing();
  if (widget::Button("Export PNG...")) dispatch(state, ActionId::kExportXrayPng);
  ImGui::SameLine();
  if (widget::Button("Export CSV...")) dispatch(state, ActionId::kExportXrayCsv);
}

}  // namespace vox::app
