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

void expectMatchesBruteForce(const VoxelGrid& g, const std::string& what) {
  for (bool to_empty : {true, false}) {
    auto f = to_empty ? computeDistance(g) : computeClearance(g);
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
  EXPECT_LE(f->memoryBytes(), size_t(11 * 11 * 11 * 4));

  auto c = computeClearance(VoxelGrid(Dims{3, 3, 3}));
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(c->squared(1, 1, 1), DistanceField::kInfinite);
  EXPECT_TRUE(std::isinf(c->voxels(1, 1, 1)));
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
