#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "grids.h"
#include "vox/analysis/distance.h"

namespace vox {
namespace {

// Brute force (SPEC section 6): for every voxel of the grid, the smallest squared distance to a voxel of the other
// kind; for filled voxels the one-voxel border around the grid counts as empty.
std::vector<uint32_t> bruteDistance(const VoxelGrid& g, bool to_empty) {
  std::vector<glm::ivec3> sites;
  for (int z = -1; z <= g.nz(); ++z)
    for (int y = -1; y <= g.ny(); ++y)
      for (int x = -1; x <= g.nx(); ++x) {
        const bool filled = g.inBounds(x, y, z) && g.get(x, y, z);
        if (to_empty ? !filled : filled) sites.emplace_back(x, y, z);
      }
  std::vector<uint32_t> out(size_t(g.dims().count()), 0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        if (g.get(x, y, z) != to_empty) continue;  // a site of its own: 0
        uint32_t best = DistanceField::kInfinite;
        for (const glm::ivec3& s : sites) {
          const int64_t dx = s.x - x, dy = s.y - y, dz = s.z - z;
          best = std::min<uint32_t>(best, uint32_t(dx * dx + dy * dy + dz * dz));
        }
        out[size_t(g.index(x, y, z))] = best;
      }
  return out;
}

// The distance in both layouts (packed rows, dense) and the clearance.
void expectMatchesBruteForce(const VoxelGrid& g, const std::string& what) {
  for (int kind : {0, 1, 2}) {
    const bool to_empty = kind < 2;
    auto f = kind == 0   ? computeDistance(g)
             : kind == 1 ? computeDistance(g, {}, DistanceLayout::kDense)
                         : computeClearance(g);
    ASSERT_TRUE(f.ok()) << what;
    const std::vector<uint32_t> expect = bruteDistance(g, to_empty);
    uint32_t mx = 0;
    int64_t mismatches = 0;
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x) {
          const uint32_t e = expect[size_t(g.index(x, y, z))];
          if (e != DistanceField::kInfinite) mx = std::max(mx, e);
          if (f->squared(x, y, z) != e && ++mismatches <= 5) {
            ADD_FAILURE() << what << (to_empty ? " distance" : " clearance") << " at " << x << "," << y << "," << z
                          << ": " << f->squared(x, y, z) << " expected " << e;
          }
        }
    EXPECT_EQ(mismatches, 0) << what;
    EXPECT_EQ(f->maxSquared(), mx) << what << (to_empty ? " distance" : " clearance");
  }
}

TEST(Distance, matchesBruteForceOnAssortedGrids) {
  expectMatchesBruteForce(VoxelGrid(Dims{7, 5, 3}), "empty");
  {
    VoxelGrid g(Dims{9, 7, 5});
    test::fillBox(g, {0, 0, 0}, {9, 7, 5});
    expectMatchesBruteForce(g, "full");
  }
  {
    VoxelGrid g(Dims{1, 1, 1});
    g.set(0, 0, 0);
    expectMatchesBruteForce(g, "single voxel grid");
  }
  {
    VoxelGrid g(Dims{11, 13, 9});
    g.set(5, 6, 4);
    expectMatchesBruteForce(g, "single voxel");
  }
  {
    VoxelGrid g(Dims{13, 11, 7});
    test::fillBox(g, {0, 2, 0}, {13, 9, 4});  // touches the grid's x and z borders
    expectMatchesBruteForce(g, "box on the border");
  }
  expectMatchesBruteForce(test::ballGrid(Dims{15, 17, 13}, {7.3, 8.1, 6.2}, 6.4), "ball");
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    expectMatchesBruteForce(test::randomBoxes(Dims{17, 9 + int(seed), 11}, 5, seed), "boxes " + std::to_string(seed));
    expectMatchesBruteForce(test::randomGrid(Dims{9, 7, 5 + int(seed)}, 0.3 * seed, seed),
                            "noise " + std::to_string(seed));
  }
  // rows longer than a word, a box that does not start at the grid origin
  expectMatchesBruteForce(test::randomBoxes(Dims{70, 6, 5}, 4, 11), "boxes across words");
  expectMatchesBruteForce(test::randomGrid(Dims{130, 3, 4}, 0.85, 12), "noise across words");
  expectMatchesBruteForce(test::ballGrid(Dims{1, 19, 1}, {0.5, 9.5, 0.5}, 7.0), "a line");
  // lines along Y and Z longer than one and two words (the passes find their pieces in words of 64 steps)
  expectMatchesBruteForce(test::randomBoxes(Dims{5, 140, 4}, 4, 13), "boxes along y");
  expectMatchesBruteForce(test::randomBoxes(Dims{4, 5, 150}, 4, 14), "boxes along z");
  expectMatchesBruteForce(test::randomGrid(Dims{3, 67, 66}, 0.85, 15), "noise in long y and z lines");
  expectMatchesBruteForce(test::ballGrid(Dims{3, 3, 131}, {1.5, 1.5, 65.5}, 64.0), "a line along z");
}

