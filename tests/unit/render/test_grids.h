#pragma once
// Small grids built in code for the render unit tests.
#include <cmath>
#include <cstdint>
#include <random>

#include "support/grids.h"
#include "vox/core/voxel_grid.h"

namespace vox::render::testing {

// A ball of radius r (voxels) centred in a cube grid of side n: voxel centres within r of the grid centre.
inline VoxelGrid ball(int32_t n, double r) {
  VoxelGrid g(Dims{n, n, n});
  const double c = n * 0.5;
  for (int32_t z = 0; z < n; ++z) {
    for (int32_t y = 0; y < n; ++y) {
      const double dy = y + 0.5 - c, dz = z + 0.5 - c, h2 = r * r - dy * dy - dz * dz;
      if (h2 < 0) continue;
      const double h = std::sqrt(h2);
      g.fillRun(y, z, int64_t(std::ceil(c - h - 0.5)), int64_t(std::floor(c + h - 0.5)) + 1);
    }
  }
  return g;
}

// Filled box [lo, hi).
inline VoxelGrid box(Dims d, glm::ivec3 lo, glm::ivec3 hi) {
  VoxelGrid g(d);
  for (int32_t z = lo.z; z < hi.z; ++z)
    for (int32_t y = lo.y; y < hi.y; ++y) g.fillRun(y, z, lo.x, hi.x);
  return g;
}

inline void fillBox(VoxelGrid& g, glm::ivec3 lo, glm::ivec3 hi) {
  for (int32_t z = lo.z; z < hi.z; ++z)
    for (int32_t y = lo.y; y < hi.y; ++y) g.fillRun(y, z, lo.x, hi.x);
}

// Each voxel filled with probability p: every code occurs, including isolated voxels and thin walls.
inline VoxelGrid noise(Dims d, double p, uint32_t seed) { return vox::test::randomGrid(d, p, seed); }

}  // namespace vox::render::testing
