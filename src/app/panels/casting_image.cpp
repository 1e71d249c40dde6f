// The section image while the Casting panel is open: the section (Section panel's axis and index) coloured by the
// field the panel shows (the metal still liquid at the front red), the hot spots it cuts ringed, a colour bar, and
// the value under the mouse.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/casting.h"
#include "app/update.h"  // currentSection
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/io/figure.h"

namespace vox::app {
namespace {

constexpr Rgb8 kLiquid{240, 30, 25};

// The section's pixels (row 0 at the top) into the texture when the run, field, front or section changed.
void uploadSection(AppState& state, const CastingOutcome& r, int32_t iw, int32_t ih) {
  CastingUi& ui = state.casting_ui;
  const double front = castingTimeShown(state, r);
  const std::vector<double> sig = {double(r.id),
                                   double(int(ui.field)),
                                   ui.field == CastingField::kTime ? front : 0.0,
                                   double(int(state.section.axis)),
                                   double(state.section.index),
                                   double(state.model_version)};
  if (sig == ui.image_sig && !ui.image_texture.empty()) return;
  const ImageAxes ax = imageAxes(state.section.axis);
  ImageRgb picture(iw, ih);
  for (int32_t v = 0; v < ih; ++v)
    for (int32_t u = 0; u < iw; ++u) {
      glm::ivec3 voxel(0);
      voxel[int(state.section.axis)] = state.section.index;
      voxel[ax.right] = u;
      voxel[ax.up] = ih - 1 - v;
      const uint8_t value = castingColourValue(r, ui.field, front, voxel);
      picture.at(u, v) =
          value == 0 ? io::kNoMaterialColour : (value == 1 ? kLiquid : io::rampColour(double(value - 2) / 253.0));
    }
  ui.image_texture.upload(picture);
  ui.image_sig = sig;
}

void colourBar(ImDrawList* dl, ImVec2 at, float height, double min, double max, const std::string& unit) {
  constexpr int kBands = 48;
  const float w = 18.0f;
  for (int i = 0; i < kBands; ++i) {
    const Rgb8 c = io::rampColour(1.0 - (i + 0.5) / kBands);
    const float y0 = at.y + height * float(i) / kBands, y1 = at.y + height * float(i + 1) / kBands;
    dl->AddRectFilled(ImVec2(at.x, y0), ImVec2(at.x + w, y1), IM_COL32(c.r, c.g, c.b, 255));
  }
  dl->AddRect(at, ImVec2(at.x + w, at.y + height), IM_COL32(90, 90, 90, 255));
  char text[64];
  std::snprintf(text, sizeof text, "%.4g %s", max, unit.c_str());
  dl->AddText(ImVec2(at.x + w + 6.0f, at.y), IM_COL32(230, 230, 230, 255), text);
  std::snprintf(text, sizeof text, "%.4g %s", min, unit.c_str());
  dl->AddText(ImVec2(at.x + w + 6.0f, at.y + height - ImGui::GetFontSize()), IM_COL32(230, 230, 230, 255), text);
}

}  // namespace

void drawCastingImage(AppState& state) {
  const CastingOutcome* r = currentCasting(state);
  if (!r) {
    ImGui::TextUnformatted("Simulate in the Casting panel to colour the section.");
    return;
  }
  currentSection(state);  // clamps the index to the model
  const Axis axis = state.section.axis;
  const ImageAxes ax = imageAxes(axis);
  const Dims d = state.model.dims();
  const int32_t dims[3] = {d.nx, d.ny, d.nz};
  const int32_t iw = dims[ax.right], ih = dims[ax.up];
  if (iw <= 0 || ih <= 0) return;
  uploadSection(state, *r, iw, ih);
  const CastingField field = state.casting_ui.field;
  const std::string units = state.model.frame().units;
  ImGui::Text("%s, section %s = %d (Section panel's slider)", castingFieldName(field), axisName(axis),
              state.section.index);
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  float scale =
      std::min(std::max(1.0f, avail.x - 160.0f) / float(iw), std::max(1.0f, avail.y - 3.0f * line) / float(ih));
  if (scale >= 1.0f) scale = std::floor(scale);
  scale = std::max(scale, 0.05f);
  const ImVec2 size(float(iw) * scale, float(ih) * scale);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Image(textureId(state.casting_ui.image_texture.id()), size);
  markWidget("casting_image");
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  colourBar(dl, ImVec2(origin.x + size.x + 14.0f, origin.y), std::max(size.y, 5.0f * line),
            field == CastingField::kTime ? r->first_solid_s : 0.0, castingFieldMax(*r, field),
            castingFieldUnit(field, units));
  ImGui::Dummy(ImVec2(0.0f, line));
  // the hot spots within two voxels of the section, ringed
  const GridFrame& frame = state.model.frame();
  const CastingHotSpot* chosen = selectedCastingSpot(state);
  for (const CastingHotSpot& s : r->run.result.hot_spots) {
    const glm::dvec3 v = (s.centre - frame.origin) / frame.voxel_size;
    if (std::abs(v[int(axis)] - (state.section.index + 0.5)) > 2.0) continue;
    const ImVec2 c(origin.x + float(v[ax.right]) * scale, origin.y + float(double(ih) - v[ax.up]) * scale);
    const ImU32 colour = s.in_feeder ? IM_COL32(110, 170, 255, 255)
                                     : (s.isolated ? IM_COL32(255, 80, 70, 255) : IM_COL32(255, 255, 255, 255));
    const float radius = &s == chosen ? 12.0f : 8.0f;
    dl->AddCircle(c, radius, IM_COL32(0, 0, 0, 255), 0, 4.0f);
    dl->AddCircle(c, radius, colour, 0, 2.0f);
  }
  if (!hovered) return;
  const ImVec2 m = ImGui::GetIO().MousePos;
  const int32_t u = std::clamp(int32_t((m.x - origin.x) / scale), 0, iw - 1);
  const int32_t row = std::clamp(int32_t((m.y - origin.y) / scale), 0, ih - 1);
  glm::ivec3 voxel(0);
  voxel[int(axis)] = state.section.index;
  voxel[ax.right] = u;
  voxel[ax.up] = ih - 1 - row;
  const ImVec2 cell(origin.x + float(u) * scale, origin.y + float(row) * scale);
  markCell(origin, ImVec2(origin.x + size.x, origin.y + size.y), cell, ImVec2(cell.x + scale, cell.y + scale));
  const float t = castingFieldAt(*r, CastingField::kTime, voxel);
  if (t <= 0.0f) {
    ImGui::SetTooltip("voxel (%d, %d, %d): empty", voxel.x, voxel.y, voxel.z);
    return;
  }
  ImGui::SetTooltip("voxel (%d, %d, %d): freezes at %.4g s, Niyama %.3g, modulus %s", voxel.x, voxel.y, voxel.z, t,
                    castingFieldAt(*r, CastingField::kNiyama, voxel),
                    formatLength(castingFieldAt(*r, CastingField::kModulus, voxel), units).c_str());
}

}  // namespace vox::app