TEST(Distance, boxIsTheFilledBoundingBoxAndValuesHaveUnits) {
  GridFrame frame;
  frame.voxel_size = 0.5;
  VoxelGrid g(Dims{40, 30, 20}, frame);
  test::fillBox(g, {10, 5, 3}, {21, 16, 14});  // an 11-voxel cube: centre at depth 6
  auto f = computeDistance(g);
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f->boxMin(), glm::ivec3(10, 5, 3));
  EXPECT_EQ(f->boxDims(), (Dims{11, 11, 11}));
  EXPECT_EQ(f->squared(15, 10, 8), 36u);
  EXPECT_DOUBLE_EQ(f->voxels(15, 10, 8), 6.0);
  EXPECT_DOUBLE_EQ(f->model(15, 10, 8), 3.0);
  EXPECT_DOUBLE_EQ(f->maxModel(), 3.0);
  EXPECT_EQ(f->squared(0, 0, 0), 0u);  // outside the box
  EXPECT_EQ(f->squared(10, 5, 3), 1u);
  EXPECT_EQ(f->storedValues(), 11 * 11 * 11);  // every row of a cube is filled from end to end

  auto c = computeClearance(VoxelGrid(Dims{3, 3, 3}));
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->squared(1, 1, 1), DistanceField::kInfinite);
  EXPECT_TRUE(std::isinf(c->voxels(1, 1, 1)));
}

// A distance field keeps each row's span of filled voxels; the voxels of the box outside it read 0, and the dense copy
// and the field computed dense hold the same values in box order. A clearance field is dense.
TEST(Distance, packedRowsHoldEachRowsSpanOfFilledVoxels) {
  VoxelGrid g = test::ballGrid(Dims{41, 37, 33}, {20.0, 18.0, 16.0}, 15.0);
  test::fillBox(g, {30, 2, 3}, {31, 3, 4});  // a voxel apart from the ball, in a row of its own
  auto f = computeDistance(g);
  ASSERT_TRUE(f.ok());
  EXPECT_FALSE(f->isDense());
  const glm::ivec3 lo = f->boxMin();
  const Dims d = f->boxDims();
  int64_t filled_rows = 0, stored = 0;
  for (int32_t z = 0; z < d.nz; ++z)
    for (int32_t y = 0; y < d.ny; ++y) {
      int32_t first = -1, last = -1;
      for (int32_t x = 0; x < d.nx; ++x)
        if (g.get(lo.x + x, lo.y + y, lo.z + z)) {
          if (first < 0) first = x;
          last = x;
        }
      const DistanceField::Row r = f->row(y, z);
      if (first < 0) {
        EXPECT_EQ(r.hi - r.lo, 0) << "row " << y << ", " << z;
        continue;
      }
      ++filled_rows;
      stored += last + 1 - first;
      EXPECT_EQ(r.lo, first) << "row " << y << ", " << z;
      EXPECT_EQ(r.hi, last + 1) << "row " << y << ", " << z;
    }
  EXPECT_GT(filled_rows, 0);
  EXPECT_EQ(f->storedValues(), stored);
  EXPECT_LT(f->storedValues(), d.count() * 3 / 5);  // a ball fills about half its box's rows' length
  EXPECT_EQ(f->squared(lo.x, lo.y, lo.z), 0u);      // a box corner outside the ball: outside its row's span

  auto computed = computeDistance(g, {}, DistanceLayout::kDense);
  ASSERT_TRUE(computed.ok());
  EXPECT_TRUE(computed->isDense());
  EXPECT_EQ(computed->maxSquared(), f->maxSquared());
  const DistanceField dense = f->denseCopy();
  ASSERT_NE(dense.data(), nullptr);
  EXPECT_TRUE(dense.isDense());
  EXPECT_EQ(dense.storedValues(), d.count());
  EXPECT_EQ(dense.maxSquared(), f->maxSquared());
  int64_t mismatches = 0;
  for (int32_t z = 0; z < g.nz(); ++z)
    for (int32_t y = 0; y < g.ny(); ++y)
      for (int32_t x = 0; x < g.nx(); ++x) {
        const uint32_t v = f->squared(x, y, z);
        EXPECT_EQ(v != 0, g.get(x, y, z));
        if (dense.squared(x, y, z) != v) ++mismatches;
        if (dense.inBox(x, y, z) && dense.data()[dense.boxIndex(x, y, z)] != v) ++mismatches;
        if (computed->inBox(x, y, z) && computed->data()[computed->boxIndex(x, y, z)] != v) ++mismatches;
        if (computed->squared(x, y, z) != v) ++mismatches;
      }
  EXPECT_EQ(mismatches, 0);

  auto c = computeClearance(g);
  ASSERT_TRUE(c.ok());
  EXPECT_TRUE(c->isDense());
}

