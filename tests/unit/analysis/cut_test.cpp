// cutAway: the half of a model the window's cut-away shows, against a voxel-by-voxel filter.
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

TEST(CutAway, leavesTheModelItCameFromUnchanged) {
  const VoxelGrid g = test::boxGrid({20, 20, 20}, {2, 2, 2}, {18, 18, 18});
  const int64_t before = g.filledCount();
  const VoxelGrid cut = cutAway(g, Axis::kY, 9, false);
  EXPECT_EQ(cut.filledCount(), 16 * 8 * 16);  // y = 2..9
  EXPECT_EQ(g.filledCount(), before);
}

}  // namespace
}  // namespace vox
