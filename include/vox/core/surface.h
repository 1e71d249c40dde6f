#pragma once
// Surface extraction with word operations on whole rows (thesis 5.1/5.2.2): a voxel is on the surface when it is
// filled and at least one face neighbour is empty, i.e. surface = filled & ~(all six neighbours). Both the
// analysis module (statistics, skin removal) and the renderer (points to draw) build on these primitives.
#include <bit>
#include <cstdint>
#include <vector>

#include "vox/core/neighbour_code.h"
#include "vox/core/voxel_grid.h"

namespace vox {

// Per-word neighbour masks of one row: bit b of `xm[w]` is set when the voxel at padded x = 64w + b has its x-1
// neighbour filled, and so on. Computed for padded words 0..wordsPerRow()-1.
struct RowNeighbours {
  std::vector<uint64_t> self, xm, xp, ym, yp, zm, zp;
  void resize(size_t n) {
    for (auto* v : {&self, &xm, &xp, &ym, &yp, &zm, &zp}) v->assign(n, 0);
  }
};

// Fills `out` with the six neighbour masks of row (y, z), 0 <= y < ny, 0 <= z < nz.
void rowNeighbourMasks(const VoxelGrid& grid, int32_t y, int32_t z, RowNeighbours& out);

// Surface mask of row (y, z): filled voxels with at least one empty face neighbour (padded bit positions).
void rowSurfaceMask(const VoxelGrid& grid, int32_t y, int32_t z, uint64_t* out);

// Calls f(x, y, z, code) for every surface voxel (code < 63) of rows z0 <= z < z1 (all when z1 < 0), in order of
// z, then y, then x. Cost: O(words) plus O(surface voxels).
template <class F>
void forEachSurfaceVoxel(const VoxelGrid& grid, F&& f, int32_t z0 = 0, int32_t z1 = -1) {
  if (z1 < 0) z1 = grid.nz();
  RowNeighbours n;
  n.resize(size_t(grid.wordsPerRow()));
  for (int32_t z = z0; z < z1; ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < grid.ny(); ++y) {
      rowNeighbourMasks(grid, y, z, n);
      for (size_t w = 0; w < n.self.size(); ++w) {
        const uint64_t all = n.xm[w] & n.xp[w] & n.ym[w] & n.yp[w] & n.zm[w] & n.zp[w];
        uint64_t surf = n.self[w] & ~all;
        while (surf) {
          const int b = std::countr_zero(surf);
          surf &= surf - 1;
          const uint64_t bit = uint64_t(1) << b;
          const uint8_t code = uint8_t(((n.ym[w] & bit) ? kCodeYMinus : 0) | ((n.xm[w] & bit) ? kCodeXMinus : 0) |
                                       ((n.xp[w] & bit) ? kCodeXPlus : 0) | ((n.yp[w] & bit) ? kCodeYPlus : 0) |
                                       ((n.zm[w] & bit) ? kCodeZMinus : 0) | ((n.zp[w] & bit) ? kCodeZPlus : 0));
          f(int32_t(int64_t(w) * 64 + b - 1), y, z, code);
        }
      }
    }
  }
}

// Number of surface voxels (filled with at least one empty face neighbour).
int64_t countSurfaceVoxels(const VoxelGrid& grid);
// Of layers [z0, z1) only (their neighbours in layers z0 - 1 and z1 count as the grid holds them).
int64_t countSurfaceVoxels(const VoxelGrid& grid, int32_t z0, int32_t z1);

}  // namespace vox
