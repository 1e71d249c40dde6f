#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "analysis/distance_lanes.h"
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

// The passes as a processor without AVX2 runs them (analysis_detail::vectorLanes() false) while it lives.
struct ScalarLanes {
  ScalarLanes() { analysis_detail::setVectorLanes(false); }
  ~ScalarLanes() { analysis_detail::setVectorLanes(true); }
};

// Separable brute force of the squared distance to the nearest empty voxel (the grid's outside empty): along X, then
// Y, then Z, each step the smallest (q - p)^2 + value over every position p of the line and two past each end (zeros).
// O(n^2) a line, for grids too large for bruteDistance.
std::vector<uint32_t> separableDistance(const VoxelGrid& g) {
  const int n[3] = {g.nx(), g.ny(), g.nz()};
  std::vector<uint32_t> v(size_t(g.dims().count()));
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        uint32_t best = 0;
        if (g.get(x, y, z)) {
          int64_t d = std::min(x + 1, g.nx() - x);
          for (int p = 0; p < g.nx(); ++p)
            if (!g.get(p, y, z)) d = std::min<int64_t>(d, std::abs(p - x));
          best = uint32_t(d * d);
        }
        v[size_t(g.index(x, y, z))] = best;
      }
  for (int axis = 1; axis < 3; ++axis) {
    std::vector<int64_t> line(size_t(n[axis]));
    const int other = axis == 1 ? 2 : 1;
    for (int o = 0; o < n[other]; ++o)
      for (int x = 0; x < g.nx(); ++x) {
        auto at = [&](int q) -> uint32_t& {
          return axis == 1 ? v[size_t(g.index(x, q, o))] : v[size_t(g.index(x, o, q))];
        };
        for (int q = 0; q < n[axis]; ++q) line[size_t(q)] = at(q);
        for (int q = 0; q < n[axis]; ++q) {
          int64_t best = std::min<int64_t>(int64_t(q + 1) * (q + 1), int64_t(n[axis] - q) * (n[axis] - q));
          for (int p = 0; p < n[axis]; ++p) best = std::min(best, int64_t(q - p) * (q - p) + line[size_t(p)]);
          at(q) = uint32_t(best);
        }
      }
  }
  return v;
}

TEST(Distance, matchesBruteForceOnAssortedGrids) {
  for (bool vector_lanes : {true, false}) {
    SCOPED_TRACE(vector_lanes ? "vector steps where the processor has them" : "scalar steps");
    std::unique_ptr<ScalarLanes> scalar;
    if (!vector_lanes) scalar = std::make_unique<ScalarLanes>();
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
}

// Solids thick enough that most sites of the Y and Z lines are left out of the envelopes (distance_lanes.h), with
// lines longer than a word, tiles of 64 lines and a last tile and group of eight lines cut short: both layouts, with
// the vector steps and without, against the separable brute force.
TEST(Distance, matchesSeparableBruteForceOnThickSolids) {
  std::vector<std::pair<std::string, VoxelGrid>> grids;
  grids.emplace_back("ball", test::ballGrid(Dims{75, 70, 68}, {37.2, 34.9, 33.6}, 33.5));
  {
    VoxelGrid g = test::randomBoxes(Dims{141, 69, 77}, 7, 21);
    const VoxelGrid ball = test::ballGrid(Dims{141, 69, 77}, {90.5, 30.2, 40.7}, 29.0);
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x)
          if (ball.get(x, y, z)) g.set(x, y, z, true);
    grids.emplace_back("boxes and a ball", std::move(g));
  }
  {
    VoxelGrid g = test::ballGrid(Dims{70, 131, 66}, {35.0, 65.0, 33.0}, 32.0);  // a shell with a hole through it
    const VoxelGrid inner = test::ballGrid(Dims{70, 131, 66}, {35.4, 65.3, 32.8}, 26.0);
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x)
          if (inner.get(x, y, z) || (std::abs(x - 20) < 4 && std::abs(z - 40) < 5)) g.set(x, y, z, false);
    grids.emplace_back("shell", std::move(g));
  }
  for (const auto& [what, g] : grids) {
    const std::vector<uint32_t> expect = separableDistance(g);
    const uint32_t mx = *std::max_element(expect.begin(), expect.end());
    for (bool vector_lanes : {true, false}) {
      std::unique_ptr<ScalarLanes> scalar;
      if (!vector_lanes) scalar = std::make_unique<ScalarLanes>();
      for (DistanceLayout layout : {DistanceLayout::kPackedRows, DistanceLayout::kDense}) {
        auto f = computeDistance(g, {}, layout);
        ASSERT_TRUE(f.ok()) << what;
        int64_t mismatches = 0;
        for (int z = 0; z < g.nz(); ++z)
          for (int y = 0; y < g.ny(); ++y)
            for (int x = 0; x < g.nx(); ++x) {
              const uint32_t e = expect[size_t(g.index(x, y, z))];
              if (f->squared(x, y, z) != e && ++mismatches <= 5) {
                ADD_FAILURE() << what << (vector_lanes ? "" : " (scalar)") << " at " << x << "," << y << "," << z
                              << ": " << f->squared(x, y, z) << " expected " << e;
              }
            }
        EXPECT_EQ(mismatches, 0) << what;
        EXPECT_EQ(f->maxSquared(), mx) << what;
      }
    }
  }
}

