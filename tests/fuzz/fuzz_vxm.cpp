// libFuzzer target: the .vxm reader. Accepted files must re-encode to a grid that decodes identically.
// Random bytes almost never pass the two CRC-32 checks, so each input is decoded twice: as it is, and with both CRCs
// recomputed (layout in docs/file-format.md), which lets the fuzzer reach the header fields and the run-length body.
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "vox/io/voxel_file.h"

namespace {

// Grids beyond this are refused as they would be on a small machine; keeps the fuzzer under its RSS limit.
constexpr uint64_t kFuzzMemoryLimit = uint64_t(256) << 20;

void putCrc(std::vector<uint8_t>& b, size_t at, size_t covered) {
  const uint32_t crc = uint32_t(crc32(0L, b.data(), uInt(covered)));
  for (int i = 0; i < 4; ++i) b[at + size_t(i)] = uint8_t(crc >> (8 * i));
}

void decodeAndCheck(const uint8_t* data, size_t size) {
  auto grid = vox::io::decodeVxm({data, size}, "fuzz.vxm", kFuzzMemoryLimit);
  if (grid.ok()) {
    const auto bytes = vox::io::encodeVxm(*grid);
    auto again = vox::io::decodeVxm(bytes, "fuzz-again.vxm");
    if (!again.ok() || again->filledCount() != grid->filledCount()) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  decodeAndCheck(data, size);
  if (size < 96) return 0;
  std::vector<uint8_t> fixed(data, data + size);
  uint32_t header_size = 0;
  std::memcpy(&header_size, fixed.data() + 12, 4);  // little-endian hosts only, like the fuzzing machines
  if (header_size < 92 || size_t(header_size) + 4 > size) return 0;
  putCrc(fixed, header_size - 4, header_size - 4);
  putCrc(fixed, size - 4, size - 4);
  decodeAndCheck(fixed.data(), fixed.size());
  return 0;
}
