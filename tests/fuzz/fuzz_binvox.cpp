// libFuzzer target: the .binvox reader (files from binvox, trimesh, cuda_voxelizer and hostile ones).
#include <cstddef>
#include <cstdint>

#include "vox/io/voxel_file.h"

// Grids beyond this are refused as they would be on a small machine; keeps the fuzzer under its RSS limit.
constexpr uint64_t kFuzzMemoryLimit = uint64_t(256) << 20;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto grid = vox::io::decodeBinvox({data, size}, "fuzz.binvox", kFuzzMemoryLimit);
  if (grid.ok()) {
    const auto bytes = vox::io::encodeBinvox(*grid);
    auto again = vox::io::decodeBinvox(bytes, "fuzz-again.binvox");
    if (!again.ok() || again->filledCount() != grid->filledCount()) __builtin_trap();
  }
  return 0;
}
