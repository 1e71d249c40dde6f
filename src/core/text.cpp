#include "vox/core/text.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include "vox/core/units.h"

namespace vox {

std::string formatBytes(uint64_t bytes) {
  char buf[32];
  const double b = double(bytes);
  if (bytes < 1024) {
    std::snprintf(buf, sizeof buf, "%" PRIu64 " B", bytes);
  } else if (b < 1024.0 * 1024.0) {
    std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024.0);
  } else if (b < 1024.0 * 1024.0 * 1024.0) {
    std::snprintf(buf, sizeof buf, "%.1f MiB", b / (1024.0 * 1024.0));
  } else {
    std::snprintf(buf, sizeof buf, "%.2f GiB", b / (1024.0 * 1024.0 * 1024.0));
  }
  return buf;
}

std::string dimsText(const Dims& d) {
  return std::to_string(d.nx) + " x " + std::to_string(d.ny) + " x " + std::to_string(d.nz);
}

std::string formatCoordinate(double value, const std::string& units, double voxel_size) {
  // One decimal finer than the voxel: 0.0127 mm voxels read to 0.001 mm, 3.8 mm voxels to 0.1 mm.
  const int decimals = voxel_size > 0.0 && std::isfinite(voxel_size)
                           ? int(std::clamp(std::ceil(-std::log10(voxel_size)) + 1.0, 0.0, 9.0))
                           : 3;
  const double unit = std::pow(10.0, -decimals);
  const double shown = std::abs(value) < 0.5 * unit ? 0.0 : value;  // never "-0.000"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f %s", decimals, shown, unitsLabel(units).c_str());
  return buf;
}

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

uint64_t defaultMemoryLimitBytes() {
  const uint64_t physical = physicalMemoryBytes();
  return physical > 0 ? physical / 5 * 4 : UINT64_MAX;
}

double nowSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

uint64_t physicalMemoryBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0;
  return uint64_t(pages) * uint64_t(page_size);
}

}  // namespace vox
