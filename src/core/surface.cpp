#include "vox/core/surface.h"

#include "vox/core/bits.h"

namespace vox {

void rowNeighbourMasks(const VoxelGrid& grid, int32_t y, int32_t z, RowNeighbours& out) {
  const size_t n = size_t(grid.wordsPerRow());
  if (out.self.size() != n) out.resize(n);
  const uint64_t* c = grid.rowWords(y, z);
  const uint64_t* ym = grid.rowWords(y - 1, z);
  const uint64_t* yp = grid.rowWords(y + 1, z);
  const uint64_t* zm = grid.rowWords(y, z - 1);
  const uint64_t* zp = grid.rowWords(y, z + 1);
  for (size_t w = 0; w < n; ++w) {
    const uint64_t prev = w > 0 ? c[w - 1] : 0;
    const uint64_t next = w + 1 < n ? c[w + 1] : 0;
    out.self[w] = c[w];
    out.xm[w] = (c[w] << 1) | (prev >> 63);  // bit b gets voxel b-1
    out.xp[w] = (c[w] >> 1) | (next << 63);  // bit b gets voxel b+1
    out.ym[w] = ym[w];
    out.yp[w] = yp[w];
    out.zm[w] = zm[w];
    out.zp[w] = zp[w];
  }
}

void rowSurfaceMask(const VoxelGrid& grid, int32_t y, int32_t z, uint64_t* out) {
  const int64_t n = grid.wordsPerRow();
  const uint64_t* c = grid.rowWords(y, z);
  const uint64_t* ym = grid.rowWords(y - 1, z);
  const uint64_t* yp = grid.rowWords(y + 1, z);
  const uint64_t* zm = grid.rowWords(y, z - 1);
  const uint64_t* zp = grid.rowWords(y, z + 1);
  for (int64_t w = 0; w < n; ++w) {
    const uint64_t prev = w > 0 ? c[w - 1] : 0;
    const uint64_t next = w + 1 < n ? c[w + 1] : 0;
    const uint64_t xm = (c[w] << 1) | (prev >> 63);
    const uint64_t xp = (c[w] >> 1) | (next << 63);
    out[w] = c[w] & ~(xm & xp & ym[w] & yp[w] & zm[w] & zp[w]);
  }
}

int64_t countSurfaceVoxels(const VoxelGrid& grid) { return countSurfaceVoxels(grid, 0, grid.nz()); }

int64_t countSurfaceVoxels(const VoxelGrid& grid, int32_t z0, int32_t z1) {
  std::vector<uint64_t> mask(size_t(grid.wordsPerRow()));
  int64_t count = 0;
  for (int32_t z = z0; z < z1; ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < grid.ny(); ++y) {
      rowSurfaceMask(grid, y, z, mask.data());
      for (uint64_t w : mask) count += popcount64(w);
    }
  }
  return count;
}

}  // namespace vox
