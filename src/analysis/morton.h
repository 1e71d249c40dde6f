#pragma once
// Morton (Z-order) codes: neighbours in space come near each other in the order, so work done in this order walks
// memory that is still cached.
#include <cstdint>

namespace vox::analysis_detail {

// The Morton code of (x, y, z), each below 2^16: their bits interleaved, x lowest.
inline uint64_t mortonCode(uint32_t x, uint32_t y, uint32_t z) {
  auto spread = [](uint64_t v) {  // bits of a 16-bit value to every third bit
    v = (v | v << 16) & 0x0000FF0000FFull;
    v = (v | v << 8) & 0x00F00F00F00F00Full;
    v = (v | v << 4) & 0x0C30C30C30C30C3ull;
    return (v | v << 2) & 0x249249249249249ull;
  };
  return spread(x & 0xFFFFu) | spread(y & 0xFFFFu) << 1 | spread(z & 0xFFFFu) << 2;
}

}  // namespace vox::analysis_detail
