// The skin depth and the X-ray as scalar fields (vox/analysis/scalar_fields.h).
#include "vox/analysis/scalar_fields.h"

#include <array>

namespace vox {

ScalarField depthField(const DepthMap& depth, const VoxelGrid& grid) {
  ScalarField f(grid.dims(), grid.frame());
  for (int32_t z = 0; z < grid.nz(); ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < grid.ny(); ++y) {
      for (int32_t x = 0; x < grid.nx(); ++x) {
        if (grid.get(x, y, z)) f.at(x, y, z) = float(depth.depthAt(x, y, z));
      }
    }
  }
  return f;
}

ScalarField xrayField(const XrayResult& xray, const VoxelGrid& grid) {
  const auto axis = int(xray.axis), right = int(imageRightAxis(xray.axis)), up = int(imageUpAxis(xray.axis));
  std::array<int32_t, 3> n{grid.nx(), grid.ny(), grid.nz()};
  n[size_t(axis)] = 1;
  ScalarField f(Dims{n[0], n[1], n[2]}, grid.frame());
  const Image2D<int32_t>& image = xray.thickness;
  for (int32_t row = 0; row < image.height; ++row) {
    for (int32_t col = 0; col < image.width; ++col) {
      std::array<int32_t, 3> v{0, 0, 0};
      v[size_t(right)] = col;
      v[size_t(up)] = image.height - 1 - row;  // row 0 holds the largest index
      f.at(v[0], v[1], v[2]) = float(double(image.at(col, row)) * xray.voxel_size);
    }
  }
  return f;
}

}  // namespace vox
