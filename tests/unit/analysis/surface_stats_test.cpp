#include <gtest/gtest.h>

#include "grids.h"
#include "vox/analysis/analysis.h"
#include "vox/core/neighbour_code.h"

namespace vox {
namespace {

using test::boxGrid;

TEST(SurfaceStats, isolatedVoxelHasCodeZero) {
  VoxelGrid g(Dims{3, 3, 3});
  g.set(1, 1, 1);
  const SurfaceStats s = computeSurfaceStats(g);
  EXPECT_EQ(s.filled, 1);
  EXPECT_EQ(s.surface_voxels, 1);
  EXPECT_EQ(s.code_histogram[0], 1);
  EXPECT_EQ(s.suspect_voxels, 0);  // six free faces: an isolated voxel, not a 1D/2D structure
}

TEST(SurfaceStats, cubeOfThreeHasOneInteriorVoxelAndCornerCodes) {
  const VoxelGrid g = boxGrid(Dims{5, 5, 5}, {1, 1, 1}, {4, 4, 4});
  const SurfaceStats s = computeSurfaceStats(g);
  EXPECT_EQ(s.filled, 27);
  EXPECT_EQ(s.code_histogram[kCodeInterior], 1);
  EXPECT_EQ(s.surface_voxels, 26);
  // The corner at the minimum has its x+1, y+1 and z+1 neighbours: 8 + 4 + 1.
  EXPECT_EQ(s.code_histogram[kCodeXPlus | kCodeYPlus | kCodeZPlus], 1);
  // Face centres have five neighbours: one code per face.
  EXPECT_EQ(s.code_histogram[63 - kCodeZMinus], 1);
  EXPECT_EQ(s.suspect_voxels, 0);
}

TEST(SurfaceStats, lineOfVoxelsIsSuspect) {
  // A one-voxel-thick line: the middle voxels have four free faces, the ends five (thesis 4.3.3: such 1D
  // structures come from voxelization errors).
  const VoxelGrid g = boxGrid(Dims{70, 3, 3}, {2, 1, 1}, {67, 2, 2});
  const SurfaceStats s = computeSurfaceStats(g);
  EXPECT_EQ(s.filled, 65);
  EXPECT_EQ(s.code_histogram[kCodeXMinus | kCodeXPlus], 63);
  EXPECT_EQ(s.code_histogram[kCodeXPlus], 1);
  EXPECT_EQ(s.code_histogram[kCodeXMinus], 1);
  EXPECT_EQ(s.suspect_voxels, 65);
}

TEST(SurfaceStats, gridBoundaryCountsAsEmpty) {
  const VoxelGrid g = boxGrid(Dims{64, 2, 2}, {0, 0, 0}, {64, 2, 2});  // fills the grid; 64 + 2 padded bits
  const SurfaceStats s = computeSurfaceStats(g);
  EXPECT_EQ(s.filled, 256);
  EXPECT_EQ(s.surface_voxels, 256);
  EXPECT_EQ(s.code_histogram[kCodeInterior], 0);
}

TEST(SurfaceStats, matchesBruteForceOnRandomGridsAcrossWordBoundaries) {
  for (int nx : {1, 2, 62, 63, 64, 65, 127, 130}) {
    const VoxelGrid g = test::randomGrid(Dims{nx, 9, 7}, 0.7, uint32_t(nx));
    std::array<int64_t, 64> hist{};
    int64_t filled = 0;
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x)
          if (g.get(x, y, z)) {
            ++filled;
            ++hist[g.neighbourCode(x, y, z)];
          }
    const SurfaceStats s = computeSurfaceStats(g);
    EXPECT_EQ(s.filled, filled) << nx;
    EXPECT_EQ(s.code_histogram, hist) << nx;
    EXPECT_EQ(s.surface_voxels, filled - hist[63]) << nx;
  }
}

TEST(SurfaceStats, emptyGrids) {
  EXPECT_EQ(computeSurfaceStats(VoxelGrid()).filled, 0);
  EXPECT_EQ(computeSurfaceStats(VoxelGrid(Dims{4, 4, 4})).surface_voxels, 0);
}

}  // namespace
}  // namespace vox
