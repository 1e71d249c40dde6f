#include <gtest/gtest.h>

#include <bit>

#include "grids.h"
#include "peel_layers.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

using test::boxGrid;
using test::sameVoxels;

int64_t cube(int64_t s) { return s > 0 ? s * s * s : 0; }

// A cube of side n peels in ceil(n / 2) layers; layer k (0-based) removes (n - 2k)^3 - (n - 2k - 2)^3 voxels.
void expectCubePeel(Dims dims, glm::ivec3 lo, int n) {
  const VoxelGrid g = boxGrid(dims, lo, lo + glm::ivec3(n));
  auto r = test::peelLayers(g, PeelParams{0, true});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(int(r->removed_per_layer.size()), (n + 1) / 2) << n;
  for (int k = 0; k < (n + 1) / 2; ++k) {
    EXPECT_EQ(r->removed_per_layer[size_t(k)], cube(n - 2 * k) - cube(n - 2 * k - 2)) << "n " << n << " layer " << k;
  }
  EXPECT_EQ(r->remaining_count, 0);
  EXPECT_EQ(r->remaining.filledCount(), 0);
  EXPECT_EQ(r->remaining.allocatedLayers(), 0);  // empty layers went back to the shared zero layer
  EXPECT_EQ(r->core_voxels, n % 2 ? 1 : 8);
}

TEST(Peel, cubePeelsInHalfItsSideWithTheFormulaPerLayer) {
  for (int n : {1, 2, 3, 4, 7, 10}) expectCubePeel(Dims{12, 12, 12}, {1, 1, 1}, n);
  expectCubePeel(Dims{70, 70, 70}, {0, 0, 0}, 70);    // fills the grid: the grid boundary is empty space
  expectCubePeel(Dims{140, 80, 80}, {60, 3, 2}, 75);  // crosses word boundaries in x
}

TEST(Peel, oneLayerMatchesBruteForce) {
  for (int nx : {1, 5, 62, 63, 64, 65, 126, 130}) {
    for (const VoxelGrid& g : {test::randomGrid(Dims{nx, 8, 9}, 0.8, uint32_t(nx)),
                               test::randomBoxes(Dims{nx, 20, 17}, 6, uint32_t(7 * nx))}) {
      int64_t removed = -1, expect_removed = -1;
      const VoxelGrid got = peelOneLayer(g, &removed);
      const VoxelGrid expect = test::brutePeel(g, &expect_removed);
      EXPECT_TRUE(sameVoxels(got, expect)) << nx;
      EXPECT_EQ(removed, expect_removed) << nx;
      EXPECT_EQ(got.filledCount(), g.filledCount() - removed);
    }
  }
}

TEST(Peel, doesNotModifyItsInput) {
  const VoxelGrid g = boxGrid(Dims{20, 20, 20}, {2, 2, 2}, {18, 18, 18});
  const VoxelGrid copy = g;  // shares the layers
  auto r = test::peelLayers(g, PeelParams{3, false});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(g.filledCount(), 16 * 16 * 16);
  for (int z = 0; z < 20; ++z) EXPECT_TRUE(g.sharesLayerWith(copy, z));
  EXPECT_EQ(r->remaining.filledCount(), 10 * 10 * 10);
}

TEST(Peel, nLayersEqualsNSuccessiveSingleLayers) {
  const VoxelGrid g = test::randomBoxes(Dims{90, 40, 30}, 8, 42);
  VoxelGrid step = g;
  std::vector<int64_t> removed;
  for (int k = 0; k < 5; ++k) {
    int64_t r = 0;
    step = peelOneLayer(step, &r);
    if (r == 0) break;
    removed.push_back(r);
  }
  auto res = test::peelLayers(g, PeelParams{5, false});
  ASSERT_TRUE(res.ok());
  EXPECT_EQ(res->removed_per_layer, removed);
  EXPECT_TRUE(sameVoxels(res->remaining, step));
  EXPECT_EQ(res->remaining_count, step.filledCount());
  EXPECT_EQ(res->core_voxels, removed.back());
}

