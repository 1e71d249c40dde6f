#pragma once
// Plain 2D images produced by analysis (sections, X-ray maps) and the renderer; row 0 is the top row.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vox {

template <class T>
struct Image2D {
  int32_t width = 0;
  int32_t height = 0;
  std::vector<T> pixels;  // row-major, width * height

  Image2D() = default;
  Image2D(int32_t w, int32_t h, T fill = T{}) : width(w), height(h), pixels(size_t(w) * size_t(h), fill) {}
  T& at(int32_t x, int32_t y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const T& at(int32_t x, int32_t y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};
struct Rgba8 {
  uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba8&) const = default;
};

using ImageRgb = Image2D<Rgb8>;
using ImageRgba = Image2D<Rgba8>;

}  // namespace vox
