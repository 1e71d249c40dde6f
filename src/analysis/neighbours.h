#pragma once
// The 26-neighbourhood of a voxel of a box (x fastest, then y, then z), for the walks over a distance field's box
// (hot spots, thin walls): f(j) for the index j of every voxel at most one step away in each axis, the voxel itself
// included, that lies inside the box.
#include <cstdint>

namespace vox::analysis_detail {

template <class F>
void forEach26(int64_t x, int64_t y, int64_t z, int64_t nx, int64_t ny, int64_t nz, F&& f) {
  const int64_t plane = nx * ny;
  const int64_t i = x + nx * y + plane * z;
  for (int64_t dz = -1; dz <= 1; ++dz) {
    if (z + dz < 0 || z + dz >= nz) continue;
    for (int64_t dy = -1; dy <= 1; ++dy) {
      if (y + dy < 0 || y + dy >= ny) continue;
      for (int64_t dx = -1; dx <= 1; ++dx) {
        if (x + dx < 0 || x + dx >= nx) continue;
        f(i + dx + nx * dy + plane * dz);
      }
    }
  }
}

}  // namespace vox::analysis_detail
