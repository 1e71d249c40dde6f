#pragma once
// Voxel grids built in code, shared by the test executables.
#include <cstdint>
#include <random>

#include "vox/core/voxel_grid.h"

namespace vox::test {

// Each voxel filled with probability p (deterministic for a seed): every neighbour code occurs, including isolated
// voxels and thin walls.
inline VoxelGrid randomGrid(Dims d, double p, uint32_t seed) {
  VoxelGrid g(d);
  std::mt19937 rng(seed);
  std::bernoulli_distribution fill(p);
  for (int32_t z = 0; z < d.nz; ++z)
    for (int32_t y = 0; y < d.ny; ++y)
      for (int32_t x = 0; x < d.nx; ++x)
        if (fill(rng)) g.set(x, y, z);
  return g;
}

}  // namespace vox::test
