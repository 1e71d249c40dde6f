#pragma once
// Plain 2D images produced by analysis (sections, X-ray maps) and the renderer; row 0 is the top row.
#include <cstddef>
#include <cstdint>
#include <string>
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

// What a legend says about a map of non-negative integer values (0: no material on that ray), such as an X-ray:
// analysis writes the words (it knows what the values mean), the figure module draws them (io::drawScalarMapFigure)
// and the window shows them as its own text.
struct ScalarMapLegend {
  std::string title;                // e.g. "X-ray along z: max thickness per ray"
  std::string value_name;           // e.g. "voxels"
  double units_per_value = 1.0;     // model units per value (the voxel size)
  int32_t value_divisor = 1;        // the map holds values times this (10: tenths of a voxel); labels divide by it
  std::string units;                // e.g. "mm", "model units"
  std::string right_axis, up_axis;  // the grid axes along the image's columns and rows, e.g. "x", "y"
  std::vector<std::string> notes;   // statistics, one line each
};

}  // namespace vox
