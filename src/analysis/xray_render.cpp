// Picture of an X-ray scan (thesis 6.5): the thickness map in a colour scale, with a colour bar whose ticks are
// labelled in voxels and in model units, the scan direction and mode as a title, the image axes, and the
// statistics over the rays that hit material. The thesis maps intensity proportionally to thickness; the scale
// here therefore starts at 0, so equal colours mean equal thickness across images of the same part.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/tiny_font.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

using analysis_detail::drawText;
using analysis_detail::kGlyphHeight;
using analysis_detail::textWidth;

constexpr Rgb8 kCanvas{255, 255, 255};
constexpr Rgb8 kNoMaterial{222, 222, 222};
constexpr Rgb8 kInk{20, 20, 20};
constexpr Rgb8 kFrame{120, 120, 120};

// Colour ramp from dark blue (thin) through teal and green to yellow (thick). Lightness rises monotonically, so the
// order survives greyscale printing and the common colour-vision deficiencies; the darkest colour still stands out
// from the light grey of rays without material.
Rgb8 rampColour(double t) {
  struct Stop {
    double t;
    double r, g, b;
  };
  static constexpr Stop kStops[] = {
      {0.00, 30, 20, 90}, {0.25, 35, 90, 165}, {0.50, 30, 155, 150}, {0.75, 140, 200, 70}, {1.00, 250, 230, 50},
  };
  t = std::clamp(t, 0.0, 1.0);
  size_t i = 0;
  while (i + 2 < std::size(kStops) && t > kStops[i + 1].t) ++i;
  const Stop& a = kStops[i];
  const Stop& b = kStops[i + 1];
  const double f = (t - a.t) / (b.t - a.t);
  auto mix = [&](double x, double y) { return uint8_t(std::lround(x + (y - x) * f)); };
  return Rgb8{mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

void fillRect(ImageRgb& img, int x0, int y0, int w, int h, Rgb8 c) {
  for (int y = std::max(0, y0); y < std::min(img.height, y0 + h); ++y) {
    for (int x = std::max(0, x0); x < std::min(img.width, x0 + w); ++x) img.at(x, y) = c;
  }
}

void frameRect(ImageRgb& img, int x0, int y0, int w, int h, Rgb8 c) {
  fillRect(img, x0 - 1, y0 - 1, w + 2, 1, c);
  fillRect(img, x0 - 1, y0 + h, w + 2, 1, c);
  fillRect(img, x0 - 1, y0, 1, h, c);
  fillRect(img, x0 + w, y0, 1, h, c);
}

// Tick values in voxels: multiples of a 1-2-5 step (at least 1 voxel) from 0, plus the maximum itself.
std::vector<int64_t> tickValues(int64_t max_value) {
  std::vector<int64_t> ticks;
  if (max_value <= 0) return {0};
  const double raw = double(max_value) / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(std::max(raw, 1.0))));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  const int64_t s = std::max<int64_t>(1, std::llround(step));
  for (int64_t v = 0; v < max_value; v += s) ticks.push_back(v);
  ticks.push_back(max_value);
  return ticks;
}

}  // namespace

