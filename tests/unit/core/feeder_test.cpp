// A feeder's voxels on a lattice: exactly the voxels whose centres lie in its cylinder (the ones the casting
// simulation makes metal), as many as its volume over a voxel's within a few percent; a feeder thinner than a voxel
// or larger than memory is refused before anything is allocated.
#include "vox/core/feeder.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace vox {
namespace {

TEST(FeederVoxels, areTheVoxelsWhoseCentresLieInTheCylinder) {
  const Lattice lattice{{0.3, -1.1, 2.0}, 0.25, "mm"};
  const Feeder f{{1.0, 0.5, 3.0}, 4.0, 6.0};
  auto v = feederVoxels(f, lattice);
  ASSERT_TRUE(v.ok()) << v.error().message;
  const GridFrame frame = lattice.frameAt(glm::ivec3(0));
  int64_t inside = 0;
  for (int32_t z = v->first.z - 2; z < v->first.z + v->grid.nz() + 2; ++z)
    for (int32_t y = v->first.y - 2; y < v->first.y + v->grid.ny() + 2; ++y)
      for (int32_t x = v->first.x - 2; x < v->first.x + v->grid.nx() + 2; ++x) {
        const glm::ivec3 q(x, y, z), l = q - v->first;
        const bool held = v->grid.inBounds(l.x, l.y, l.z) && v->grid.get(l.x, l.y, l.z);
        ASSERT_EQ(held, inFeeder(f, frame, q)) << x << " " << y << " " << z;
        inside += held;
      }
  EXPECT_EQ(inside, v->grid.filledCount());
  EXPECT_EQ(v->grid.frame().origin, lattice.frameAt(v->first).origin);
  const double volume = std::numbers::pi * 4.0 * 6.0 / std::pow(0.25, 3);
  EXPECT_NEAR(double(inside), volume, 0.03 * volume);
  // the foot stands on base.z: the first layer's centres lie just above it
  EXPECT_GE(frame.voxelCentre(0, 0, v->first.z).z, f.base.z);
  EXPECT_LT(frame.voxelCentre(0, 0, v->first.z).z, f.base.z + 0.25);
}

TEST(FeederVoxels, tooThinOrTooLargeIsRefused) {
  const Lattice lattice{{0.0, 0.0, 0.0}, 1.0, "mm"};
  auto thin = feederVoxels(Feeder{{0.2, 0.2, 0.0}, 0.1, 5.0}, lattice);
  ASSERT_FALSE(thin.ok());
  EXPECT_EQ(thin.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(thin.error().message.find("thinner or shorter than a voxel"), std::string::npos);
  auto huge = feederVoxels(Feeder{{0.0, 0.0, 0.0}, 1e5, 1e5}, lattice);
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.error().code, ErrorCode::kLimit);
  auto far = feederVoxels(Feeder{{1e12, 0.0, 0.0}, 2.0, 2.0}, lattice);
  ASSERT_FALSE(far.ok());
  EXPECT_EQ(far.error().code, ErrorCode::kLimit);
}

}  // namespace
}  // namespace vox
