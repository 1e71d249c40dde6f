// X-ray panel (thesis 5.2.3 and 6.5): thickness of material along rays parallel to an axis, per ray the thinnest
// run (min), the thickest run (max) or the sum of the runs (total); the picture comes from vox::renderXray with
// its colour bar and legend, and hovering it reads the thickness of one ray.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};

const XrayResult* currentXray(const AppState& state) {
  const XrayKey key{state.model_version, state.xray.params.axis, state.xray.params.mode};
  const auto* x = state.xray_result.get(key);
  return x ? x->get() : nullptr;
}

// Where renderXray put the thickness map inside its figure. The analysis module does not report its layout, so
// this finds the one-pixel frame (grey 120) that renderXray draws around a map of exactly map_w x map_h pixels,
// scanning from the top left (the map is left of the colour bar, whose frame has a different size). Returns false
// when no such frame exists; the hover read-out is then off.
bool findMapOrigin(const ImageRgb& img, int32_t map_w, int32_t map_h, int32_t& x_out, int32_t& y_out) {
  constexpr Rgb8 kFrame{120, 120, 120};
  for (int32_t y = 0; y + map_h + 1 < img.height; ++y) {
    for (int32_t x = 0; x + map_w + 1 < img.width; ++x) {
      if (img.at(x, y) == kFrame && img.at(x + 1, y) == kFrame && img.at(x, y + 1) == kFrame &&
          img.at(x + map_w + 1, y) == kFrame && img.at(x, y + map_h + 1) == kFrame &&
          img.at(x + map_w + 1, y + map_h + 1) == kFrame) {
        x_out = x + 1;
        y_out = y + 1;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

void drawXrayPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to X-ray it.");
    return;
  }
  XrayParams& p = state.xray.params;
  int axis = int(p.axis);
  ImGui::TextUnformatted("Rays along");
  for (int a = 0; a < 3; ++a) {
    ImGui::SameLine();
    const std::string label = std::string(1, char('X' + a)) + "##xray_axis";
    if (ImGui::RadioButton(label.c_str(), &axis, a)) p.axis = Axis(a);
  }
  int mode = int(p.mode);
  ImGui::RadioButton("Minimum", &mode, int(XrayMode::kMin));
  {
    const ImVec2 r0 = ImGui::GetItemRectMin(), r1 = ImGui::GetItemRectMax();
    state.widget_rects.push_back({"xray_min", r0.x, r0.y, r1.x, r1.y});
  }
  ImGui::SameLine();
  ImGui::RadioButton("Maximum", &mode, int(XrayMode::kMax));
  {
    const ImVec2 r0 = ImGui::GetItemRectMin(), r1 = ImGui::GetItemRectMax();
    state.widget_rects.push_back({"xray_max", r0.x, r0.y, r1.x, r1.y});
  }
  ImGui::SameLine();
  ImGui::RadioButton("Total", &mode, int(XrayMode::kTotal));
  {
    const ImVec2 r0 = ImGui::GetItemRectMin(), r1 = ImGui::GetItemRectMax();
    state.widget_rects.push_back({"xray_total", r0.x, r0.y, r1.x, r1.y});
  }
  p.mode = XrayMode(mode);
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

ImVec2 XrayFigure::sizeAt(int32_t scale) const {
  if (scale <= 1) return ImVec2(float(w1), float(h1));
  return ImVec2(float(w2 + (scale - 2) * map_width), float(h2 + (scale - 2) * map_height));
}

int32_t XrayFigure::bestScale(ImVec2 area) const {
  int32_t best = 1;
  for (int32_t s = 2; s <= 16; ++s) {
    const ImVec2 size = sizeAt(s);
    if (size.x > area.x || size.y > area.y) break;
    best = s;
  }
  return best;
}

XrayFigure xrayFigureSize(AppState& state) {
  const XrayResult* x = currentXray(state);
  if (!x) return {};
  const XrayKey key{state.model_version, x->axis, x->mode};
  int32_t* p = state.xray_probe_size;
  if (!(key == state.xray_probe_key) || p[0] == 0) {
    const ImageRgb one = renderXray(*x, 1), two = renderXray(*x, 2);
    state.xray_probe_key = key;
    p[0] = one.width;
    p[1] = one.height;
    p[2] = two.width;
    p[3] = two.height;
  }
  return {p[0], p[1], p[2], p[3], x->thickness.width, x->thickness.height};
}

void drawXrayImage(AppState& state) {
  const XrayResult* x = currentXray(state);
  if (!x) {
    ImGui::TextUnformatted("Computing the X-ray...");
    return;
  }
  const int32_t tw = x->thickness.width, th = x->thickness.height;
  const float readout_h = 2.0f * ImGui::GetTextLineHeightWithSpacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const XrayKey key{state.model_version, x->axis, x->mode};

  // The largest whole number of pixels per ray whose figure fits (whole numbers keep the rays equal squares and the
  // legend's pixel font sharp).
  const int32_t fit_scale = xrayFigureSize(state).bestScale(ImVec2(avail.x, avail.y - readout_h));
  if (!(key == state.xray_texture_key) || state.xray_texture.empty() || fit_scale != state.xray.image_scale) {
    state.xray.image_scale = fit_scale;
    const ImageRgb img = renderXray(*x, fit_scale);
    if (!findMapOrigin(img, tw * fit_scale, th * fit_scale, state.xray_map_x, state.xray_map_y)) {
      state.xray_map_x = state.xray_map_y = -1;
    }
    state.xray_texture.upload(img);
    state.xray_texture_key = key;
  }
  const Texture& tex = state.xray_texture;
  const float fit = std::min(1.0f, std::min(avail.x / float(tex.width()), (avail.y - readout_h) / float(tex.height())));
  const ImVec2 size(float(tex.width()) * fit, float(tex.height()) * fit);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Image(textureId(tex.id()), size);
  {
    const ImVec2 r0 = ImGui::GetItemRectMin(), r1 = ImGui::GetItemRectMax();
    state.widget_rects.push_back({"xray_image", r0.x, r0.y, r1.x, r1.y});
  }

  // Hover read-out: the ray under the mouse, in voxels and model units.
  std::string readout = "Hover the map to read the thickness of one ray.";
  if (ImGui::IsItemHovered() && state.xray_map_x >= 0) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const float px = (m.x - origin.x) / fit - float(state.xray_map_x);
    const float py = (m.y - origin.y) / fit - float(state.xray_map_y);
    const int32_t s = state.xray.image_scale;
    const int32_t u = int32_t(std::floor(px / float(s))), row = int32_t(std::floor(py / float(s)));
    if (u >= 0 && u < tw && row >= 0 && row < th) {
      static constexpr int kRight[] = {1, 0, 0}, kUp[] = {2, 2, 1};
      const int a = int(x->axis);
      const int32_t v = th - 1 - row;  // row 0 holds the largest "up" index
      const int32_t t = x->thickness.at(u, row);
      const ImVec2 map0(origin.x + float(state.xray_map_x) * fit, origin.y + float(state.xray_map_y) * fit);
      const float cell = float(s) * fit;
      const ImVec2 c0(map0.x + float(u) * cell, map0.y + float(row) * cell);
      markCell(map0, ImVec2(map0.x + float(tw) * cell, map0.y + float(th) * cell), c0,
               ImVec2(c0.x + cell, c0.y + cell));
      char buf[200];
      const std::string units = state.model.frame().units;
      if (t > 0) {
        std::snprintf(buf, sizeof buf, "Ray %s = %d, %s = %d: %s thickness %d voxels = %.4g %s", kAxisNames[kRight[a]],
                      u, kAxisNames[kUp[a]], v, xrayModeName(x->mode), t, double(t) * x->voxel_size,
                      units == "model" ? "model units" : units.c_str());
      } else {
        std::snprintf(buf, sizeof buf, "Ray %s = %d, %s = %d: no material", kAxisNames[kRight[a]], u,
                      kAxisNames[kUp[a]], v);
      }
      readout = buf;
    }
  }
  ImGui::TextUnformatted(readout.c_str());
}

}  // namespace vox::app