ImageRgb renderXray(const XrayResult& xray, int32_t scale) {
  scale = std::max(1, scale);
  const Image2D<int32_t>& t = xray.thickness;
  const int map_w = t.width * scale, map_h = t.height * scale;
  const int ts = map_h >= 900 ? 3 : 2;  // legend text scale: 14 px letters, 21 px on very large maps
  const int glyph_h = kGlyphHeight * ts;
  const int line_h = glyph_h + 5 * ts;
  const int margin = 6 * ts;
  const double h = xray.voxel_size;
  const std::string units = upper(xray.units.empty() ? std::string("model") : xray.units);

  // Which grid axes the image shows (vox/analysis/analysis.h: X -> (y, z), Y -> (x, z), Z -> (x, y)).
  static constexpr const char* kRight[] = {"Y", "X", "X"};
  static constexpr const char* kUp[] = {"Z", "Z", "Y"};
  const int a = int(xray.axis);
  const std::string title =
      "X-RAY ALONG " + upper(axisName(xray.axis)) + ": " + upper(xrayModeName(xray.mode)) + " THICKNESS PER RAY";
  std::string stats1 = "NO RAY HITS MATERIAL";
  std::string stats2;
  if (xray.rays_hit > 0) {
    stats1 = "RAYS HIT " + std::to_string(xray.rays_hit) + "   MIN " + std::to_string(xray.min) + "  MAX " +
             std::to_string(xray.max) + "  MEAN " + fmt("%.2f", xray.mean) + " VOXELS";
    stats2 = "MIN " + fmt("%.4g", double(xray.min) * h) + "  MAX " + fmt("%.4g", double(xray.max) * h) + "  MEAN " +
             fmt("%.4g", xray.mean * h) + " " + units + "   (VOXEL " + fmt("%.4g", h) + " " + units + ")";
  }

  // Colour bar geometry: at least 60 text pixels tall so the tick labels never collide on small maps.
  const int bar_h = std::max(map_h, 60 * ts);
  const int bar_w = 10 * ts;
  const std::vector<int64_t> ticks = tickValues(xray.max);
  std::vector<std::string> vox_labels, unit_labels;
  int vox_col = textWidth("VOXELS", ts), unit_col = textWidth(units, ts);
  for (int64_t v : ticks) {
    vox_labels.push_back(std::to_string(v));
    unit_labels.push_back(fmt("%.4g", double(v) * h));
    vox_col = std::max(vox_col, textWidth(vox_labels.back(), ts));
    unit_col = std::max(unit_col, textWidth(unit_labels.back(), ts));
  }

  const int up_label_w = textWidth(kUp[a], ts) + 2 * ts;
  const int map_x = margin + up_label_w;
  const int map_y = margin + 2 * line_h;  // title line, then the legend's column headers
  const int bar_x = map_x + map_w + 4 * margin;
  const int label_x = bar_x + bar_w + 3 * ts + 2 * ts;
  const int unit_x = label_x + vox_col + 3 * margin;
  const int body_h = std::max(map_h, bar_h);
  const int text_y = map_y + body_h + ts * 3;
  const int width = std::max({unit_x + unit_col + margin, map_x + textWidth(stats1, ts) + margin,
                              map_x + textWidth(stats2, ts) + margin, margin + textWidth(title, ts) + margin});
  const int height = text_y + line_h * 3 + margin;
  ImageRgb img(width, height, kCanvas);

  drawText(img, margin, margin, title, kInk, ts);

  // The map: row 0 of the thickness image is its top row already.
  const double max_v = double(std::max<int64_t>(xray.max, 1));
  for (int32_t y = 0; y < t.height; ++y) {
    for (int32_t x = 0; x < t.width; ++x) {
      const int32_t v = t.at(x, y);
      const Rgb8 c = v > 0 ? rampColour(double(v) / max_v) : kNoMaterial;
      fillRect(img, map_x + x * scale, map_y + y * scale, scale, scale, c);
    }
  }
  frameRect(img, map_x, map_y, map_w, map_h, kFrame);
  // Image axes: the "up" axis beside the top-left corner, the "right" axis under the bottom-right corner.
  drawText(img, margin, map_y, "^", kInk, ts);
  drawText(img, margin, map_y + glyph_h + ts, kUp[a], kInk, ts);
  const std::string right_label = std::string(kRight[a]) + " >";
  drawText(img, map_x + map_w - textWidth(right_label, ts), map_y + map_h + 3 * ts, right_label, kInk, ts);

  // Colour bar, 0 at the bottom, the maximum at the top.
  for (int i = 0; i < bar_h; ++i) {
    const double f = bar_h > 1 ? double(bar_h - 1 - i) / double(bar_h - 1) : 1.0;
    fillRect(img, bar_x, map_y + i, bar_w, 1, xray.max > 0 ? rampColour(f) : kNoMaterial);
  }
  frameRect(img, bar_x, map_y, bar_w, bar_h, kFrame);
  drawText(img, label_x + vox_col - textWidth("VOXELS", ts), map_y - line_h, "VOXELS", kInk, ts);
  drawText(img, unit_x + unit_col - textWidth(units, ts), map_y - line_h, units, kInk, ts);
  int last_label_y = 0;
  for (size_t i = ticks.size(); i-- > 0;) {  // from the maximum down, so the maximum always gets its label
    const double f = xray.max > 0 ? double(ticks[i]) / double(xray.max) : 0.0;
    const int ty = map_y + int(std::lround((1.0 - f) * double(bar_h - 1)));
    const int label_y = std::clamp(ty - glyph_h / 2, map_y - ts, map_y + bar_h - glyph_h + ts);
    const bool top = i + 1 == ticks.size();
    if (!top && label_y < last_label_y + glyph_h + 2 * ts) continue;  // would overlap the label above
    fillRect(img, bar_x + bar_w, ty, 3 * ts, std::max(1, ts / 2), kInk);
    drawText(img, label_x + vox_col - textWidth(vox_labels[i], ts), label_y, vox_labels[i], kInk, ts);
    drawText(img, unit_x + unit_col - textWidth(unit_labels[i], ts), label_y, unit_labels[i], kInk, ts);
    last_label_y = label_y;
  }

  drawText(img, map_x, text_y + line_h, stats1, kInk, ts);
  if (!stats2.empty()) drawText(img, map_x, text_y + 2 * line_h, stats2, kInk, ts);
  return img;
}

}  // namespace vox
