#include "app/thickness_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "app/casting_view.h"  // shownCasting
#include "app/print_view.h"
#include "app/thickness.h"
#include "app/ui.h"
#include "app/view_overlays.h"
#include "vox/io/figure.h"

namespace vox::app {
namespace {

constexpr ImU32 kThinColour = IM_COL32(242, 31, 26, 255);  // points.vert's red for walls under the minimum
constexpr ImU32 kThinTextColour = IM_COL32(255, 120, 110, 255);
constexpr ImU32 kHotSpotColour = IM_COL32(255, 60, 220, 255);
constexpr int kMostHotSpotsShown = 20;
// The colour scale's place at the view's top: from kLegendTop pixels down (under the view's buttons), its title, strip
// and labels taking kLegendLines text lines.
constexpr float kLegendTop = 30.0f;
constexpr float kLegendLines = 4.0f;

// The thickness of the voxel under the mouse, as a line of text at the view's bottom left, and a ring on it.
void hoverReadout(const AppState& state, const ThicknessResult& r, ImDrawList* dl, ImVec2 pos, int w, int h,
                  double aspect) {
  const ImVec2 m = ImGui::GetIO().MousePos;
  if (!ImGui::IsWindowHovered() || m.x < pos.x || m.y < pos.y || m.x >= pos.x + float(w) || m.y >= pos.y + float(h))
    return;
  const glm::dmat4 vp = state.view.camera.viewProjection(aspect, *state.model_bounds);
  const glm::dmat4 inv = glm::inverse(vp);
  const double nx = 2.0 * double(m.x - pos.x) / double(w) - 1.0, ny = 1.0 - 2.0 * double(m.y - pos.y) / double(h);
  const auto unproject = [&](double z) {
    const glm::dvec4 p = inv * glm::dvec4(nx, ny, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  const auto v = pickVoxel(state.model, unproject(-1.0), unproject(1.0));
  if (!v) return;
  const std::string units = state.model.frame().units;
  char line[160];
  const RayThicknessResult* ray = shownRay(state, r);
  const double t = shownThickness(state, r, *v);
  std::snprintf(line, sizeof line, "%s %s at voxel (%d, %d, %d)", ray ? "Ray thickness" : "Thickness",
                ray && t <= 0.0 ? "(no wall facing back)" : formatLength(t, units).c_str(), v->x, v->y, v->z);
  const float lh = ImGui::GetTextLineHeightWithSpacing();
  shadowText(dl, ImVec2(pos.x + 8.0f, pos.y + float(h) - 2.0f * lh - 6.0f), IM_COL32(255, 255, 255, 255), line);
  ImVec2 c;
  if (projectToView(vp, glm::dvec3(*v) + 0.5, pos, w, h, c))
    dl->AddCircle(c, 5.0f, IM_COL32(255, 255, 255, 255), 0, 1.5f);
}

// Local thickness: 1..255 for 0..max; thinner than the minimum wall but in no wall (an edge): 0, the model's colour.
void sphereVolume(const DistanceField& f, double max_voxels, double thin_squared, const Walls* walls,
                  std::vector<uint8_t>& values) {
  for (size_t i = 0; i < values.size(); ++i) {
    const uint32_t sq = f.data()[i];
    if (sq == 0) continue;
    if (double(sq) < thin_squared && !(walls->mask[i >> 6] >> (i & 63) & 1)) continue;
    const double t = max_voxels > 0.0 ? 2.0 * std::sqrt(double(sq)) / max_voxels : 0.0;
    values[i] = uint8_t(1 + std::lround(254.0 * std::clamp(t, 0.0, 1.0)));
  }
}

// The ray thickness over the local thickness's box, on the same scale (0 .. the thickest ball; longer rays at its top).
void rayVolume(const RayThicknessResult& ray, const DistanceField& f, double max, std::vector<uint8_t>& values) {
  const glm::ivec3 b = f.boxMin();
  const Dims& d = f.boxDims();
  size_t i = 0;
  for (int32_t z = 0; z < d.nz; ++z)
    for (int32_t y = 0; y < d.ny; ++y)
      for (int32_t x = 0; x < d.nx; ++x, ++i) {
        const double t = ray.field.at(b.x + x, b.y + y, b.z + z);
        if (t > 0.0) values[i] = uint8_t(1 + std::lround(254.0 * std::clamp(max > 0.0 ? t / max : 0.0, 0.0, 1.0)));
      }
}

}  // namespace

float thicknessLegendHeight(const AppState& state) {
  if (state.panel != Panel::kThickness || state.model.empty()) return 0.0f;
  return kLegendTop + kLegendLines * ImGui::GetTextLineHeightWithSpacing();
}

const ThicknessResult* shownThickness(const AppState& state) {
  return state.panel == Panel::kThickness && !state.model.empty() ? currentThickness(state) : nullptr;
}

ImU32 thicknessColour(double thickness, double max, double min_wall) {
  if (thickness < min_wall) return kThinColour;
  const Rgb8 c = io::rampColour(max > 0.0 ? thickness / max : 0.0);
  return IM_COL32(c.r, c.g, c.b, 255);
}

void syncThicknessVolume(AppState& state) {
  ThicknessUi& ui = state.thickness_ui;
  const ThicknessResult* r = shownThickness(state);
  const uint64_t key = r ? r->id : 0;
  const Walls* walls = r ? currentThinWalls(state) : nullptr;
  const double wall = walls ? walls->min_wall : -1.0;
  const RayThicknessResult* ray = r ? shownRay(state, *r) : nullptr;
  if ((key == ui.volume_key && wall == ui.volume_min_wall && (ray != nullptr) == ui.volume_ray) ||
      !state.viewport.renderer)
    return;
  ui.volume_key = key;
  ui.volume_min_wall = wall;
  ui.volume_ray = ray != nullptr;
  state.viewport.dirty = true;
  ui.volume_problem.clear();
  if (!r) {
    // the Print panel's overhangs and the Casting panel's colours are theirs
    if (!shownPrint(state) && !shownCasting(state)) state.viewport.renderer->clearScalarVolume();
    return;
  }
  // 0: no value (empty, or thinner than the minimum wall but in no wall: an edge, in the model's colour);
  // 1..255: thickness 0..max (the radius field holds R^2 in voxels^2; thickness = 2R).
  const DistanceField& f = r->thickness.radius;
  const double max_voxels = r->thickness.stats.max / f.voxelSize();
  const double thin_squared = wall > 0.0 ? std::pow(wall / (2.0 * f.voxelSize()), 2.0) : 0.0;
  std::vector<uint8_t> values(size_t(f.boxDims().count()), 0);
  if (ray) {
    rayVolume(*ray, f, r->thickness.stats.max, values);
  } else {
    sphereVolume(f, max_voxels, thin_squared, walls, values);
  }
  if (Status s = state.viewport.renderer->setScalarVolume(f.boxMin(), f.boxDims(), values); !s) {
    ui.volume_problem = "The 3D view is not coloured by thickness: " + s.error().message + ".";
  }
}

void thicknessDrawParams(const AppState& state, render::DrawParams& p) {
  const ThicknessResult* r = shownThickness(state);
  if (!r || !state.viewport.renderer || !state.viewport.renderer->hasScalarVolume()) return;
  p.scalar_colour = true;
  const double max = r->thickness.stats.max;
  p.scalar_threshold = max > 0.0 ? float(minWall(state) / max) : 0.0f;
}

float drawThicknessBar(ImDrawList* dl, ImVec2 at, float height, double max, double min_wall, const std::string& units) {
  constexpr float kBarW = 16.0f;
  constexpr int kBands = 48;
  for (int i = 0; i < kBands; ++i) {  // from the top (max) down
    const double t0 = max * (1.0 - double(i) / kBands), t1 = max * (1.0 - double(i + 1) / kBands);
    const float y0 = at.y + height * float(i) / kBands, y1 = at.y + height * float(i + 1) / kBands;
    const ImU32 c0 = thicknessColour(t0, max, min_wall), c1 = thicknessColour(t1, max, min_wall);
    dl->AddRectFilledMultiColor(ImVec2(at.x, y0), ImVec2(at.x + kBarW, y1), c0, c0, c1, c1);
  }
  dl->AddRect(ImVec2(at.x - 1.0f, at.y - 1.0f), ImVec2(at.x + kBarW + 1.0f, at.y + height + 1.0f),
              IM_COL32(160, 160, 160, 255));
  const float th = ImGui::GetTextLineHeight();
  const ImU32 ink = IM_COL32(230, 230, 230, 255);
  const std::string top = formatLength(max, units), bottom = formatLength(0.0, units);
  const float lx = at.x + kBarW + 6.0f;
  shadowText(dl, ImVec2(lx, at.y - th * 0.5f), ink, top.c_str());
  shadowText(dl, ImVec2(lx, at.y + height - th * 0.5f), ink, bottom.c_str());
  float width = std::max(ImGui::CalcTextSize(top.c_str()).x, ImGui::CalcTextSize(bottom.c_str()).x);
  if (max > 0.0 && min_wall > 0.0 && min_wall < max) {
    const float y = at.y + height * float(1.0 - min_wall / max);
    dl->AddLine(ImVec2(at.x - 4.0f, y), ImVec2(at.x + kBarW + 4.0f, y), ink, 1.5f);
    const std::string label = "min wall " + formatLength(min_wall, units);
    // Kept clear of the labels at the ends.
    const float ly = std::clamp(y - th * 0.5f, at.y + th * 1.2f, at.y + height - th * 2.2f);
    shadowText(dl, ImVec2(lx, ly), kThinTextColour, label.c_str());
    width = std::max(width, ImGui::CalcTextSize(label.c_str()).x);
  }
  return kBarW + 6.0f + width;
}

// The same ramp lying along the top of the 3D view (the model fills the view's middle): 0 at the left, the maximum
// at the right, the minimum wall marked.
void drawThicknessStrip(ImDrawList* dl, ImVec2 at, float width, double max, double min_wall, const std::string& units) {
  constexpr float kStripH = 12.0f;
  constexpr int kBands = 48;
  for (int i = 0; i < kBands; ++i) {
    const double t0 = max * double(i) / kBands, t1 = max * double(i + 1) / kBands;
    const float x0 = at.x + width * float(i) / kBands, x1 = at.x + width * float(i + 1) / kBands;
    const ImU32 c0 = thicknessColour(t0, max, min_wall), c1 = thicknessColour(t1, max, min_wall);
    dl->AddRectFilledMultiColor(ImVec2(x0, at.y), ImVec2(x1, at.y + kStripH), c0, c1, c1, c0);
  }
  dl->AddRect(ImVec2(at.x - 1.0f, at.y - 1.0f), ImVec2(at.x + width + 1.0f, at.y + kStripH + 1.0f),
              IM_COL32(160, 160, 160, 255));
  const ImU32 ink = IM_COL32(230, 230, 230, 255);
  const float ly = at.y + kStripH + 3.0f;
  const std::string top = formatLength(max, units);
  shadowText(dl, ImVec2(at.x, ly), ink, "0");
  shadowText(dl, ImVec2(at.x + width - ImGui::CalcTextSize(top.c_str()).x, ly), ink, top.c_str());
  if (max > 0.0 && min_wall > 0.0 && min_wall < max) {
    const float x = at.x + width * float(min_wall / max);
    dl->AddLine(ImVec2(x, at.y - 3.0f), ImVec2(x, at.y + kStripH + 3.0f), ink, 1.5f);
    const std::string label = "min wall " + formatLength(min_wall, units);
    const float lw = ImGui::CalcTextSize(label.c_str()).x;
    const float lx = std::clamp(x - lw * 0.5f, at.x, at.x + width - lw);
    shadowText(dl, ImVec2(lx, ly + ImGui::GetTextLineHeight()), kThinTextColour, label.c_str());
  }
}

float drawThicknessOverlay(AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect) {
  if (state.panel != Panel::kThickness || state.model.empty() || !state.model_bounds) return pos.y;
  const ThicknessResult* r = shownThickness(state);
  const float lh = ImGui::GetTextLineHeightWithSpacing();
  if (!r) {
    const bool cancelled = state.thickness_ui.cancelled_version == state.model_version;
    shadowText(dl, ImVec2(pos.x + 8.0f, pos.y + 8.0f), IM_COL32(230, 230, 230, 255),
               cancelled ? "Thickness cancelled (Compute thickness in the panel)" : "Computing thickness...");
    return pos.y + 8.0f + lh;
  }
  const std::string units = state.model.frame().units;
  const glm::dmat4 vp = state.view.camera.viewProjection(aspect, *state.model_bounds);
  // The colour scale along the top, under the view's buttons, with the hot spots' ring explained beside its title;
  // drawn first, so that the rings and marks go over it, never under.
  const float strip_w = std::clamp(float(w) - 24.0f, 60.0f, 300.0f);
  const float y0 = pos.y + kLegendTop;
  // the legend names the method shown
  const char* title = shownRay(state, *r) ? "Thickness by rays" : "Thickness by spheres";
  shadowText(dl, ImVec2(pos.x + 12.0f, y0), IM_COL32(230, 230, 230, 255), title);
  const float ring_x = pos.x + 12.0f + ImGui::CalcTextSize(title).x + 24.0f;
  dl->AddCircle(ImVec2(ring_x, y0 + lh * 0.45f), 6.0f, kHotSpotColour, 0, 2.0f);
  shadowText(dl, ImVec2(ring_x + 10.0f, y0), kHotSpotColour, "hot spot");
  drawThicknessStrip(dl, ImVec2(pos.x + 12.0f, y0 + lh + 2.0f), strip_w, r->thickness.stats.max, minWall(state), units);
  float bottom = y0 + kLegendLines * lh;  // under the strip's labels (two lines when the minimum wall is marked)
  if (!state.thickness_ui.volume_problem.empty()) {
    shadowText(dl, ImVec2(pos.x + 12.0f, bottom), IM_COL32(255, 200, 80, 255),
               state.thickness_ui.volume_problem.c_str());
    bottom += lh;
  }
  // Hot spots: rings at their centres, numbered as in the panel's list (the largest first).
  for (size_t i = 0; i < r->hot_spots.size() && int(i) < kMostHotSpotsShown; ++i) {
    ImVec2 c;
    if (!projectToView(vp, glm::dvec3(r->hot_spots[i].voxel) + 0.5, pos, w, h, c)) continue;
    dl->AddCircle(c, 8.0f, IM_COL32(0, 0, 0, 255), 0, 4.0f);
    dl->AddCircle(c, 8.0f, kHotSpotColour, 0, 2.0f);
    shadowText(dl, ImVec2(c.x + 10.0f, c.y - 18.0f), kHotSpotColour, std::to_string(i + 1).c_str());
  }
  // The place clicked in the panel's lists: a white ring about the hot spot, the box of the thin-wall region.
  constexpr ImU32 kMarkColour = IM_COL32(255, 255, 255, 255);
  if (const HotSpot* spot = selectedHotSpot(state)) {
    ImVec2 c;
    if (projectToView(vp, glm::dvec3(spot->voxel) + 0.5, pos, w, h, c)) {
      dl->AddCircle(c, 14.0f, IM_COL32(0, 0, 0, 255), 0, 4.0f);
      dl->AddCircle(c, 14.0f, kMarkColour, 0, 2.0f);
    }
  }
  if (const ThinWallRegion* region = selectedRegion(state)) {
    const glm::dvec3 lo(region->bbox_min_ijk), hi(glm::dvec3(region->bbox_max_ijk) + 1.0);
    ImVec2 corner[8];
    bool seen = true;
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 p(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
      seen = seen && projectToView(vp, p, pos, w, h, corner[k]);
    }
    for (const auto& [colour, width] : {std::pair(IM_COL32(0, 0, 0, 255), 4.0f), std::pair(kMarkColour, 2.0f)}) {
      if (!seen) break;
      for (int k = 0; k < 8; ++k)
        for (const int bit : {1, 2, 4})
          if (!(k & bit)) dl->AddLine(corner[k], corner[k | bit], colour, width);  // each edge from its lower corner
    }
  }
  hoverReadout(state, *r, dl, pos, w, h, aspect);
  return bottom;
}

namespace {

void drawLegendOnImage(AppState& state, const ThicknessResult* r, ImageRgb& image) {
  const int ts = std::max(1, image.height / 400);  // text scale: about 1/50 of the picture's height
  const int line = io::textLineHeight(ts) + 2 * ts, x0 = 12 * ts;
  const auto rgb = [](ImU32 c) { return Rgb8{uint8_t(c & 0xff), uint8_t((c >> 8) & 0xff), uint8_t((c >> 16) & 0xff)}; };
  const Rgb8 ink{235, 235, 235}, shadow{0, 0, 0}, ring = rgb(kHotSpotColour);
  const auto text = [&](int x, int y, const std::string& s, Rgb8 c) {
    io::drawText(image, x + ts, y + ts, s, shadow, ts);
    io::drawText(image, x, y, s, c, ts);
  };
  const std::string units = state.model.frame().units;
  const double max = r->thickness.stats.max, wall = minWall(state);
  int y = 10 * ts;
  text(x0, y, shownRay(state, *r) ? "Thickness by rays" : "Thickness by spheres", ink);
  y += line;
  const int strip_w = std::min(300 * ts, image.width - 2 * x0), strip_h = 6 * ts;
  for (int i = 0; i < strip_w; ++i) {
    const Rgb8 c = rgb(thicknessColour(max * (double(i) + 0.5) / double(std::max(strip_w, 1)), max, wall));
    for (int j = 0; j < strip_h; ++j)
      if (x0 + i < image.width && y + j < image.height) image.at(x0 + i, y + j) = c;
  }
  y += strip_h + 2 * ts;
  text(x0, y, "0", ink);
  const std::string top = formatLength(max, units);
  text(x0 + strip_w - io::textWidth(top, ts), y, top, ink);
  if (wall > 0.0 && wall < max) text(x0, y + line, "min wall " + formatLength(wall, units), rgb(kThinTextColour));
  // the hot spots where the view shows them, numbered as in the panel's list
  const double aspect = double(image.width) / double(image.height);
  const glm::dmat4 vp = state.view.camera.viewProjection(aspect, *state.model_bounds);
  for (size_t i = 0; i < r->hot_spots.size() && int(i) < kMostHotSpotsShown; ++i) {
    ImVec2 c;
    if (!projectToView(vp, glm::dvec3(r->hot_spots[i].voxel) + 0.5, ImVec2(0, 0), image.width, image.height, c))
      continue;
    io::drawRing(image, c.x, c.y, 8.0 * ts, 4.0 * ts, shadow);
    io::drawRing(image, c.x, c.y, 8.0 * ts, 2.0 * ts, ring);
    text(int(c.x) + 10 * ts, int(c.y) - 18 * ts, std::to_string(i + 1), ring);
  }
}

}  // namespace

void drawThicknessLegendOnImage(AppState& state, ImageRgba& image) {
  const ThicknessResult* r = shownThickness(state);
  if (!r || !state.model_bounds || image.width < 1 || image.height < 1) return;
  ImageRgb rgb(image.width, image.height);
  for (int32_t y = 0; y < image.height; ++y)
    for (int32_t x = 0; x < image.width; ++x) rgb.at(x, y) = Rgb8{image.at(x, y).r, image.at(x, y).g, image.at(x, y).b};
  drawLegendOnImage(state, r, rgb);
  for (int32_t y = 0; y < image.height; ++y)
    for (int32_t x = 0; x < image.width; ++x)
      image.at(x, y) = Rgba8{rgb.at(x, y).r, rgb.at(x, y).g, rgb.at(x, y).b, 255};
}

}  // namespace vox::app
