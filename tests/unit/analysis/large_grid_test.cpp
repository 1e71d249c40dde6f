// Grids large enough that the analyses split their work over threads (more than 2^16 words), checked against the
// voxel-by-voxel versions. The small grids of the other tests run on one thread.
#include <gtest/gtest.h>

#include <numeric>

#include "grids.h"
#include "peel_layers.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

const VoxelGrid& largeGrid() {
  static const VoxelGrid g = [] {
    VoxelGrid r = test::randomBoxes(Dims{300, 210, 190}, 14, 2024);
    test::fillBox(r, {5, 5, 5}, {295, 40, 60});  // a thick slab so that peeling takes many layers
    return r;
  }();
  return g;
}

TEST(LargeGrid, isLargeEnoughToUseThreads) {
  EXPECT_GT(largeGrid().allocatedLayers() * largeGrid().wordsPerLayer(), int64_t(1) << 17);
}

TEST(LargeGrid, surfaceStatsMatchBruteForce) {
  const VoxelGrid& g = largeGrid();
  std::array<int64_t, 64> hist{};
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        if (g.get(x, y, z)) ++hist[g.neighbourCode(x, y, z)];
  EXPECT_EQ(computeSurfaceStats(g).code_histogram, hist);
}

TEST(LargeGrid, peelAndDepthMapMatchBruteForce) {
  const VoxelGrid& g = largeGrid();
  auto d = computeDepthMap(g);
  ASSERT_TRUE(d.ok());
  VoxelGrid step = g;
  for (int k = 1; k <= 3; ++k) {
    int64_t removed = 0, expect_removed = 0;
    const VoxelGrid got = peelOneLayer(step, &removed);
    step = test::brutePeel(step, &expect_removed);
    EXPECT_EQ(removed, expect_removed) << k;
    EXPECT_TRUE(test::sameVoxels(got, step)) << k;
    EXPECT_TRUE(test::sameVoxels(d->remainingAfter(k), step)) << k;
    EXPECT_EQ(d->removedPerLayer()[size_t(k - 1)], expect_removed) << k;
  }
  auto all = test::peelLayers(g, PeelParams{0, true});
  ASSERT_TRUE(all.ok());
  EXPECT_EQ(all->removed_per_layer, d->removedPerLayer());
  EXPECT_EQ(std::accumulate(all->removed_per_layer.begin(), all->removed_per_layer.end(), int64_t(0)), g.filledCount());
}

TEST(LargeGrid, xrayMatchesBruteForce) {
  const VoxelGrid& g = largeGrid();
  for (int axis = 0; axis < 3; ++axis) {
    auto mn = computeXray(g, XrayParams{Axis(axis), XrayMode::kMin});
    auto mx = computeXray(g, XrayParams{Axis(axis), XrayMode::kMax});
    auto tot = computeXray(g, XrayParams{Axis(axis), XrayMode::kTotal});
    ASSERT_TRUE(mn.ok() && mx.ok() && tot.ok());
    const int nu = axis == 0 ? g.ny() : g.nx();
    const int nv = axis == 2 ? g.ny() : g.nz();
    for (int v = 0; v < nv; v += 3) {
      for (int u = 0; u < nu; ++u) {
        const glm::ivec3 s = axis == 0 ? glm::ivec3(0, u, v) : (axis == 1 ? glm::ivec3(u, 0, v) : glm::ivec3(u, v, 0));
        const std::vector<int> runs = test::bruteRuns(g, s, axis);
        const int row = nv - 1 - v;
        if (runs.empty()) {
          ASSERT_EQ(tot->thickness.at(u, row), 0);
          continue;
        }
        ASSERT_EQ(mn->thickness.at(u, row), *std::min_element(runs.begin(), runs.end()));
        ASSERT_EQ(mx->thickness.at(u, row), *std::max_element(runs.begin(), runs.end()));
        ASSERT_EQ(tot->thickness.at(u, row), std::accumulate(runs.begin(), runs.end(), 0));
      }
    }
  }
}

TEST(LargeGrid, sectionsAndMassMatchBruteForce) {
  const VoxelGrid& g = largeGrid();
  for (int i = 0; i < g.nx(); i += 17) {
    int64_t n = 0;
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y) n += g.get(i, y, z);
    EXPECT_EQ(sectionCount(g, Axis::kX, i), n) << i;
    EXPECT_EQ(computeSection(g, SectionParams{Axis::kX, i})->filled, n) << i;
  }
  double n = 0, sx = 0, sy = 0, sz = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        if (g.get(x, y, z)) n += 1, sx += x, sy += y, sz += z;
  const MassProperties m = computeMassProperties(g);
  EXPECT_EQ(m.filled, int64_t(n));
  EXPECT_NEAR(m.centroid.x, sx / n + 0.5, 1e-9);
  EXPECT_NEAR(m.centroid.y, sy / n + 0.5, 1e-9);
  EXPECT_NEAR(m.centroid.z, sz / n + 0.5, 1e-9);
}

TEST(LargeGrid, booleansMatchVoxelLogic) {
  const VoxelGrid& a = largeGrid();
  const VoxelGrid b = test::randomBoxes(a.dims(), 10, 7);
  const VoxelGrid u = *booleanOp(a, b, BoolOp::kUnion);
  const VoxelGrid i = *booleanOp(a, b, BoolOp::kIntersection);
  const VoxelGrid d = *booleanOp(a, b, BoolOp::kDifference);
  for (int z = 0; z < a.nz(); z += 2)
    for (int y = 0; y < a.ny(); ++y)
      for (int x = 0; x < a.nx(); ++x) {
        const bool va = a.get(x, y, z), vb = b.get(x, y, z);
        ASSERT_EQ(u.get(x, y, z), va || vb);
        ASSERT_EQ(i.get(x, y, z), va && vb);
        ASSERT_EQ(d.get(x, y, z), va && !vb);
      }
}

}  // namespace
}  // namespace vox
