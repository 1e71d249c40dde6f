#include "vox/core/voxel_grid.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "vox/core/grid_placement.h"
#include "vox/core/neighbour_code.h"
#include "vox/core/surface.h"

namespace vox {
namespace {

VoxelGrid box(Dims d, glm::ivec3 lo, glm::ivec3 hi) {  // filled box [lo, hi)
  VoxelGrid g(d);
  for (int z = lo.z; z < hi.z; ++z)
    for (int y = lo.y; y < hi.y; ++y) g.fillRun(y, z, lo.x, hi.x);
  return g;
}

TEST(VoxelGrid, newGridIsEmptyAndAllocatesNoLayers) {
  VoxelGrid g(Dims{10, 20, 30});
  EXPECT_EQ(g.filledCount(), 0);
  EXPECT_EQ(g.allocatedLayers(), 0);
  EXPECT_FALSE(g.get(0, 0, 0));
  EXPECT_FALSE(g.get(-1, -1, -1));  // padding reads as empty
  EXPECT_FALSE(g.get(10, 20, 30));
}

// A grid of these dims whose every layer word (padding included) was set, then freed: its layers' memory is left
// dirty for the next grid. `fresh`: the layers taken as freshLayerWords takes them, else as mutableLayerWords does.
void dirtyAndFree(Dims d, bool fresh) {
  VoxelGrid dirty(d);
  for (int32_t z = 0; z < d.nz; ++z) {
    uint64_t* w = fresh ? dirty.freshLayerWords(z) : dirty.mutableLayerWords(z);
    std::fill(w, w + dirty.wordsPerLayer(), ~uint64_t(0));
  }
}

// Every word of every layer of g, taken as freshLayerWords or mutableLayerWords takes it, is zero.
::testing::AssertionResult layersAreZero(VoxelGrid& g, bool fresh) {
  for (int32_t z = 0; z < g.nz(); ++z) {
    const uint64_t* w = fresh ? g.freshLayerWords(z) : g.mutableLayerWords(z);
    if (!std::all_of(w, w + g.wordsPerLayer(), [](uint64_t x) { return x == 0; })) {
      return ::testing::AssertionFailure() << g.nx() << " x " << g.ny() << ", layer " << z << " is not zero";
    }
  }
  return ::testing::AssertionSuccess();
}

// Layers come from calloc without being written (so untouched pages are never faulted in): a new layer must read
// as zero even where its memory was just used and freed by another grid, at small sizes (reused heap chunks) and
// large ones (whole layers handed back by the allocator).
TEST(VoxelGrid, newLayersAreZeroEvenInReusedMemory) {
  for (const Dims d : {Dims{40, 30, 6}, Dims{1000, 700, 4}}) {
    for (int round = 0; round < 3; ++round) {
      dirtyAndFree(d, false);
      VoxelGrid fresh(d);
      ASSERT_TRUE(layersAreZero(fresh, false)) << "round " << round;
      EXPECT_EQ(fresh.filledCount(), 0);
    }
  }
}

TEST(VoxelGrid, setResetAndReadBackEveryCornerAndWordBoundary) {
  VoxelGrid g(Dims{130, 3, 2});  // 132 padded bits: three words per row
  for (int x : {0, 1, 62, 63, 64, 65, 126, 127, 128, 129}) {
    g.set(x, 2, 1);
    EXPECT_TRUE(g.get(x, 2, 1)) << x;
    EXPECT_FALSE(g.get(x, 1, 1)) << x;
  }
  EXPECT_EQ(g.filledCount(), 10);
  g.reset(63, 2, 1);
  EXPECT_FALSE(g.get(63, 2, 1));
  EXPECT_EQ(g.filledCount(), 9);
  EXPECT_EQ(g.allocatedLayers(), 1);  // only layer z = 1 holds voxels
}

TEST(VoxelGrid, resetOnEmptyLayerDoesNotAllocate) {
  VoxelGrid g(Dims{4, 4, 4});
  g.reset(1, 1, 1);
  EXPECT_EQ(g.allocatedLayers(), 0);
}

TEST(VoxelGrid, fillRunMatchesPerVoxelSetsAcrossWords) {
  for (auto [x0, x1] : std::vector<std::pair<int, int>>{{0, 1}, {0, 200}, {5, 63}, {62, 66}, {63, 64}, {127, 190}}) {
    VoxelGrid a(Dims{200, 1, 1}), b(Dims{200, 1, 1});
    a.fillRun(0, 0, x0, x1);
    for (int x = x0; x < x1; ++x) b.set(x, 0, 0);
    for (int x = -1; x <= 200; ++x) ASSERT_EQ(a.get(x, 0, 0), b.get(x, 0, 0)) << x0 << ".." << x1 << " at " << x;
    EXPECT_EQ(a.filledCount(), x1 - x0);
  }
}

TEST(VoxelGrid, fillRunClampsToGridAndKeepsPaddingEmpty) {
  VoxelGrid g(Dims{64, 1, 1});
  g.fillRun(0, 0, -5, 500);
  EXPECT_EQ(g.filledCount(), 64);
  EXPECT_FALSE(g.get(-1, 0, 0));
  EXPECT_FALSE(g.get(64, 0, 0));
}

TEST(VoxelGrid, indexUses64BitArithmeticAt4096Cubed) {
  VoxelGrid g(Dims{4096, 4096, 4096});
  const int64_t last = g.index(4095, 4095, 4095);
  EXPECT_EQ(last, int64_t(4096) * 4096 * 4096 - 1);
  EXPECT_EQ(g.coordinates(last), glm::ivec3(4095, 4095, 4095));
  EXPECT_EQ(g.coordinates(g.index(7, 4000, 3000)), glm::ivec3(7, 4000, 3000));
  g.set(4095, 4095, 4095);  // allocates one layer of 4098 rows x 65 words
  EXPECT_TRUE(g.get(4095, 4095, 4095));
  EXPECT_EQ(g.allocatedLayers(), 1);
}

TEST(VoxelGrid, neighbourCodeBitsFollowSpecOrder) {
  // Centre voxel with exactly one neighbour at a time: each direction sets its own bit
  // (docs/conventions.md, "Face-neighbour code").
  struct Case {
    glm::ivec3 offset;
    uint8_t bit;
  };
  for (Case c : {Case{{0, -1, 0}, 32}, Case{{-1, 0, 0}, 16}, Case{{1, 0, 0}, 8}, Case{{0, 1, 0}, 4},
                 Case{{0, 0, -1}, 2}, Case{{0, 0, 1}, 1}}) {
    VoxelGrid g(Dims{3, 3, 3});
    g.set(1, 1, 1);
    g.set(1 + c.offset.x, 1 + c.offset.y, 1 + c.offset.z);
    EXPECT_EQ(g.neighbourCode(1, 1, 1), c.bit);
  }
  VoxelGrid full = box(Dims{3, 3, 3}, {0, 0, 0}, {3, 3, 3});
  EXPECT_EQ(full.neighbourCode(1, 1, 1), kCodeInterior);
  EXPECT_EQ(full.neighbourCode(0, 0, 0), kCodeXPlus | kCodeYPlus | kCodeZPlus);  // border: outside is empty
}

TEST(NeighbourCode, classicTableMatchesSpecEntries) {
  EXPECT_EQ(classicIntensity(0), 20);
  EXPECT_EQ(classicIntensity(2), 20);
  EXPECT_EQ(classicIntensity(28), 20);  // the misprinted second "2"
  EXPECT_EQ(classicIntensity(29), 10);
  EXPECT_EQ(classicIntensity(53), 19);
  EXPECT_EQ(classicIntensity(62), 17);  // table rules over Figure 5.2
  EXPECT_EQ(freeFaces(0), 6);
  EXPECT_EQ(freeFaces(62), 1);
  EXPECT_EQ(freeFaces(63), 0);
}

TEST(VoxelGrid, neighbourAtAndCellDistances) {
  VoxelGrid g(Dims{5, 5, 5});
  EXPECT_EQ(g.neighbourAt({2, 2, 2}, Direction::kXPlus, 2), glm::ivec3(4, 2, 2));
  EXPECT_EQ(g.neighbourAt({2, 2, 2}, Direction::kYMinus, 2), glm::ivec3(2, 0, 2));
  EXPECT_FALSE(g.neighbourAt({2, 2, 2}, Direction::kZPlus, 3).has_value());
  EXPECT_EQ(cellDistance({0, 0, 0}, {3, -4, 5}), 12);
  EXPECT_EQ(chebyshevDistance({0, 0, 0}, {3, -4, 5}), 5);
}

// Layers of at least 32 KiB freed by one grid are kept for reuse by freshLayerWords and copies on write: what they
// held must never show through.
TEST(VoxelGrid, layersMadeFromFreedLayersHoldOnlyTheirOwnWords) {
  const Dims d{1000, 700, 4};  // 16 words x 702 rows a layer
  for (int round = 0; round < 3; ++round) {
    dirtyAndFree(d, true);
    VoxelGrid fresh(d);
    ASSERT_TRUE(layersAreZero(fresh, true)) << "round " << round;
    dirtyAndFree(d, true);
    VoxelGrid a = box(d, {3, 5, 0}, {900, 600, 4});
    VoxelGrid b = a;
    b.reset(10, 10, 2);  // copy on write of layer 2, into storage another grid freed
    EXPECT_EQ(b.filledCount(), a.filledCount() - 1);
    EXPECT_FALSE(b.get(10, 10, 2));
    EXPECT_TRUE(b.get(11, 10, 2));
    EXPECT_FALSE(b.get(2, 10, 2));
  }
}

TEST(VoxelGrid, copiesShareLayersUntilWritten) {
  VoxelGrid a = box(Dims{8, 8, 8}, {1, 1, 1}, {7, 7, 7});
  VoxelGrid b = a;  // snapshot
  for (int z = 0; z < 8; ++z) EXPECT_TRUE(a.sharesLayerWith(b, z)) << z;
  b.reset(3, 3, 3);
  EXPECT_TRUE(a.get(3, 3, 3));  // the snapshot keeps its data
  EXPECT_FALSE(b.get(3, 3, 3));
  EXPECT_FALSE(a.sharesLayerWith(b, 3));
  EXPECT_TRUE(a.sharesLayerWith(b, 4));
  EXPECT_EQ(a.filledCount(), 216);
  EXPECT_EQ(b.filledCount(), 215);
}

// sameVoxels: the same dims and filled voxels, whether the layers are shared or not; one voxel, or the dims, differ.
TEST(VoxelGrid, sameVoxelsComparesTheFilledVoxelsSharedOrNot) {
  const VoxelGrid a = box(Dims{70, 9, 8}, {1, 1, 1}, {69, 7, 7});
  VoxelGrid b = a;  // all layers shared
  EXPECT_TRUE(a.sameVoxels(b));
  const VoxelGrid c = box(Dims{70, 9, 8}, {1, 1, 1}, {69, 7, 7});  // the same voxels, its own layers
  EXPECT_TRUE(a.sameVoxels(c));
  EXPECT_FALSE(a.sharesLayerWith(c, 3));
  b.reset(68, 6, 6);  // the last voxel of the last filled row and layer, past the first word
  EXPECT_FALSE(a.sameVoxels(b));
  EXPECT_FALSE(b.sameVoxels(a));
  b.set(68, 6, 6);
  EXPECT_TRUE(a.sameVoxels(b));  // written back: not shared, the same voxels
  EXPECT_FALSE(a.sharesLayerWith(b, 6));
  EXPECT_FALSE(a.sameVoxels(box(Dims{70, 9, 9}, {1, 1, 1}, {69, 7, 7})));  // one empty layer more
  EXPECT_TRUE(VoxelGrid(Dims{4, 4, 4}).sameVoxels(VoxelGrid(Dims{4, 4, 4})));
}

TEST(VoxelGrid, clearAndReleaseEmptyLayers) {
  VoxelGrid g = box(Dims{8, 8, 8}, {0, 0, 2}, {8, 8, 4});
  EXPECT_EQ(g.allocatedLayers(), 2);
  const size_t full = g.memoryBytes();
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) g.reset(x, y, 3);
  g.releaseEmptyLayers();
  EXPECT_EQ(g.allocatedLayers(), 1);
  EXPECT_LT(g.memoryBytes(), full);
  g.clear();
  EXPECT_EQ(g.filledCount(), 0);
  EXPECT_EQ(g.allocatedLayers(), 0);
  EXPECT_EQ(g.dims(), (Dims{8, 8, 8}));
}

TEST(Surface, cubeSurfaceCountAndCodesMatchBruteForce) {
  VoxelGrid g = box(Dims{70, 9, 9}, {1, 1, 1}, {69, 8, 8});  // spans two words per row
  g.reset(30, 4, 4);                                         // an interior cavity adds six surface voxels
  int64_t brute = 0;
  for (int z = 0; z < 9; ++z)
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 70; ++x)
        if (g.get(x, y, z) && g.neighbourCode(x, y, z) != kCodeInterior) ++brute;
  EXPECT_EQ(countSurfaceVoxels(g), brute);
  int64_t visited = 0;
  forEachSurfaceVoxel(g, [&](int32_t x, int32_t y, int32_t z, uint8_t code) {
    ++visited;
    ASSERT_TRUE(g.get(x, y, z));
    ASSERT_EQ(code, g.neighbourCode(x, y, z)) << x << "," << y << "," << z;
  });
  EXPECT_EQ(visited, brute);
  const int64_t shell = 68 * 7 * 7 - 66 * 5 * 5;
  EXPECT_EQ(brute, shell + 6);
}

