#pragma once
// A number per voxel of a grid's lattice (a distance or thickness field, in model units), x fastest, then y, then z,
// placed as the grid is (GridFrame: the centre of voxel (i, j, k) is frame.voxelCentre(i, j, k)).
#include <cstdint>
#include <vector>

#include "vox/core/voxel_grid.h"

namespace vox {

struct ScalarField {
  Dims dims;
  GridFrame frame;
  std::vector<float> values;  // dims.count() of them

  ScalarField() = default;
  ScalarField(Dims d, GridFrame f, float fill = 0.0f) : dims(d), frame(std::move(f)), values(size_t(d.count()), fill) {}
  float& at(int64_t x, int64_t y, int64_t z) { return values[size_t(x + dims.nx * (y + dims.ny * z))]; }
  float at(int64_t x, int64_t y, int64_t z) const { return values[size_t(x + dims.nx * (y + dims.ny * z))]; }
};

}  // namespace vox
