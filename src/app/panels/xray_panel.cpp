// X-ray panel (thesis 5.2.3 and 6.5): thickness of material along rays parallel to an axis, per ray the thinnest
// run (min), the thickest run (max) or the sum of the runs (total). The map is a texture of one texel per ray; its
// colour bar, labels and axes are drawn as UI at screen size, and hovering the map reads the thickness of one ray.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/io/figure.h"

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
    if (ImGui::RadioButton(label.c_str(), int(p.axis) == a)) choose(Axis(a), p.mode);
  }
  const std::pair<XrayMode, const char*> modes[] = {
      {XrayMode::kMin, "Minimum"}, {XrayMode::kMax, "Maximum"}, {XrayMode::kTotal, "Total"}};
  for (const auto& [mode, label] : modes) {
    if (mode != XrayMode::kMin) ImGui::SameLine();
    if (ImGui::RadioButton(label, p.mode == mode)) choose(p.axis, mode);
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
  if (ImGui::Button("Export PNG...")) dispatch(state, ActionId::kExportXrayPng);
  ImGui::SameLine();
  if (ImGui::Button("Export CSV...")) dispatch(state, ActionId::kExportXrayCsv);
}

ImVec2 xrayLegendSize() {
  // Title above the map, the colour bar with two columns of labels beside it, the read-out below.
  const float line = ImGui::GetTextLineHeightWithSpacing();
  return ImVec2(ImGui::CalcTextSize("0000000  000.00000").x + 64.0f, 5.0f * line + 8.0f);
}

