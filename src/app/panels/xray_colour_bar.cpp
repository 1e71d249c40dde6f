// The colour bar beside the X-ray map (xray_image.cpp), drawn with the window's draw list.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/panels/panels.h"
#include "vox/io/figure.h"

namespace vox::app {

float drawXrayColourBar(const XrayResult& x, const ScalarMapLegend& legend, ImVec2 map0, ImVec2 size) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float line = ImGui::GetTextLineHeightWithSpacing();
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
  const std::vector<int64_t> ticks = io::colourBarTicks(x.max);
  float last_y = -1e9f;
  for (size_t i = ticks.size(); i-- > 0;) {  // from the maximum down, so the maximum always gets its label
    const float f = x.max > 0 ? float(ticks[i]) / float(x.max) : 0.0f;
    const float ty = bar0.y + (1.0f - f) * bar_h;
    if (i + 1 != ticks.size() && ty - text_h * 0.5f < last_y + text_h + 3.0f) continue;  // would touch the label above
    dl->AddLine(ImVec2(bar0.x + bar_w, ty), ImVec2(bar0.x + bar_w + 5.0f, ty), ink);
    char units_label[32];
    std::snprintf(units_label, sizeof units_label, "%.4g", double(ticks[i]) * legend.units_per_value);
    dl->AddText(ImVec2(value_x, ty - text_h * 0.5f), ink, std::to_string(ticks[i]).c_str());
    dl->AddText(ImVec2(unit_x, ty - text_h * 0.5f), ink, units_label);
    last_y = ty - text_h * 0.5f;
  }
  return bar_h;
}

}  // namespace vox::app
