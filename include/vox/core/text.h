#pragma once
// Small helpers shared by the modules, kept in one place: byte sizes, grid dimensions and numbers for messages and
// their parsing, the machine's memory (for the limits the voxelizer, the file readers and the window enforce), and
// a clock for timings.
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "vox/core/voxel_grid.h"

namespace vox {

// "512 B", "3.5 KiB", "94.2 MiB", "1.29 GiB".
std::string formatBytes(uint64_t bytes);
// "1243 x 2110 x 4096".
std::string dimsText(const Dims& dims);
// A coordinate on a lattice of `voxel_size` with its units, in fixed notation one decimal finer than the voxel:
// "0.000 mm", "78.1 model units" (never "4.4e-05 mm").
std::string formatCoordinate(double value, const std::string& units, double voxel_size);
// Physical memory of this machine in bytes (0 if unknown).
uint64_t physicalMemoryBytes();
// The memory a large piece of work may plan for unless told otherwise: 80% of physical memory (no limit if unknown).
uint64_t defaultMemoryLimitBytes();
// Seconds since an arbitrary start (the steady clock): for timing work.
double nowSeconds();

// "1 region", "3 regions": a count with its noun, plural unless the count is one.
inline std::string countOf(int64_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

// The whole of `text` as a number (std::from_chars: no locale, no leading '+' or spaces); `out` is left as it was
// when the text is not exactly one number.
template <class T>
bool parseNumber(std::string_view text, T& out) {
  T v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return false;
  out = v;
  return true;
}

// As parseNumber, as file formats write numbers: a leading '+' is taken, and a floating-point value must be finite.
template <class T>
bool parseFileNumber(std::string_view text, T& out) {
  if (text.size() > 1 && text[0] == '+') text.remove_prefix(1);
  T v{};
  if (!parseNumber(text, v)) return false;
  if constexpr (std::is_floating_point_v<T>) {
    if (!(v - v == v - v)) return false;  // NaN or infinity
  }
  out = v;
  return true;
}

// The words of a line separated by spaces, tabs and carriage returns, as views into it.
std::vector<std::string_view> splitWords(std::string_view line);

}  // namespace vox
