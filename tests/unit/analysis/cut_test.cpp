// cutAway: the half of a model the window's cut-away shows, against a voxel-by-voxel filter.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "grids.h"
#include "vox/analysis/cut.h"

namespace vox {
namespace {

// Random grids of odd sizes (rows over one word, layers left empty) cut on every axis, both sides, at the borders
// and outside the grid: each voxel is kept exactly when its coordinate is on the kept side (the plane included).
TEST(CutAway, keepsExactlyTheVoxelsOnItsSideOfThePlane) {
  std::mt19937 rng(7);
  for (const Dims d : {Dims{70, 9, 11}, Dims{5, 130, 3}, Dims{129, 4, 6}}) {
    VoxelGrid g(d);
    std::bernoulli_distribution coin(0.4);
    for (int z = 0; z < d.nz; ++z) {
      if (z == 1) continue;  // an unallocated layer
      for (int y = 0; y < d.ny; ++y)
        for (int x = 0; x < d.nx; ++x)
          if (coin(rng)) g.set(x, y, z);
    }
    for (Axis axis : {Axis::kX, Axis::kY, Axis::kZ}) {
      const int n = axis == Axis::kX ? d.nx : axis == Axis::kY ? d.ny : d.nz;
      for (int index : {-1, 0, 1, n / 2, 63, 64, n - 1, n, n + 5}) {
        for (bool above : {false, true}) {
          const VoxelGrid cut = cutAway(g, axis, index, above);
          ASSERT_EQ(cut.dims(), g.dims());
          int64_t expected = 0;
          for (int z = 0; z < d.nz; ++z)
            for (int y = 0; y < d.ny; ++y)
              for (int x = 0; x < d.nx; ++x) {
                const int c = axis == Axis::kX ? x : axis == Axis::kY ? y : z;
                const bool keep = g.get(x, y, z) && (above ? c >= index : c <= index);
                expected += keep;
                ASSERT_EQ(cut.get(x, y, z), keep)
                    << axisName(axis) << " " << index << " " << above << " at " << x << "," << y << "," << z;
              }
          EXPECT_EQ(cut.filledCount(), expected);
        }
      }
    }
  }
}

// At any angle: a voxel is kept when its centre lies on the kept side of the plane or within half the normal's L1 norm
// of it (worked out here in double); the two halves overlap in exactly that slab.
TEST(CutAway, atAnAngleKeepsTheVoxelsOnItsSideOfThePlaneAndItsSlab) {
  std::mt19937 rng(11);
  const Dims d{70, 9, 11};
  VoxelGrid g(d);
  std::bernoulli_distribution coin(0.5);
  for (int z = 0; z < d.nz; ++z)
    for (int y = 0; y < d.ny; ++y)
      for (int x = 0; x < d.nx; ++x)
        if (z != 3 && coin(rng)) g.set(x, y, z);
  // Leaning along +X, along -X (each row's kept run a suffix, not a prefix) and nearly along -Z.
  for (const glm::dvec3 normal :
       {glm::dvec3(0.8, -0.4, 0.45), glm::dvec3(-0.9, 0.2, 0.1), glm::dvec3(0.1, 0.3, -0.95)}) {
    const glm::dvec3 n = glm::normalize(normal);
    const double offset = glm::dot(n, glm::dvec3(35.0, 4.5, 5.5)) + 0.137;  // near the grid's centre
    const SectionPlane plane = sectionPlaneOf(glm::vec3(n), float(offset));
    const double half = 0.5 * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
    const VoxelGrid below = cutAway(g, plane, false), above = cutAway(g, plane, true);
    int64_t slab = 0;
    for (int z = 0; z < d.nz; ++z)
      for (int y = 0; y < d.ny; ++y)
        for (int x = 0; x < d.nx; ++x) {
          const double s = glm::dot(n, glm::dvec3(x, y, z) + 0.5) - offset;
          ASSERT_EQ(below.get(x, y, z), g.get(x, y, z) && s < half) << x << "," << y << "," << z;
          ASSERT_EQ(above.get(x, y, z), g.get(x, y, z) && s >= -half) << x << "," << y << "," << z;
          slab += g.get(x, y, z) && s >= -half && s < half;
        }
    EXPECT_GT(slab, 0);
    EXPECT_EQ(below.filledCount() + above.filledCount(), g.filledCount() + slab);
  }
}

TEST(CutAway, leavesTheModelItCameFromUnchanged) {
  const VoxelGrid g = test::boxGrid({20, 20, 20}, {2, 2, 2}, {18, 18, 18});
  const int64_t before = g.filledCount();
  const VoxelGrid cut = cutAway(g, Axis::kY, 9, false);
  EXPECT_EQ(cut.filledCount(), 16 * 8 * 16);  // y = 2..9
  EXPECT_EQ(g.filledCount(), before);
}

}  // namespace
}  // namespace vox