TEST(Peel, allLayersRemoveEverythingAndReportTheCore) {
  const VoxelGrid g = test::randomBoxes(Dims{66, 50, 40}, 10, 9);
  auto r = test::peelLayers(g, PeelParams{0, true});
  ASSERT_TRUE(r.ok());
  int64_t sum = 0;
  for (int64_t v : r->removed_per_layer) {
    EXPECT_GT(v, 0);
    sum += v;
  }
  EXPECT_EQ(sum, g.filledCount());
  EXPECT_EQ(r->remaining_count, 0);
  EXPECT_EQ(r->core_voxels, r->removed_per_layer.back());
}

TEST(Peel, moreLayersThanTheModelHasStopsWhenEmpty) {
  const VoxelGrid g = boxGrid(Dims{8, 8, 8}, {0, 0, 0}, {4, 4, 4});
  auto r = test::peelLayers(g, PeelParams{10, false});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->removed_per_layer, (std::vector<int64_t>{56, 8}));
  EXPECT_EQ(r->remaining_count, 0);
}

TEST(Peel, zeroLayersKeepsTheModelAndNegativeIsAnError) {
  const VoxelGrid g = boxGrid(Dims{8, 8, 8}, {0, 0, 0}, {4, 4, 4});
  auto r = test::peelLayers(g, PeelParams{0, false});
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r->removed_per_layer.empty());
  EXPECT_EQ(r->remaining_count, 64);
  auto bad = test::peelLayers(g, PeelParams{-1, false});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidArgument);
}

TEST(Peel, progressCanCancel) {
  const VoxelGrid g = boxGrid(Dims{30, 30, 30}, {0, 0, 0}, {30, 30, 30});
  int calls = 0;
  auto r = test::peelLayers(g, PeelParams{0, true}, [&](double f) {
    EXPECT_GE(f, 0.0);
    EXPECT_LE(f, 1.0);
    return ++calls < 3;
  });
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kCancelled);
  EXPECT_EQ(calls, 3);
  auto d = computeDepthMap(g, kPeelAll, [](double) { return false; });
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error().code, ErrorCode::kCancelled);
}

TEST(DepthMap, remainingAfterKEqualsKSuccessivePeels) {
  for (const VoxelGrid& g : {test::randomBoxes(Dims{100, 45, 38}, 12, 5), test::randomGrid(Dims{65, 9, 10}, 0.9, 3),
                             test::ballGrid(Dims{40, 40, 40}, glm::dvec3(20.0), 17.3)}) {
    auto d = computeDepthMap(g);
    ASSERT_TRUE(d.ok());
    EXPECT_TRUE(d->complete());
    VoxelGrid step = g;
    std::vector<int64_t> removed;
    for (int k = 0;; ++k) {
      const VoxelGrid rem = d->remainingAfter(k);
      ASSERT_TRUE(sameVoxels(rem, step)) << "k " << k;
      EXPECT_EQ(rem.filledCount(), step.filledCount());
      int64_t r = 0;
      const VoxelGrid next = peelOneLayer(step, &r);
      if (r == 0) break;
      removed.push_back(r);
      // removedBy(k + 1) is exactly what the (k + 1)-th peel took away.
      const VoxelGrid by = d->removedBy(k + 1);
      EXPECT_EQ(by.filledCount(), r);
      auto diff = booleanOp(step, next, BoolOp::kDifference);
      ASSERT_TRUE(diff.ok());
      EXPECT_TRUE(sameVoxels(by, *diff)) << "k " << k + 1;
      step = next;
    }
    EXPECT_EQ(d->removedPerLayer(), removed);
    EXPECT_EQ(d->layers(), int(removed.size()));
    EXPECT_EQ(d->coreVoxels(), removed.back());
    EXPECT_EQ(d->remainingAfter(d->layers()).filledCount(), 0);
    EXPECT_EQ(d->remainingAfter(d->layers() + 5).filledCount(), 0);
    EXPECT_EQ(d->removedBy(0).filledCount(), 0);
    EXPECT_EQ(d->removedBy(d->layers() + 1).filledCount(), 0);
  }
}

