// X-ray image (thesis 5.2.3 and 6.5): the map is a texture of one texel per ray; its colour bar
// (xray_colour_bar.cpp), labels and axes are drawn as UI at screen size, and hovering the map reads one ray.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/io/figure.h"

namespace vox::app {
namespace {

// The map, one texel per ray, coloured once per change; the texture shows it magnified without smoothing.
void uploadXrayMap(AppState& state, const XrayResult& x, const XrayKey& key) {
  const int32_t tw = x.thickness.width, th = x.thickness.height;
  if (!(key == state.xray_texture_key) || state.xray_texture.empty()) {
    ImageRgb map(tw, th);
    const double top = double(std::max<int64_t>(x.max, 1));
    for (int32_t v = 0; v < th; ++v) {
      for (int32_t u = 0; u < tw; ++u) {
        const int32_t t = x.thickness.at(u, v);
        map.at(u, v) = t > 0 ? io::rampColour(double(t) / top) : io::kNoMaterialColour;
      }
    }
    state.xray_texture.upload(map);
    state.xray_texture_key = key;
  }
}

// Image axes: "right" under the map's bottom-right corner, "up" beside its top-left corner.
void drawMapAxes(const ScalarMapLegend& legend, ImVec2 map0, ImVec2 size) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
  const float text_h = ImGui::GetTextLineHeight();
  const std::string right = legend.right_axis + " >";
  dl->AddText(ImVec2(map0.x + size.x - ImGui::CalcTextSize(right.c_str()).x, map0.y + size.y + 2.0f), ink,
              right.c_str());
  dl->AddText(ImVec2(map0.x - ImGui::CalcTextSize("^").x - 4.0f, map0.y), ink, "^");
  dl->AddText(ImVec2(map0.x - ImGui::CalcTextSize(legend.up_axis.c_str()).x - 4.0f, map0.y + text_h), ink,
              legend.up_axis.c_str());
}

// Hover read-out: the ray under the mouse, found from where the map was drawn (map0, `fit` pixels per ray).
std::string hoverReadout(const XrayResult& x, const ScalarMapLegend& legend, ImVec2 map0, ImVec2 size, float fit,
                         bool hovered) {
  const int32_t tw = x.thickness.width, th = x.thickness.height;
  std::string readout = "Hover the map to read the thickness of one ray.";
  if (hovered) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const int32_t u = int32_t(std::floor((m.x - map0.x) / fit)), row = int32_t(std::floor((m.y - map0.y) / fit));
    if (u >= 0 && u < tw && row >= 0 && row < th) {
      const int32_t v = th - 1 - row;  // row 0 holds the largest "up" index
      const int32_t t = x.thickness.at(u, row);
      const ImVec2 c0(map0.x + float(u) * fit, map0.y + float(row) * fit);
      markCell(map0, ImVec2(map0.x + size.x, map0.y + size.y), c0, ImVec2(c0.x + fit, c0.y + fit));
      char buf[200];
      if (t > 0) {
        std::snprintf(buf, sizeof buf, "Ray %s = %d, %s = %d: %s thickness %d voxels = %.4g %s",
                      legend.right_axis.c_str(), u, legend.up_axis.c_str(), v, xrayModeName(x.mode), t,
                      double(t) * x.voxel_size, legend.units.c_str());
      } else {
        std::snprintf(buf, sizeof buf, "Ray %s = %d, %s = %d: no material", legend.right_axis.c_str(), u,
                      legend.up_axis.c_str(), v);
      }
      readout = buf;
    }
  }
  return readout;
}

}  // namespace

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
  uploadXrayMap(state, *x, key);

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

  const float bar_h = drawXrayColourBar(*x, legend, map0, size);
  // The scale bar on its own line, under the axis label, so the two never run into each other.
  drawScaleBar(ImVec2(map0.x, map0.y + size.y + 2.0f + line), fit / float(x->voxel_size), state.model.frame().units,
               std::max(size.x * 0.5f, 60.0f));
  drawMapAxes(legend, map0, size);
  ImGui::Dummy(ImVec2(0.0f, std::max(0.0f, bar_h - size.y) + line * 1.5f));

  const std::string readout = hoverReadout(*x, legend, map0, size, fit, hovered);
  ImGui::TextUnformatted(readout.c_str());
}

}  // namespace vox::app
