// libFuzzer target: the .vxm reader. Accepted files must re-encode to a grid that decodes identically.
#include <cstddef>
#include <cstdint>

#include "vox/io/voxel_file.h"

// Grids beyond this are refused as they would be on a small machine; keeps the fuzzer under its RSS limit.
constexpr uint64_t kFuzzMemoryLimit = uint64_t(256) << 20;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto grid = vox::io::decodeVxm({data, size}, "fuzz.vxm", kFuzzMemoryLimit);
  if (grid.ok()) {
    const auto bytes = vox::io::encodeVxm(*grid);
    auto again = vox::io::decodeVxm(bytes, "fuzz-again.vxm");
    if (!again.ok() || again->filledCount() != grid->filledCount()) __builtin_trap();
  }
  return 0;
}
