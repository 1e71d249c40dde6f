// A coarse copy of a .vxm file's grid (vox/io/vxm_stream.h, readVxmCoarse), read in windows of `level` layers: the
// rows of a window that fall into one coarse row are ORed together word by word, then each coarse voxel is set from
// the first filled voxel of its block in that row, so the cost is O(words of the file's grid + coarse voxels).
#include <algorithm>
#include <bit>

#include "io/vxm_detail.h"
#include "vox/io/vxm_stream.h"

namespace vox::io {

namespace {

int32_t ceilDiv(int32_t n, int32_t d) { return (n + d - 1) / d; }

Dims coarseDims(const Dims& d, int32_t level) {
  return Dims{ceilDiv(d.nx, level), ceilDiv(d.ny, level), ceilDiv(d.nz, level)};
}

// Sets coarse voxel (x / level, cy, cz) for every block of `level` x values holding a set bit of `row` (unpadded
// words).
void setBlocks(const std::vector<uint64_t>& row, int32_t level, int32_t cy, int32_t cz, VoxelGrid& coarse) {
  for (size_t w = 0; w < row.size(); ++w) {
    uint64_t bits = row[w];
    while (bits) {
      const int64_t x = int64_t(w) * 64 + std::countr_zero(bits);
      const int64_t cx = x / level;
      coarse.set(cx, cy, cz);
      const int64_t next = (cx + 1) * level - int64_t(w) * 64;  // the next block's first bit in this word
      bits = next >= 64 ? 0 : bits & ~((uint64_t(1) << next) - 1);
    }
  }
}

}  // namespace

int32_t coarseLevelFor(const Dims& dims, uint64_t bytes) {
  for (int32_t level = 1; level < 64; level *= 2) {
    if (estimateGridBytes(coarseDims(dims, level)) <= bytes) return level;
  }
  return 64;
}

Result<VoxelGrid> readVxmCoarse(const std::filesystem::path& path, int32_t level, const ProgressFn& progress) {
  auto header = readVxmHeader(path);
  if (!header) return header.error();
  const Dims d = header->dims;
  level = std::clamp(level, 1, 64);
  GridFrame frame = header->frame;
  frame.voxel_size *= level;
  VoxelGrid coarse(coarseDims(d, level), frame);
  const size_t words = size_t((int64_t(d.nx) + 63) / 64);
  std::vector<std::vector<uint64_t>> acc(size_t(coarse.ny()), std::vector<uint64_t>(words));
  std::vector<uint64_t> row(words);
  bool cancelled = false, dirty = false;  // dirty: acc holds rows of the last window
  const Status read = readVxmInWindows(path, level, 0, [&](const VxmWindow& w) {
    if (dirty) {
      for (auto& a : acc) std::fill(a.begin(), a.end(), 0);
    }
    bool any = false;
    for (int32_t z = w.core_begin; z < w.core_end; ++z) {
      if (!w.grid.layerAllocated(z - w.z_offset)) continue;
      any = true;
      for (int32_t y = 0; y < d.ny; ++y) {
        vxm_detail::unpaddedRow(w.grid, y, z - w.z_offset, row);
        std::vector<uint64_t>& a = acc[size_t(y / level)];
        for (size_t i = 0; i < words; ++i) a[i] |= row[i];
      }
    }
    const int32_t cz = w.core_begin / level;
    dirty = any;
    if (any) {
      for (int32_t cy = 0; cy < coarse.ny(); ++cy) setBlocks(acc[size_t(cy)], level, cy, cz, coarse);
    }
    if (progress && !progress(double(w.core_end) / double(d.nz))) {
      cancelled = true;
      return Status(makeError(ErrorCode::kCancelled, "opening cancelled"));
    }
    return Status(Ok{});
  });
  if (!read) return read.error();
  if (cancelled) return makeError(ErrorCode::kCancelled, "opening cancelled");
  return coarse;
}

}  // namespace vox::io
