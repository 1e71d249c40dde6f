// The optional clean-up after voxelizing (thesis 4.3.3: stray voxels with four or more free faces are artefacts of
// thin sections and broken meshes), as word operations on the grid's rows.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "vox/core/bits.h"
#include "vox/core/surface.h"
#include "vox/core/voxel_grid.h"
#include "vox/core/parallel.h"
#include "voxelize/passes.h"

namespace vox::voxelize_detail {

int64_t removeStrayVoxels(VoxelGrid& grid, int threads) {
  const VoxelGrid before = grid;  // copy-on-write snapshot: shares the layers until one is written
  std::vector<int64_t> removed(size_t(std::max(threads, 1)), 0);
  forLayers(grid.nz(), threads, [&](int t, int32_t z) {
    if (!before.layerAllocated(z)) return;
    RowNeighbours n;
    n.resize(size_t(before.wordsPerRow()));
    for (int32_t y = 0; y < before.ny(); ++y) {
      rowNeighbourMasks(before, y, z, n);
      uint64_t* row = nullptr;
      for (size_t w = 0; w < n.self.size(); ++w) {
        if (n.self[w] == 0) continue;
        // Bit-sliced count of filled neighbours (s2 s1 s0 in binary), then "count <= 2".
        uint64_t s0 = 0, s1 = 0, s2 = 0;
        for (uint64_t m : {n.xm[w], n.xp[w], n.ym[w], n.yp[w], n.zm[w], n.zp[w]}) {
          const uint64_t c0 = s0 & m;
          s0 ^= m;
          const uint64_t c1 = s1 & c0;
          s1 ^= c0;
          s2 |= c1;
        }
        const uint64_t stray = n.self[w] & ~s2 & ~(s1 & s0);
        if (stray == 0) continue;
        if (!row) row = grid.mutableRowWords(y, z);
        row[w] &= ~stray;
        removed[size_t(t)] += popcount64(stray);
      }
    }
  });
  grid.releaseEmptyLayers();
  int64_t total = 0;
  for (int64_t r : removed) total += r;
  return total;
}

}  // namespace vox::voxelize_detail