TEST(GridPlacement, longestAxisHasExactlyRVoxels) {
  Box3d b;
  b.expand({0.1371, 0.2459, 0.3187});
  b.expand({1.3716, 1.4804, 1.5532});
  for (int r : {1, 64, 100, 128, 1000, 4096}) {
    auto p = placeGridByResolution(b, r);
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(std::max({p->dims.nx, p->dims.ny, p->dims.nz}), r);
    EXPECT_DOUBLE_EQ(p->frame.voxel_size, (1.5532 - 0.3187) / r);
  }
  Box3d flat;
  flat.expand({0, 0, 0});
  flat.expand({203.2, 304.8, 0});
  auto p = placeGridByResolution(flat, 100);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p->dims, (Dims{67, 100, 1}));  // a zero-thickness axis still has one voxel
}

TEST(GridPlacement, rejectsAbsurdRequestsWithReasons) {
  Box3d b;
  b.expand({0, 0, 0});
  b.expand({1, 2, 3});
  auto zero = placeGridByResolution(b, 0);
  ASSERT_FALSE(zero.ok());
  EXPECT_EQ(zero.error().message, "resolution 0 is out of range (1 to 16384)");
  EXPECT_FALSE(placeGridByResolution(b, 16385).ok());
  EXPECT_FALSE(placeGridByVoxelSize(b, -1.0).ok());
  auto tiny = placeGridByVoxelSize(b, 1e-9);
  ASSERT_FALSE(tiny.ok());
  EXPECT_EQ(tiny.error().code, ErrorCode::kLimit);
  auto ok = placeGridByVoxelSize(b, 0.1);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok->dims, (Dims{10, 20, 30}));
  EXPECT_FALSE(placeGridByResolution(Box3d{}, 10).ok());
}

TEST(VoxelGrid, estimateGridBytesCoversAllocatedLayers) {
  VoxelGrid g = box(Dims{100, 50, 10}, {0, 0, 0}, {100, 50, 10});
  EXPECT_GE(estimateGridBytes(g.dims()), uint64_t(g.wordsPerLayer()) * 8 * 10);
  EXPECT_LE(g.memoryBytes(), estimateGridBytes(g.dims()) + 4096);
}

}  // namespace
}  // namespace vox
