// Picking the voxel a click points at: the first filled voxel along the ray, in voxel-index space.
#include <gtest/gtest.h>

#include "grids.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

TEST(PickVoxel, findsTheFirstFilledVoxelAlongTheRay) {
  VoxelGrid g(Dims{10, 8, 6}, GridFrame{});
  g.set(7, 4, 3, true);
  g.set(3, 4, 3, true);
  // From beyond +x along -x through row (y, z) = (4, 3): x = 7 comes first.
  auto v = pickVoxel(g, glm::dvec3(20.0, 4.5, 3.5), glm::dvec3(-20.0, 4.5, 3.5));
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, glm::ivec3(7, 4, 3));
  // The other way round: x = 3.
  v = pickVoxel(g, glm::dvec3(-20.0, 4.5, 3.5), glm::dvec3(20.0, 4.5, 3.5));
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, glm::ivec3(3, 4, 3));
  // A diagonal ray that passes beside the voxels meets nothing; one that misses the grid too.
  EXPECT_FALSE(pickVoxel(g, glm::dvec3(0.1, 0.1, 0.1), glm::dvec3(9.9, 7.9, 5.9)).has_value());
  EXPECT_FALSE(pickVoxel(g, glm::dvec3(-5, 20, 3), glm::dvec3(30, 20, 3)).has_value());
  // A segment that stops short of the material.
  EXPECT_FALSE(pickVoxel(g, glm::dvec3(20.0, 4.5, 3.5), glm::dvec3(8.5, 4.5, 3.5)).has_value());
}

TEST(PickVoxel, agreesWithAWalkInSmallStepsOnABall) {
  const VoxelGrid g = test::ballGrid(Dims{30, 30, 30}, glm::dvec3(15, 15, 15), 9.3);
  const glm::dvec3 from(-4.0, 3.3, 29.1), to(33.0, 26.2, 1.7);
  glm::ivec3 expected(-1);
  for (int i = 0; i <= 100000; ++i) {
    const glm::dvec3 p = from + (to - from) * (double(i) / 100000.0);
    const glm::ivec3 v(glm::floor(p));
    if (g.inBounds(v.x, v.y, v.z) && g.get(v.x, v.y, v.z)) {
      expected = v;
      break;
    }
  }
  ASSERT_NE(expected, glm::ivec3(-1));
  const auto v = pickVoxel(g, from, to);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, expected);
}

}  // namespace
}  // namespace vox
