#pragma once
// What the .vxm codec (vxm.cpp) shares with its slab writer and layer reader (vxm_stream.cpp): the header's layout
// and parser, the varints and the run encoder. docs/file-format.md gives the layout byte by byte. Private to io.
#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "io/voxel_file_common.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox::io::vxm_detail {

using voxel_file_detail::Writer;

template <class T>
T loadLE(const uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) {
    if constexpr (sizeof(T) == 2) v = T(__builtin_bswap16(v));
    if constexpr (sizeof(T) == 4) v = T(__builtin_bswap32(v));
    if constexpr (sizeof(T) == 8) v = T(__builtin_bswap64(v));
  }
  return v;
}

inline constexpr uint8_t kVxmMagic[8] = {0x89, 'V', 'X', 'M', '\r', '\n', 0x1A, '\n'};
inline constexpr size_t kVxmFixedBytes = 84;                            // magic .. body size, before the two strings
inline constexpr size_t kVxmMinBytes = kVxmFixedBytes + 2 + 2 + 4 + 4;  // empty strings, header CRC, file CRC

// Emits alternating runs, starting with an empty one, as varints.
class RunEncoder {
 public:
  explicit RunEncoder(Writer& w) : w_(w) {}
  void add(bool filled, uint64_t n) {
    if (n == 0) return;
    if (filled != state_) {
      w_.varint(run_);
      ++runs_;
      run_ = 0;
      state_ = filled;
    }
    run_ += n;
    if (filled) filled_ += n;
  }
  void finish() {
    w_.varint(run_);
    ++runs_;
  }
  uint64_t runs() const { return runs_; }
  uint64_t filled() const { return filled_; }

 private:
  Writer& w_;
  bool state_ = false;
  uint64_t run_ = 0;
  uint64_t runs_ = 0;
  uint64_t filled_ = 0;
};

// Parsed .vxm header fields.
struct VxmHeader {
  Dims dims;
  GridFrame frame;
  uint64_t filled = 0, runs = 0, body_bytes = 0;
  size_t header_bytes = 0;  // offset of the body
};

// Reads one LEB128 varint of at most 10 bytes; false when it is truncated or overlong.
inline bool readVarint(const uint8_t*& p, const uint8_t* end, uint64_t& v) {
  v = 0;
  for (int shift = 0; shift < 64 && p < end; shift += 7) {
    const uint8_t b = *p++;
    if (shift == 63 && b > 1) return false;  // would overflow 64 bits
    v |= uint64_t(b & 0x7F) << shift;
    if (!(b & 0x80)) return true;
  }
  return false;
}

// The header: magic and version, then the fields under their own CRC, so that a truncated body is told apart
// from a damaged header. `bytes` is the file, or at least its first kVxmMaxHeaderBytes bytes (a longer file is
// only checked for being long enough to hold the header).
Result<VxmHeader> parseVxmHeader(std::span<const uint8_t> bytes, const std::string& name);
// A file of `size` bytes holds exactly the header, the body and the CRC the header describes (truncated, or bytes
// after its end, otherwise).
Status checkVxmLength(uint64_t size, const VxmHeader& h, const std::string& name);
inline constexpr size_t kVxmMaxHeaderBytes = kVxmFixedBytes + 8 + 2 * 0xFFFF;

// Voxel bits of row (y, z) as unpadded words: bit b of word w is voxel x = 64 w + b. Bits past nx are zero.
void unpaddedRow(const VoxelGrid& grid, int32_t y, int32_t z, std::vector<uint64_t>& out);

}  // namespace vox::io::vxm_detail