// Random tiles of kLanes lines whose values look like squared distances (smooth, with ridges, zeros between runs)
// or are noise up to the largest squared distance a grid can hold. `rows` has the kSitePad steps each side.
std::vector<uint32_t> randomTile(int64_t len, std::mt19937& rng, bool noise) {
  using analysis_detail::kLanes, analysis_detail::kSitePad;
  std::vector<uint32_t> rows(size_t((len + 2 * kSitePad) * kLanes), 0);
  std::uniform_int_distribution<uint32_t> big(0, 3u * 8193u * 8193u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int64_t j = 0; j < kLanes; ++j) {
    const double c = u(rng) * double(len), r = 5 + u(rng) * double(len), s = 0.3 + u(rng);
    for (int64_t q = 0; q < len; ++q) {
      uint32_t& v = rows[size_t((q + kSitePad) * kLanes + j)];
      if (noise) {
        v = u(rng) < 0.2 ? 0 : big(rng);
      } else {
        const double d = r - s * std::abs(double(q) - c) + 3 * std::sin(0.3 * double(q + j));
        v = d <= 1 ? 0 : uint32_t(d * d + u(rng) * 4);
      }
    }
  }
  return rows;
}

TEST(DistanceLanes, aSiteLeftOutIsBeatenEverywhereAndTheLowestStay) {
  using analysis_detail::kLanes, analysis_detail::kSitePad;
  std::mt19937 rng(7);
  int64_t left_out = 0, sites = 0;
  for (int round = 0; round < 40; ++round) {
    const int64_t len = 1 + int64_t(rng() % 150);
    const std::vector<uint32_t> rows = randomTile(len, rng, round % 4 == 3);
    const uint32_t* tile = rows.data() + kSitePad * kLanes;
    std::vector<uint64_t> masks(static_cast<size_t>(len)), keep(static_cast<size_t>(len));
    for (auto& m : masks) m = (uint64_t(rng()) << 32 | rng()) | (round % 2 ? ~uint64_t(0) : 0);
    analysis_detail::keepSitesScalar(tile, len, masks.data(), keep.data());
    for (int64_t j = 0; j < kLanes; ++j) {
      auto h = [&](int64_t q) -> int64_t { return q < -kSitePad || q >= len + kSitePad ? 0 : tile[q * kLanes + j]; };
      for (int64_t q = 0; q < len; ++q) {
        const bool asked = (masks[size_t(q)] >> j) & 1, kept = (keep[size_t(q)] >> j) & 1;
        ASSERT_TRUE(asked || !kept) << "a site nobody asked about is kept";
        if (!asked) continue;
        ++sites;
        if (kept) continue;
        ++left_out;
        // beaten strictly at every position near the line (far away the nearest zero past an end beats it)
        for (int64_t p = -len - 20; p < 2 * len + 20; ++p) {
          const int64_t own = (p - q) * (p - q) + h(q);
          bool beaten = false;
          for (int64_t r = -kSitePad - 1; r < len + kSitePad + 1 && !beaten; ++r) {
            beaten = r != q && (p - r) * (p - r) + h(r) < own;
          }
          ASSERT_TRUE(beaten) << "line " << j << " site " << q << " is lowest at " << p;
        }
      }
      // the lowest value at each step over the sites not left out is that over every site
      auto leftOut = [&](int64_t r) {
        return r >= 0 && r < len && ((masks[size_t(r)] >> j) & 1) && !((keep[size_t(r)] >> j) & 1);
      };
      for (int64_t p = 0; p < len; ++p) {
        int64_t all = INT64_MAX, kept = INT64_MAX;
        for (int64_t r = -kSitePad - 1; r < len + kSitePad + 1; ++r) {
          const int64_t v = (p - r) * (p - r) + h(r);
          all = std::min(all, v);
          if (!leftOut(r)) kept = std::min(kept, v);
        }
        ASSERT_EQ(kept, all) << "line " << j << " step " << p;
      }
    }
  }
  EXPECT_GT(left_out, sites / 4) << "the test leaves out few sites: " << left_out << " of " << sites;
}

TEST(DistanceLanes, vectorTestMatchesTheScalarOne) {
  using analysis_detail::kLanes, analysis_detail::kSitePad;
  if (!analysis_detail::vectorLanes()) GTEST_SKIP() << "this processor has no AVX2: the vector steps do not run";
  std::mt19937 rng(11);
  for (int round = 0; round < 200; ++round) {
    const int64_t len = 1 + int64_t(rng() % 700);
    const std::vector<uint32_t> rows = randomTile(len, rng, round % 3 == 2);
    const uint32_t* tile = rows.data() + kSitePad * kLanes;
    std::vector<uint64_t> masks(static_cast<size_t>(len)), keep(masks.size()), expect(masks.size());
    for (auto& m : masks) {
      m = uint64_t(rng()) << 32 | rng();
      if (round % 5 == 0) m &= 0x00ff00000000ff0full;  // groups of eight without a bit are skipped
    }
    analysis_detail::keepSites(tile, len, masks.data(), keep.data());
    analysis_detail::keepSitesScalar(tile, len, masks.data(), expect.data());
    ASSERT_EQ(keep, expect) << "round " << round << ", " << len << " steps";
  }
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
