#include "vox/core/text.h"

#include <unistd.h>

#include <chrono>
#include <cinttypes>
#include <cstdio>

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