TEST(DepthMap, depthIsTheL1DistanceToEmptySpace) {
  // Repeated 6-neighbour erosion removes a voxel at the layer equal to its L1 distance to the nearest empty voxel
  // (outside the grid counts as empty).
  const VoxelGrid g = test::randomBoxes(Dims{30, 25, 20}, 6, 77);
  auto d = computeDepthMap(g);
  ASSERT_TRUE(d.ok());
  std::vector<glm::ivec3> empties;
  for (int z = -1; z <= g.nz(); ++z)
    for (int y = -1; y <= g.ny(); ++y)
      for (int x = -1; x <= g.nx(); ++x)
        if (!g.get(x, y, z)) empties.emplace_back(x, y, z);
  for (int z = 0; z < g.nz(); z += 3)
    for (int y = 0; y < g.ny(); y += 2)
      for (int x = 0; x < g.nx(); ++x) {
        if (!g.get(x, y, z)) {
          EXPECT_EQ(d->depthAt(x, y, z), 0);
          continue;
        }
        int64_t best = INT64_MAX;
        for (const glm::ivec3& e : empties) best = std::min(best, cellDistance(e, glm::ivec3(x, y, z)));
        ASSERT_EQ(d->depthAt(x, y, z), best) << x << "," << y << "," << z;
      }
}

TEST(DepthMap, stoppedByMaxLayersKeepsTheRest) {
  const VoxelGrid g = boxGrid(Dims{20, 20, 20}, {0, 0, 0}, {20, 20, 20});
  auto d = computeDepthMap(g, PeelParams{3, false});
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->layers(), 3);
  EXPECT_FALSE(d->complete());
  EXPECT_EQ(d->remainingAfter(3).filledCount(), 14 * 14 * 14);
  EXPECT_EQ(d->remainingAfter(99).filledCount(), 14 * 14 * 14);
  EXPECT_EQ(d->remainingAfter(2).filledCount(), 16 * 16 * 16);
  EXPECT_EQ(d->depthAt(10, 10, 10), 0);  // not reached
  EXPECT_EQ(d->depthAt(2, 5, 5), 3);
  EXPECT_GT(d->memoryBytes(), 0u);
}

TEST(DepthMap, bitPlanesStayCompact) {
  // 60^3 solid cube: 30 layers need five bit planes, whatever the number of layers.
  const VoxelGrid g = boxGrid(Dims{60, 60, 60}, {0, 0, 0}, {60, 60, 60});
  auto d = computeDepthMap(g);
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->layers(), 30);
  EXPECT_LE(d->memoryBytes(), 5 * g.memoryBytes() + 4096);
  EXPECT_EQ(d->depthAt(29, 30, 30), 30);
  EXPECT_EQ(d->depthAt(0, 30, 30), 1);
}

TEST(DepthMap, emptyInputs) {
  auto d = computeDepthMap(VoxelGrid(Dims{5, 5, 5}));
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->layers(), 0);
  EXPECT_EQ(d->coreVoxels(), 0);
  EXPECT_EQ(d->remainingAfter(1).filledCount(), 0);
  auto e = computeDepthMap(VoxelGrid());
  ASSERT_TRUE(e.ok());
  EXPECT_EQ(e->layers(), 0);
}

// The window shows this bound before it computes the skin layers and refuses past the memory limit: it must hold
// for what the depth map really keeps (its bit planes), and stay a small multiple of the grid.
TEST(DepthMap, memoryEstimateBoundsWhatTheMapHolds) {
  const VoxelGrid g = test::ballGrid(Dims{60, 50, 40}, glm::dvec3(30, 25, 20), 18.5);
  const uint64_t estimate = estimateDepthMapBytes(g);
  // Deepest possible layer: ceil(40 / 2) = 20, 5 bit planes, plus the two grids of the peel in progress.
  EXPECT_EQ(estimate, 7 * uint64_t(g.memoryBytes()));
  auto d = computeDepthMap(g);
  ASSERT_TRUE(d.ok());
  EXPECT_LE(d->memoryBytes(), estimate);
  EXPECT_LE(size_t(std::bit_width(uint32_t(d->layers()))), 5u);
  EXPECT_EQ(estimateDepthMapBytes(VoxelGrid()), 0u);
}

}  // namespace
}  // namespace vox
