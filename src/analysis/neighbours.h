#pragma once
// The 26-neighbourhood of a voxel of a box (x fastest, then y, then z), for the walks over a distance field's box
// (hot spots, thin walls): f(j) for the index j of every voxel at most one step away in each axis, the voxel itself
// included, that lies inside the box.
#include <algorithm>
#include <cstdint>

namespace vox::analysis_detail {

// f(qx, qy, qz) for the same voxels, by their coordinates.
template <class F>
void forEach26At(int64_t x, int64_t y, int64_t z, int64_t nx, int64_t ny, int64_t nz, F&& f) {
  for (int64_t qz = std::max<int64_t>(z - 1, 0); qz <= std::min(z + 1, nz - 1); ++qz)
    for (int64_t qy = std::max<int64_t>(y - 1, 0); qy <= std::min(y + 1, ny - 1); ++qy)
      for (int64_t qx = std::max<int64_t>(x - 1, 0); qx <= std::min(x + 1, nx - 1); ++qx) f(qx, qy, qz);
}

template <class F>
void forEach26(int64_t x, int64_t y, int64_t z, int64_t nx, int64_t ny, int64_t nz, F&& f) {
  forEach26At(x, y, z, nx, ny, nz, [&](int64_t qx, int64_t qy, int64_t qz) { f(qx + nx * (qy + ny * qz)); });
}

}  // namespace vox::analysis_detail
