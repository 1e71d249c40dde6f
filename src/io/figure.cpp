// Annotated figures (vox/io/figure.h). The text comes from stb_easy_font (public domain, Debian's libstb): each glyph
// is a handful of axis-aligned quads, which are filled here as rectangles of scale x scale pixels per font pixel.
#include "vox/io/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

// stb_easy_font is a header of static functions; we use three of them, and it takes text as char*.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wconversion"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace vox::io {
namespace {

constexpr Rgb8 kCanvas{255, 255, 255};
constexpr Rgb8 kInk{20, 20, 20};
constexpr Rgb8 kFrame{120, 120, 120};
constexpr int kCapHeight = 7;  // stb_easy_font's capital letters and digits, in font pixels

void fillRect(ImageRgb& img, int x0, int y0, int w, int h, Rgb8 c) {
  for (int y = std::max(0, y0); y < std::min(img.height, y0 + h); ++y) {
    for (int x = std::max(0, x0); x < std::min(img.width, x0 + w); ++x) img.at(x, y) = c;
  }
}

void frameRect(ImageRgb& img, const PixelRect& r, Rgb8 c) {
  fillRect(img, r.x - 1, r.y - 1, r.width + 2, 1, c);
  fillRect(img, r.x - 1, r.y + r.height, r.width + 2, 1, c);
  fillRect(img, r.x - 1, r.y, 1, r.height, c);
  fillRect(img, r.x + r.width, r.y, 1, r.height, c);
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

Rgb8 rampColour(double t) {
  struct Stop {
    double t;
    double r, g, b;
  };
  static constexpr Stop kStops[] = {
      {0.00, 30, 20, 90}, {0.25, 35, 90, 165}, {0.50, 30, 155, 150}, {0.75, 140, 200, 70}, {1.00, 250, 230, 50},
  };
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  size_t i = 0;
  while (i + 2 < std::size(kStops) && t > kStops[i + 1].t) ++i;
  const Stop& a = kStops[i];
  const Stop& b = kStops[i + 1];
  const double f = (t - a.t) / (b.t - a.t);
  auto mix = [&](double x, double y) { return uint8_t(std::lround(x + (y - x) * f)); };
  return Rgb8{mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

std::vector<int64_t> colourBarTicks(int64_t max_value) {
  if (max_value <= 0) return {0};
  const double raw = double(max_value) / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(std::max(raw, 1.0))));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  const int64_t s = std::max<int64_t>(1, std::llround(step));
  std::vector<int64_t> ticks;
  for (int64_t v = 0; v < max_value; v += s) ticks.push_back(v);
  ticks.push_back(max_value);
  return ticks;
}

int textWidth(std::string_view text, int scale) {
  std::string s(text);
  return stb_easy_font_width(s.data()) * scale;
}

int textLineHeight(int scale) { return 12 * scale; }

void drawText(ImageRgb& image, int x, int y, std::string_view text, Rgb8 colour, int scale) {
  // About 270 bytes of quads per character (the header's estimate); drawn a chunk of text at a time.
  constexpr size_t kChunk = 64;
  alignas(16) static thread_local float quads[kChunk * 300 / sizeof(float)];
  float pen = 0.0f;
  for (size_t start = 0; start < text.size(); start += kChunk) {
    std::string part(text.substr(start, kChunk));
    const int n = stb_easy_font_print(pen, 0.0f, part.data(), nullptr, quads, int(sizeof quads));
    for (int q = 0; q < n; ++q) {
      const float* v = quads + size_t(q) * 16;  // four vertices of x, y, z, colour (4 floats' worth each)
      const float x0 = std::min(v[0], v[8]), x1 = std::max(v[0], v[8]);
      const float y0 = std::min(v[1], v[9]), y1 = std::max(v[1], v[9]);
      fillRect(image, x + int(std::lround(x0 * float(scale))), y + int(std::lround(y0 * float(scale))),
               int(std::lround((x1 - x0) * float(scale))), int(std::lround((y1 - y0) * float(scale))), colour);
    }
    pen += float(stb_easy_font_width(part.data()));
  }
}

void drawRing(ImageRgb& image, double cx, double cy, double r, double width, Rgb8 colour) {
  const double outer = r + 0.5 * width, inner = std::max(0.0, r - 0.5 * width);
  const int x0 = std::max(0, int(std::floor(cx - outer))), x1 = std::min(image.width - 1, int(std::ceil(cx + outer)));
  const int y0 = std::max(0, int(std::floor(cy - outer))), y1 = std::min(image.height - 1, int(std::ceil(cy + outer)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      if (d >= inner && d <= outer) image.at(x, y) = colour;
    }
  }
}

ScalarMapFigure drawScalarMapFigure(const Image2D<int32_t>& values, int64_t max_value, const ScalarMapLegend& legend,
                                    int32_t scale) {
  ScalarMapFigure fig;
  scale = std::max(1, scale);
  fig.scale = scale;
  const int map_w = values.width * scale, map_h = values.height * scale;
  const int ts = std::max(2, int(std::ceil(double(std::max(map_w, map_h)) / (60.0 * kCapHeight))));
  fig.text_scale = ts;
  const int cap_h = kCapHeight * ts;
  const int line_h = textLineHeight(ts) + 2 * ts;
  const int margin = 6 * ts;
  const std::string& units = legend.units;

  // Colour bar: at least 60 text pixels tall, so that tick labels never collide on small maps.
  const int bar_h = std::max(map_h, 60 * ts);
  const int bar_w = 10 * ts;
  const std::vector<int64_t> ticks = colourBarTicks(max_value);
  std::vector<std::string> value_labels, unit_labels;
  int value_col = textWidth(legend.value_name, ts), unit_col = textWidth(units, ts);
  const int64_t divisor = std::max<int64_t>(legend.value_divisor, 1);
  for (int64_t v : ticks) {
    value_labels.push_back(divisor == 1 ? std::to_string(v) : fmt("%.4g", double(v) / double(divisor)));
    unit_labels.push_back(fmt("%.4g", double(v) / double(divisor) * legend.units_per_value));
    value_col = std::max(value_col, textWidth(value_labels.back(), ts));
    unit_col = std::max(unit_col, textWidth(unit_labels.back(), ts));
  }

  const int up_label_w = std::max(textWidth(legend.up_axis, ts), textWidth("^", ts)) + 2 * ts;
  fig.map = {margin + up_label_w, margin + 2 * line_h, map_w, map_h};  // below the title and the column headers
  fig.bar = {fig.map.x + map_w + 4 * margin, fig.map.y, bar_w, bar_h};
  const int label_x = fig.bar.x + bar_w + 5 * ts;
  const int unit_x = label_x + value_col + 3 * margin;
  const int text_y = fig.map.y + std::max(map_h, bar_h) + line_h;
  int width = std::max(unit_x + unit_col + margin, margin + textWidth(legend.title, ts) + margin);
  for (const std::string& note : legend.notes) width = std::max(width, fig.map.x + textWidth(note, ts) + margin);
  const int height = text_y + line_h * int(legend.notes.size()) + margin;
  ImageRgb& img = fig.image;
  img = ImageRgb(width, height, kCanvas);

  drawText(img, margin, margin, legend.title, kInk, ts);
  const double top = double(std::max<int64_t>(max_value, 1));
  for (int32_t y = 0; y < values.height; ++y) {
    for (int32_t x = 0; x < values.width; ++x) {
      const int32_t v = values.at(x, y);
      fillRect(img, fig.map.x + x * scale, fig.map.y + y * scale, scale, scale,
               v > 0 ? rampColour(double(v) / top) : kNoMaterialColour);
    }
  }
  frameRect(img, fig.map, kFrame);
  // Image axes: the "up" axis beside the top-left corner, the "right" axis under the bottom-right corner.
  drawText(img, margin, fig.map.y, "^", kInk, ts);
  drawText(img, margin, fig.map.y + cap_h + 2 * ts, legend.up_axis, kInk, ts);
  const std::string right_label = legend.right_axis + " >";
  drawText(img, fig.map.x + map_w - textWidth(right_label, ts), fig.map.y + map_h + 3 * ts, right_label, kInk, ts);

  for (int i = 0; i < bar_h; ++i) {
    const double f = bar_h > 1 ? double(bar_h - 1 - i) / double(bar_h - 1) : 1.0;
    fillRect(img, fig.bar.x, fig.bar.y + i, bar_w, 1, max_value > 0 ? rampColour(f) : kNoMaterialColour);
  }
  frameRect(img, fig.bar, kFrame);
  drawText(img, label_x + value_col - textWidth(legend.value_name, ts), fig.map.y - line_h, legend.value_name, kInk,
           ts);
  drawText(img, unit_x + unit_col - textWidth(units, ts), fig.map.y - line_h, units, kInk, ts);
  int last_label_y = 0;
  for (size_t i = ticks.size(); i-- > 0;) {  // from the maximum down, so the maximum always gets its label
    const double f = max_value > 0 ? double(ticks[i]) / double(max_value) : 0.0;
    const int ty = fig.bar.y + int(std::lround((1.0 - f) * double(bar_h - 1)));
    const int label_y = std::clamp(ty - cap_h / 2, fig.bar.y - ts, fig.bar.y + bar_h - cap_h + ts);
    const bool top_tick = i + 1 == ticks.size();
    if (!top_tick && label_y < last_label_y + cap_h + 3 * ts) continue;  // would overlap the label above
    fillRect(img, fig.bar.x + bar_w, ty, 3 * ts, std::max(1, ts / 2), kInk);
    drawText(img, label_x + value_col - textWidth(value_labels[i], ts), label_y, value_labels[i], kInk, ts);
    drawText(img, unit_x + unit_col - textWidth(unit_labels[i], ts), label_y, unit_labels[i], kInk, ts);
    last_label_y = label_y;
  }
  for (size_t i = 0; i < legend.notes.size(); ++i) {
    drawText(img, fig.map.x, text_y + line_h * int(i), legend.notes[i], kInk, ts);
  }
  return fig;
}

ImageRgb sectionPicture(const Image2D<uint8_t>& m, int32_t scale) {
  scale = std::max(1, scale);
  ImageRgb img(m.width * scale, m.height * scale);
  // Steel blue material, a darker outline so thin walls stay visible, light grey empty space: readable in print
  // and for the common forms of colour blindness (the outline differs in lightness, not only in hue).
  constexpr Rgb8 kMaterial{70, 130, 180};
  constexpr Rgb8 kOutline{20, 45, 85};
  constexpr Rgb8 kEmpty{232, 232, 232};
  auto filled = [&](int32_t x, int32_t y) {
    return x >= 0 && y >= 0 && x < m.width && y < m.height && m.at(x, y) != 0;
  };
  for (int32_t y = 0; y < m.height; ++y) {
    for (int32_t x = 0; x < m.width; ++x) {
      Rgb8 c = kEmpty;
      if (filled(x, y)) {
        const bool outline = !filled(x - 1, y) || !filled(x + 1, y) || !filled(x, y - 1) || !filled(x, y + 1);
        c = outline ? kOutline : kMaterial;
      }
      for (int32_t dy = 0; dy < scale; ++dy) {
        Rgb8* out = &img.at(x * scale, y * scale + dy);
        std::fill(out, out + scale, c);
      }
    }
  }
  return img;
}

}  // namespace vox::io