void drawXrayImage(AppState& state) {
  const XrayResult* x = currentXray(state);
  if (!x) {
    ImGui::TextUnformatted("Computing the X-ray...");
    return;
  }
  const int32_t tw = x->thickness.width, th = x->thickness.height;
  const XrayKey key{state.model_version, x->axis, x->mode};
  const ScalarMapLegend legend = xrayLegend(*x);

  // The map, one texel per ray, coloured once per change; the texture shows it magnified without smoothing.
  if (!(key == state.xray_texture_key) || state.xray_texture.empty()) {
    ImageRgb map(tw, th);
    const double top = double(std::max<int64_t>(x->max, 1));
    for (int32_t v = 0; v < th; ++v) {
      for (int32_t u = 0; u < tw; ++u) {
        const int32_t t = x->thickness.at(u, v);
        map.at(u, v) = t > 0 ? io::rampColour(double(t) / top) : io::kNoMaterialColour;
      }
    }
    state.xray_texture.upload(map);
    state.xray_texture_key = key;
  }

  ImGui::TextUnformatted(legend.title.c_str());
  ImGui::Dummy(ImVec2(0.0f, ImGui::GetTextLineHeight() * 1.2f));  // room for the colour bar's column headers
  // Room left of the map for the "up" axis label.
  const float axis_w = std::max(ImGui::CalcTextSize(legend.up_axis.c_str()).x, ImGui::CalcTextSize("^").x) + 6.0f;
  ImGui::SetCursorPosX(ImGui::GetCursorPosX() + axis_w);
  const ImVec2 legend_size = xrayLegendSize();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  float fit = std::min((avail.x - legend_size.x - axis_w) / float(tw), (avail.y - 3.0f * line - 4.0f) / float(th));
  if (fit >= 1.0f) fit = std::floor(fit);  // whole pixels per ray keep every ray the same square
  fit = std::max(fit, 0.05f);
  const ImVec2 size(float(tw) * fit, float(th) * fit);
  const ImVec2 map0 = ImGui::GetCursorScreenPos();
  ImGui::Image(textureId(state.xray_texture.id()), size);
  const bool hovered = ImGui::IsItemHovered();
  markWidget("xray_image");
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRect(ImVec2(map0.x - 1.0f, map0.y - 1.0f), ImVec2(map0.x + size.x + 1.0f, map0.y + size.y + 1.0f),
              IM_COL32(120, 120, 120, 255));

  // The colour bar beside the map, as UI at screen size: 0 at the bottom, the maximum at the top, ticks labelled in
  // voxels and in model units.
  const float bar_h = std::max(size.y, 6.0f * line);
  const ImVec2 bar0(map0.x + size.x + 16.0f, map0.y);
  const float bar_w = 14.0f;
  constexpr int kBands = 32;
  for (int i = 0; i < kBands; ++i) {
    const auto colour = [](double t) {
      const Rgb8 c = io::rampColour(t);
      return IM_COL32(c.r, c.g, c.b, 255);
    };
    const double t_top = 1.0 - double(i) / kBands, t_bottom = 1.0 - double(i + 1) / kBands;
    const float y0 = bar0.y + bar_h * float(i) / kBands, y1 = bar0.y + bar_h * float(i + 1) / kBands;
    dl->AddRectFilledMultiColor(ImVec2(bar0.x, y0), ImVec2(bar0.x + bar_w, y1), colour(t_top), colour(t_top),
                                colour(t_bottom), colour(t_bottom));
  }
  dl->AddRect(ImVec2(bar0.x - 1.0f, bar0.y - 1.0f), ImVec2(bar0.x + bar_w + 1.0f, bar0.y + bar_h + 1.0f),
              IM_COL32(120, 120, 120, 255));
  const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
  const float text_h = ImGui::GetTextLineHeight();
  const float value_x = bar0.x + bar_w + 8.0f;
  const float unit_x = value_x + ImGui::CalcTextSize("0000000").x + 8.0f;
  const float header_y = bar0.y - 1.5f * text_h - 2.0f;
  dl->AddText(ImVec2(value_x, header_y), ink, legend.value_name.c_str());
  dl->AddText(ImVec2(unit_x, header_y), ink, legend.units.c_str());
  const std::vector<int64_t> ticks = io::colourBarTicks(x->max);
  float last_y = -1e9f;
  for (size_t i = ticks.size(); i-- > 0;) {  // from the maximum down, so the maximum always gets its label
    const float f = x->max > 0 ? float(ticks[i]) / float(x->max) : 0.0f;
    const float ty = bar0.y + (1.0f - f) * bar_h;
    if (i + 1 != ticks.size() && ty - text_h * 0.5f < last_y + text_h + 3.0f) continue;  // would touch the label above
    dl->AddLine(ImVec2(bar0.x + bar_w, ty), ImVec2(bar0.x + bar_w + 5.0f, ty), ink);
    char units_label[32];
    std::snprintf(units_label, sizeof units_label, "%.4g", double(ticks[i]) * legend.units_per_value);
    dl->AddText(ImVec2(value_x, ty - text_h * 0.5f), ink, std::to_string(ticks[i]).c_str());
    dl->AddText(ImVec2(unit_x, ty - text_h * 0.5f), ink, units_label);
    last_y = ty - text_h * 0.5f;
  }
  // The scale bar on its own line, under the axis label, so the two never run into each other.
  drawScaleBar(ImVec2(map0.x, map0.y + size.y + 2.0f + line), fit / float(x->voxel_size), state.model.frame().units,
               std::max(size.x * 0.5f, 60.0f));
  // Image axes: "right" under the map's bottom-right corner, "up" beside its top-left corner.
  const std::string right = legend.right_axis + " >";
  dl->AddText(ImVec2(map0.x + size.x - ImGui::CalcTextSize(right.c_str()).x, map0.y + size.y + 2.0f), ink,
              right.c_str());
  dl->AddText(ImVec2(map0.x - ImGui::CalcTextSize("^").x - 4.0f, map0.y), ink, "^");
  dl->AddText(ImVec2(map0.x - ImGui::CalcTextSize(legend.up_axis.c_str()).x - 4.0f, map0.y + text_h), ink,
              legend.up_axis.c_str());
  ImGui::Dummy(ImVec2(0.0f, std::max(0.0f, bar_h - size.y) + line * 1.5f));

  // Hover read-out: the ray under the mouse, found from where the map was drawn.
  std::string readout = "Hover the map to read the thickness of one ray.";
  if (hovered) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const int32_t u = int32_t(std::floor((m.x - map0.x) / fit)), row = int32_t(std::floor((m.y - map0.y) / fit));
    if (u >= 0 && u < tw && row >= 0 && row < th) {
      const int32_t v = th - 1 - row;  // row 0 holds the largest "up" index
      const int32_t t = x->thickness.at(u, row);
      const ImVec2 c0(map0.x + float(u) * fit, map0.y + float(row) * fit);
      markCell(map0, ImVec2(map0.x + size.x, map0.y + size.y), c0, ImVec2(c0.x + fit, c0.y + fit));
      char buf[200];
      if (t > 0) {
        std::snprintf(buf, sizeof buf, "Ray %s = %d, %s = %d: %s thickness %d voxels = %.4g %s",
                      legend.right_axis.c_str(), u, legend.up_axis.c_str(), v, xrayModeName(x->mode), t,
                      double(t) * x->voxel_size, legend.units.c_str());
      } else {
        std::snprintf(buf, sizeof buf, "Ray %s = %d, %s = %d: no material", legend.right_axis.c_str(), u,
                      legend.up_axis.c_str(), v);
      }
      readout = buf;
    }
  }
  ImGui::TextUnformatted(readout.c_str());
}

}  // namespace vox::app
