// The skin depth and the X-ray as scalar fields for volume export (vox/analysis/scalar_fields.h).
#include <gtest/gtest.h>

#include "grids.h"
#include "vox/analysis/scalar_fields.h"

namespace vox {
namespace {

GridFrame frame() {
  return GridFrame{.origin = glm::dvec3(1.0, -2.0, 3.0), .voxel_size = 0.5, .units = "mm", .source = ""};
}

TEST(ScalarFields, depthIsTheSkinLayerOfEveryVoxel) {
  VoxelGrid g(Dims{9, 7, 5}, frame());
  test::fillBox(g, glm::ivec3(1), glm::ivec3(8, 6, 4));  // 7 x 5 x 3: two layers, the core a 5 x 3 x 1 slab
  auto depth = computeDepthMap(g, kPeelAll);
  ASSERT_TRUE(depth.ok());
  const ScalarField f = depthField(*depth, g);
  EXPECT_EQ(f.dims, g.dims());
  EXPECT_EQ(f.frame, g.frame());
  for (int32_t z = 0; z < 5; ++z)
    for (int32_t y = 0; y < 7; ++y)
      for (int32_t x = 0; x < 9; ++x) {
        const bool core = x >= 2 && x < 7 && y >= 2 && y < 5 && z == 2;
        const float want = !g.get(x, y, z) ? 0.0f : core ? 2.0f : 1.0f;
        ASSERT_EQ(f.at(x, y, z), want) << x << " " << y << " " << z;
      }
}

// A 4 x 3 x 2 block in a 6 x 5 x 4 grid: every ray through it meets 4, 3 or 2 voxels of 0.5 mm.
TEST(ScalarFields, anXrayIsASlabOneVoxelThickAlongItsAxisInModelUnits) {
  VoxelGrid g(Dims{6, 5, 4}, frame());
  test::fillBox(g, glm::ivec3(1, 1, 1), glm::ivec3(5, 4, 3));
  const int32_t thick[3] = {4, 3, 2};
  for (Axis axis : {Axis::kX, Axis::kY, Axis::kZ}) {
    SCOPED_TRACE(axisName(axis));
    auto x = computeXray(g, XrayParams{axis, XrayMode::kTotal});
    ASSERT_TRUE(x.ok());
    const ScalarField f = xrayField(*x, g);
    glm::ivec3 dims(6, 5, 4);
    dims[int(axis)] = 1;
    EXPECT_EQ(f.dims, (Dims{dims.x, dims.y, dims.z}));
    EXPECT_EQ(f.frame, g.frame());
    for (int32_t k = 0; k < dims.z; ++k)
      for (int32_t j = 0; j < dims.y; ++j)
        for (int32_t i = 0; i < dims.x; ++i) {
          glm::ivec3 v(i, j, k);
          v[int(axis)] = 1;  // a voxel the ray through (i, j, k) crosses when it hits the block
          const float want = g.get(v.x, v.y, v.z) ? float(thick[int(axis)]) * 0.5f : 0.0f;
          ASSERT_EQ(f.at(i, j, k), want) << i << " " << j << " " << k;
        }
  }
}

}  // namespace
}  // namespace vox