TEST(Distance, cancels) {
  const VoxelGrid g = test::ballGrid(Dims{40, 40, 40}, {20, 20, 20}, 15);
  int calls = 0;
  auto f = computeDistance(g, [&](double) { return ++calls < 3; });
  ASSERT_FALSE(f.ok());
  EXPECT_EQ(f.error().code, ErrorCode::kCancelled);
  double last = -1;
  bool monotone = true;
  auto ok = computeDistance(g, [&](double p) {
    monotone = monotone && p >= last - 1e-12;
    last = p;
    return true;
  });
  ASSERT_TRUE(ok.ok());
  EXPECT_DOUBLE_EQ(last, 1.0);
}

TEST(Distance, peelByDistanceLeavesTheInnerBall) {
  GridFrame frame;
  frame.voxel_size = 0.1;
  const glm::dvec3 c(20.0, 20.0, 20.0);  // a voxel corner: the ball is symmetric
  const VoxelGrid g = test::ballGrid(Dims{40, 40, 40}, c, 15.0, frame);
  for (double d : {0.0, 0.35, 0.5, 1.0}) {
    auto r = peelByDistance(g, d);
    ASSERT_TRUE(r.ok());
    auto dist = computeDistance(g);
    ASSERT_TRUE(dist.ok());
    int64_t kept = 0, max_r2 = 0;
    for (int z = 0; z < 40; ++z)
      for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
          const bool in = g.get(x, y, z), out = r->get(x, y, z);
          ASSERT_EQ(out, in && dist->model(x, y, z) > d) << x << "," << y << "," << z << " d " << d;
          if (out) {
            ++kept;
            const glm::dvec3 p(x + 0.5, y + 0.5, z + 0.5);
            const glm::dvec3 q = p - c;
            max_r2 = std::max<int64_t>(max_r2, int64_t(std::llround(4 * (q.x * q.x + q.y * q.y + q.z * q.z))));
          }
        }
    // what is left is a ball of radius 15 - d / h, within one voxel
    const double left = std::sqrt(double(max_r2) / 4.0);
    EXPECT_NEAR(left, 15.0 - d / 0.1, 1.0) << d;
    EXPECT_GT(kept, 0);
  }
  EXPECT_EQ(peelByDistance(g, 0.0)->filledCount(), g.filledCount());
  EXPECT_FALSE(peelByDistance(g, -1.0).ok());
  EXPECT_EQ(peelByDistance(g, 10.0)->filledCount(), 0);
}

}  // namespace
}  // namespace vox
