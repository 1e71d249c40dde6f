#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "grids.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/thickness.h"

namespace vox {
namespace {

// A grid whose voxel (i, j, k) is filled when inside(centre) holds, centre = (i + 0.5, j + 0.5, k + 0.5) in voxels.
template <class F>
VoxelGrid shapeGrid(Dims d, F inside, GridFrame frame = {}) {
  VoxelGrid g(d, std::move(frame));
  for (int z = 0; z < d.nz; ++z)
    for (int y = 0; y < d.ny; ++y)
      for (int x = 0; x < d.nx; ++x)
        if (inside(glm::dvec3(x + 0.5, y + 0.5, z + 0.5))) g.set(x, y, z);
  return g;
}

Thickness thicknessOf(const VoxelGrid& g) {
  auto dist = computeDistance(g);
  EXPECT_TRUE(dist.ok());
  auto t = computeThickness(*dist);
  EXPECT_TRUE(t.ok());
  return std::move(t.value());
}

// Brute force of the definition: R^2(p) = max s(c) over filled c with |p - c|^2 < s(c).
TEST(Thickness, matchesBruteForceOfTheDefinition) {
  std::vector<std::pair<VoxelGrid, std::string>> grids;
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    grids.emplace_back(test::randomBoxes(Dims{19, 15, 13}, 5, seed), "boxes " + std::to_string(seed));
    grids.emplace_back(test::randomGrid(Dims{12, 11, 9}, 0.55 + 0.1 * seed, seed), "noise " + std::to_string(seed));
  }
  grids.emplace_back(test::ballGrid(Dims{17, 17, 17}, {8.2, 8.6, 8.4}, 7.3), "ball");
  grids.emplace_back(VoxelGrid(Dims{5, 5, 5}), "empty");
  for (const auto& [g, what] : grids) {
    auto dist = computeDistance(g);
    ASSERT_TRUE(dist.ok());
    auto t = computeThickness(*dist);
    ASSERT_TRUE(t.ok());
    std::vector<glm::ivec3> filled;
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x)
          if (g.get(x, y, z)) filled.emplace_back(x, y, z);
    int64_t mismatches = 0;
    double sum = 0;
    uint32_t mn = UINT32_MAX, mx = 0;
    for (const glm::ivec3& p : filled) {
      uint32_t best = 0;
      for (const glm::ivec3& c : filled) {
        const uint32_t s = dist->squared(c.x, c.y, c.z);
        const glm::ivec3 d = p - c;
        if (uint32_t(d.x * d.x + d.y * d.y + d.z * d.z) < s) best = std::max(best, s);
      }
      const uint32_t got = t->radius.squared(p.x, p.y, p.z);
      if (got != best && ++mismatches <= 5) {
        ADD_FAILURE() << what << " at " << p.x << "," << p.y << "," << p.z << ": " << got << " expected " << best;
      }
      sum += 2 * std::sqrt(double(best));
      mn = std::min(mn, best);
      mx = std::max(mx, best);
    }
    EXPECT_EQ(mismatches, 0) << what;
    EXPECT_EQ(t->stats.voxels, int64_t(filled.size())) << what;
    if (!filled.empty()) {
      EXPECT_NEAR(t->stats.mean, sum / double(filled.size()), 1e-9) << what;
      EXPECT_DOUBLE_EQ(t->stats.min, 2 * std::sqrt(double(mn))) << what;
      EXPECT_DOUBLE_EQ(t->stats.max, 2 * std::sqrt(double(mx))) << what;
      int64_t total = 0;
      for (int64_t c : t->stats.counts) total += c;
      EXPECT_EQ(total, int64_t(filled.size())) << what;
      EXPECT_LE(t->ball_centres, int64_t(filled.size()));
    }
  }
}

// The definition painted naively: every filled voxel's ball, max over the balls.
std::vector<uint32_t> naivePainting(const VoxelGrid& g, const DistanceField& dist) {
  std::vector<uint32_t> expect(size_t(g.dims().count()), 0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const int s = int(dist.squared(x, y, z));
        if (!s) continue;
        const int r = int(std::sqrt(double(s))) + 1;
        for (int dz = -r; dz <= r; ++dz)
          for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
              if (dx * dx + dy * dy + dz * dz >= s) continue;
              uint32_t& e = expect[size_t(g.index(x + dx, y + dy, z + dz))];
              e = std::max(e, uint32_t(s));
            }
      }
  return expect;
}

// Walls whose middle voxels have equal neighbours on both sides (the crests where the central differences of the
// distance are zero, which try the offsets toward their largest neighbour, or only the 26): a plate and a fin both
// at least nine voxels from the filled box's faces, where the containment test reads its offsets unchecked, with a
// tilted slab and a cylinder along y; a box of 90 x 90 x 76 voxels, which two threads share where the machine has
// them (slabs of two slices; one thread takes slabs of four), against the naive painting.
TEST(Thickness, crestsAndSlabsMatchNaivePainting) {
  const Dims d{90, 90, 84};
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 0.5, 1.0));
  const VoxelGrid g = shapeGrid(d, [&](glm::dvec3 p) {
    const bool foot = p.z < 4 && p.x < 6 && p.y < 6;                            // the box from z = 0
    const bool plate = p.z > 10 && p.z < 19 && p.x > 2 && p.x < 88;             // 9 thick: its crest at z = 14
    const bool fin = p.x > 20 && p.x < 27 && p.z >= 19 && p.z < 40 && p.y > 5;  // 7 thick: its crest at x = 23
    const bool slab = std::abs(glm::dot(p - glm::dvec3(23, 26, 50), n)) < 5.5 && p.z >= 40;  // tilted
    const double rr = (p.x - 23) * (p.x - 23) + (p.z - 30) * (p.z - 30);
    const bool cylinder = rr < 64 && p.y > 10 && p.y < 42;  // radius 8 along y
    return foot || plate || fin || slab || cylinder;
  });
  auto dist = computeDistance(g);
  ASSERT_TRUE(dist.ok());
  const std::vector<uint32_t> expect = naivePainting(g, *dist);
  auto t = computeThickness(*dist);
  ASSERT_TRUE(t.ok());
  int64_t mismatches = 0, filled = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        filled += g.get(x, y, z);
        const uint32_t want = expect[size_t(g.index(x, y, z))];
        if (t->radius.squared(x, y, z) != want && ++mismatches <= 5) {
          ADD_FAILURE() << "at " << x << "," << y << "," << z << ": " << t->radius.squared(x, y, z) << " expected "
                        << want;
        }
      }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(filled, 20000);
  EXPECT_LT(t->ball_centres, filled / 4);  // most balls dropped, the crests' among them
}

// A grid large enough for several threads (noise, so most balls are small, and three large balls), against the
// definition painted naively.
TEST(Thickness, largeGridMatchesNaivePainting) {
  VoxelGrid g = test::randomGrid(Dims{110, 90, 80}, 0.6, 7);
  for (const glm::dvec3 c : {glm::dvec3(30.2, 40.7, 30.1), glm::dvec3(70.5, 45.5, 50.5), glm::dvec3(60, 30, 20)}) {
    const VoxelGrid b = test::ballGrid(g.dims(), c, 14.3);
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x)
          if (b.get(x, y, z)) g.set(x, y, z);
  }
  auto dist = computeDistance(g);
  ASSERT_TRUE(dist.ok());
  const std::vector<uint32_t> expect = naivePainting(g, *dist);
  // The statistics of a field large enough to be counted on several threads.
  int64_t voxels = 0;
  double sum = 0;
  uint32_t mn = UINT32_MAX, mx = 0;
  for (const uint32_t e : expect) {
    if (!e) continue;
    ++voxels;
    sum += 2 * std::sqrt(double(e));
    mn = std::min(mn, e);
    mx = std::max(mx, e);
  }
  // Both paintings: the automatic one (AVX-512, else AVX2, else SSE2) and the SSE2 one any processor takes.
  ThicknessParams sse2;
  sse2.simd = ThicknessParams::Simd::kSse2;
  for (const ThicknessParams& params : {ThicknessParams{}, sse2}) {
    const char* what = params.simd == ThicknessParams::Simd::kSse2 ? "SSE2" : "automatic";
    auto t = computeThickness(*dist, params);
    ASSERT_TRUE(t.ok());
    int64_t mismatches = 0;
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x)
          if (t->radius.squared(x, y, z) != expect[size_t(g.index(x, y, z))]) ++mismatches;
    EXPECT_EQ(mismatches, 0) << what;
    EXPECT_EQ(t->stats.voxels, voxels) << what;
    EXPECT_NEAR(t->stats.mean, sum / double(voxels), 1e-9) << what;
    EXPECT_DOUBLE_EQ(t->stats.min, 2 * std::sqrt(double(mn))) << what;
    EXPECT_DOUBLE_EQ(t->stats.max, 2 * std::sqrt(double(mx))) << what;
    int64_t total = 0;
    for (const int64_t c : t->stats.counts) total += c;
    EXPECT_EQ(total, voxels) << what;
  }
}

// An axis-aligned plate n voxels thick reads n when n is even, n + 1 when n is odd (docs/accuracy.md).
TEST(Thickness, axisAlignedPlateReadsItsVoxelCountRoundedUpToEven) {
  GridFrame frame;
  frame.voxel_size = 0.25;
  for (int n = 1; n <= 9; ++n) {
    VoxelGrid g(Dims{40, 36, 20}, frame);
    test::fillBox(g, {0, 0, 3}, {40, 36, 3 + n});
    const Thickness t = thicknessOf(g);
    const double expect = (n % 2 == 0 ? n : n + 1) * 0.25;
    for (int z = 3; z < 3 + n; ++z)
      for (int y = n + 1; y < 36 - n - 1; ++y)
        for (int x = n + 1; x < 40 - n - 1; ++x) ASSERT_DOUBLE_EQ(t.model(x, y, z), expect) << n << " at " << z;
    EXPECT_DOUBLE_EQ(t.stats.max, expect) << n;
    EXPECT_DOUBLE_EQ(t.model(0, 0, 0), 0.0);  // empty
  }
}

// A plate of true thickness tv voxels, normal (sin a, 0, cos a) (rotated about Y), through the grid: the local
// thickness of its voxels away from the grid's border.
struct PlateReading {
  double mean = 0, median = 0;
  int64_t voxels = 0;
};
PlateReading rotatedPlate(double tv, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  const glm::dvec3 n(std::sin(a), 0.0, std::cos(a)), u(std::cos(a), 0.0, -std::sin(a));
  const int side = int(std::ceil(8 * tv)) + 16;
  const glm::dvec3 c(side / 2.0 + 0.13, 12.0, side / 2.0 + 0.37);
  const VoxelGrid g = shapeGrid(Dims{side, 24, side}, [&](glm::dvec3 p) {
    const double d = glm::dot(p - c, n);
    return d > -tv / 2 && d < tv / 2;
  });
  const Thickness t = thicknessOf(g);
  std::vector<double> v;
  for (int z = 0; z < side; ++z)
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < side; ++x) {
        if (!g.get(x, y, z)) continue;
        const glm::dvec3 p(x + 0.5, y + 0.5, z + 0.5);
        if (std::abs(glm::dot(p - c, u)) > 1.5 * tv || std::abs(p.y - c.y) > 6) continue;
        v.push_back(t.voxels(x, y, z));
      }
  PlateReading r;
  r.voxels = int64_t(v.size());
  for (double x : v) r.mean += x / double(v.size());
  std::sort(v.begin(), v.end());
  r.median = v[v.size() / 2];
  return r;
}

TEST(Thickness, rotatedPlatesReadTheirThicknessWithinAVoxel) {
  for (double tv : {4.0, 5.5, 7.3, 10.0}) {
    const PlateReading aligned = rotatedPlate(tv, 0);
    for (double deg : {0.0, 30.0, 45.0}) {
      const PlateReading r = rotatedPlate(tv, deg);
      ASSERT_GT(r.voxels, 100);
      std::printf("plate %.1f voxels at %2.0f degrees: median %.3f mean %.3f\n", tv, deg, r.median, r.mean);
      EXPECT_NEAR(r.median, tv, 1.0) << tv << " at " << deg << " degrees";
      EXPECT_NEAR(r.mean, tv, 1.0) << tv << " at " << deg << " degrees";
      EXPECT_NEAR(r.median, aligned.median, 1.0) << tv << " at " << deg << " degrees";
    }
  }
}

TEST(Thickness, tubeCylinderSphereAndLBracket) {
  const double h = 0.5;
  GridFrame frame;
  frame.voxel_size = h;
  // tube along z: outer radius 14, inner 8 -> wall 6 voxels
  {
    const VoxelGrid g = shapeGrid(
        Dims{32, 32, 20},
        [](glm::dvec3 p) {
          const double r2 = (p.x - 16.1) * (p.x - 16.1) + (p.y - 15.8) * (p.y - 15.8);
          return r2 < 14.0 * 14.0 && r2 > 8.0 * 8.0;
        },
        frame);
    const Thickness t = thicknessOf(g);
    std::vector<double> v;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        if (g.get(x, y, 10)) v.push_back(t.voxels(x, y, 10));
    std::sort(v.begin(), v.end());
    std::printf("tube wall 6 voxels: median %.3f, min %.3f, max %.3f\n", v[v.size() / 2], v.front(), v.back());
    EXPECT_NEAR(v[v.size() / 2], 6.0, 1.0);
  }
  // cylinder along z, radius 9.5 -> 19 voxels
  {
    const VoxelGrid g = shapeGrid(
        Dims{24, 24, 50}, [](glm::dvec3 p) { return (p.x - 12) * (p.x - 12) + (p.y - 12) * (p.y - 12) < 9.5 * 9.5; });
    const Thickness t = thicknessOf(g);
    // the ridge voxels sit half a voxel off the axis in x and y: within two voxels (docs/accuracy.md)
    EXPECT_NEAR(t.voxels(12, 12, 25), 19.0, 2.0);
    EXPECT_NEAR(t.stats.max, 19.0, 2.0);
    // every voxel of the middle slice lies in a ball of the axis
    for (int y = 0; y < 24; ++y) {
      for (int x = 0; x < 24; ++x) {
        if (g.get(x, y, 25)) {
          EXPECT_DOUBLE_EQ(t.voxels(x, y, 25), t.voxels(12, 12, 25));
        }
      }
    }
  }
  // sphere, radius 11.2 centred on a voxel centre: one ball holds every voxel
  {
    const VoxelGrid g = test::ballGrid(Dims{26, 26, 26}, {13.5, 13.5, 13.5}, 11.2, frame);
    const Thickness t = thicknessOf(g);
    EXPECT_NEAR(t.stats.min, 2 * 11.2 * h, 2 * h);
    EXPECT_DOUBLE_EQ(t.stats.min, t.stats.max);
    EXPECT_LT(t.ball_centres, 100);  // of 5,800 voxels: the lattice containment test prunes the rest
  }
  // L-bracket: a horizontal arm 4 voxels thick and a vertical arm 7 voxels thick
  {
    VoxelGrid g(Dims{40, 20, 40}, frame);
    test::fillBox(g, {0, 0, 0}, {40, 20, 4});
    test::fillBox(g, {0, 0, 0}, {7, 20, 40});
    const Thickness t = thicknessOf(g);
    EXPECT_DOUBLE_EQ(t.voxels(30, 10, 2), 4.0);  // even: 4
    EXPECT_DOUBLE_EQ(t.voxels(3, 10, 30), 8.0);  // odd: 7 + 1
    EXPECT_DOUBLE_EQ(t.voxels(30, 10, 0), 4.0);  // the skin of the arm too
    EXPECT_GE(t.voxels(5, 10, 2), 8.0);          // the corner is at least as thick as the thicker arm
  }
}

TEST(Thickness, histogramAndCancellation) {
  VoxelGrid g(Dims{30, 30, 30});
  test::fillBox(g, {0, 0, 0}, {30, 30, 2});    // 2 thick
  test::fillBox(g, {0, 0, 10}, {30, 30, 16});  // 6 thick
  auto dist = computeDistance(g);
  ASSERT_TRUE(dist.ok());
  auto t = computeThickness(*dist, ThicknessParams{3});
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t->stats.edges.size(), 4u);
  EXPECT_DOUBLE_EQ(t->stats.edges.back(), 6.0);
  EXPECT_DOUBLE_EQ(t->stats.edges[1], 2.0);
  // the 2-thick plate in [2, 4) (a value on an edge goes above it), the 6-thick one in the last bin
  EXPECT_EQ(t->stats.counts[0], 0);
  EXPECT_EQ(t->stats.counts[1], 30 * 30 * 2);
  EXPECT_GT(t->stats.counts[2], 30 * 30 * 4);
  int calls = 0;
  auto c = computeThickness(*dist, {}, [&](double) { return ++calls < 2; });
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error().code, ErrorCode::kCancelled);
  auto clearance = computeClearance(g);
  ASSERT_TRUE(clearance.ok());
  EXPECT_FALSE(computeThickness(*clearance).ok());
  // the field can be handed over instead of copied (a packed one is made dense: the radius field is dense)
  EXPECT_FALSE(dist->isDense());
  auto moved = computeThickness(std::move(dist.value()), ThicknessParams{3});
  ASSERT_TRUE(moved.ok());
  EXPECT_TRUE(moved->radius.isDense());
  EXPECT_EQ(moved->stats.counts, t->stats.counts);
}

TEST(ThinWalls, aLoneFinIsOneRegionWithItsFacesAndBox) {
  GridFrame frame;
  frame.voxel_size = 0.5;
  frame.origin = glm::dvec3(10, 20, 30);
  VoxelGrid g(Dims{20, 20, 20}, frame);
  test::fillBox(g, {3, 4, 5}, {5, 16, 17});  // 2 x 12 x 12
  const Thickness t = thicknessOf(g);
  auto w = findThinWalls(t, 1.5);  // 3 voxels
  ASSERT_TRUE(w.ok());
  EXPECT_EQ(w->voxels, 2 * 12 * 12);
  ASSERT_EQ(w->regions.size(), 1u);
  const ThinWallRegion& r = w->regions[0];
  EXPECT_EQ(r.voxels, 288);
  EXPECT_EQ(r.exposed_faces, 2 * (2 * 12 + 2 * 12 + 12 * 12));
  EXPECT_DOUBLE_EQ(r.area, 384 * 0.25);
  EXPECT_EQ(r.bbox_min_ijk, glm::ivec3(3, 4, 5));
  EXPECT_EQ(r.bbox_max_ijk, glm::ivec3(4, 15, 16));
  EXPECT_DOUBLE_EQ(r.bbox.min.x, 11.5);
  EXPECT_DOUBLE_EQ(r.bbox.max.z, 30 + 17 * 0.5);
  EXPECT_DOUBLE_EQ(r.min, 1.0);
  // a minimum wall at the fin's own reading: nothing is thinner
  EXPECT_EQ(findThinWalls(t, 1.0)->voxels, 0);
}

TEST(ThinWalls, finOnABlockAndDiagonalContact) {
  VoxelGrid g(Dims{50, 30, 30});
  test::fillBox(g, {0, 0, 0}, {20, 30, 30});     // thick block
  test::fillBox(g, {20, 10, 10}, {32, 12, 20});  // fin 2 thick (y), 12 long, 10 high
  test::fillBox(g, {34, 0, 0}, {36, 10, 10});    // plate A, 2 thick
  test::fillBox(g, {36, 10, 10}, {38, 20, 20});  // plate B touches A along an edge only (26-connected)
  const Thickness t = thicknessOf(g);
  auto w = findThinWalls(t, 3.5);
  ASSERT_TRUE(w.ok());
  ASSERT_EQ(w->regions.size(), 2u);
  EXPECT_EQ(w->regions[0].voxels, 2 * 2 * 10 * 10);  // A and B joined through their edge
  const ThinWallRegion& fin = w->regions[1];
  EXPECT_LE(fin.voxels, 12 * 2 * 10);
  EXPECT_GE(fin.voxels, 10 * 2 * 10);  // all but the root, where the block's balls reach in
  EXPECT_GE(fin.bbox_min_ijk.x, 20);
  EXPECT_EQ(fin.bbox_max_ijk, glm::ivec3(31, 11, 19));
  EXPECT_DOUBLE_EQ(fin.min, 2.0);
  EXPECT_FALSE(findThinWalls(t, -1).ok());
}

// Chvorinov's modulus V/A from the geometry: a wide plate (thickness / 2), a long square bar (side / 4), a cube
// (side / 6) and a ball (diameter / 6) of one modulus, 10 voxels, each read within 10% by its one hot spot.
TEST(HotSpots, plateBarCubeAndBallOfOneModulusReadIt) {
  GridFrame frame;
  frame.voxel_size = 0.1;
  const double modulus = 1.0;  // 10 voxels
  struct Shape {
    const char* name;
    VoxelGrid grid;
  };
  const Shape shapes[] = {
      {"plate 2 thick, 60 wide", test::boxGrid(Dims{604, 604, 24}, {2, 2, 2}, {602, 602, 22}, frame)},
      {"bar 4 x 4 x 60", test::boxGrid(Dims{44, 44, 604}, {2, 2, 2}, {42, 42, 602}, frame)},
      {"cube 6", test::boxGrid(Dims{64, 64, 64}, {2, 2, 2}, {62, 62, 62}, frame)},
      {"ball 6 across", test::ballGrid(Dims{64, 64, 64}, glm::dvec3(32.0), 30.0, frame)},
  };
  for (const Shape& s : shapes) {
    auto dist = computeDistance(s.grid, {}, DistanceLayout::kDense);
    ASSERT_TRUE(dist.ok());
    auto spots = findHotSpots(*dist);
    ASSERT_TRUE(spots.ok());
    ASSERT_FALSE(spots->empty()) << s.name;
    EXPECT_NEAR(spots->front().modulus, modulus, 0.1 * modulus) << s.name << ", radius " << spots->front().radius;
  }
}

TEST(HotSpots, dumbbellHasTwoIsolatedSpotsAtTheBallCentres) {
  GridFrame frame;
  frame.voxel_size = 0.2;
  frame.origin = glm::dvec3(-1, 2, 3);
  const glm::dvec3 a(12.0, 12.0, 12.0), b(44.0, 12.0, 12.0);  // voxel corners: 8-voxel plateaus
  const VoxelGrid g = shapeGrid(
      Dims{56, 24, 24},
      [&](glm::dvec3 p) {
        const glm::dvec3 pa = p - a, pb = p - b;
        const double ra = 9.0, rb = 8.0, bar = 2.5;
        if (glm::dot(pa, pa) < ra * ra || glm::dot(pb, pb) < rb * rb) return true;
        return p.x > a.x && p.x < b.x && (p.y - 12) * (p.y - 12) + (p.z - 12) * (p.z - 12) < bar * bar;
      },
      frame);
  auto dist = computeDistance(g);
  ASSERT_TRUE(dist.ok());
  auto spots = findHotSpots(*dist);
  ASSERT_TRUE(spots.ok());
  ASSERT_GE(spots->size(), 2u);
  const HotSpot& big = (*spots)[0];
  const HotSpot& small = (*spots)[1];
  const glm::dvec3 ca = frame.origin + a * 0.2, cb = frame.origin + b * 0.2;
  EXPECT_NEAR(glm::length(big.centre - ca), 0.0, 0.2) << big.centre.x;
  EXPECT_NEAR(glm::length(small.centre - cb), 0.0, 0.2) << small.centre.x;
  EXPECT_NEAR(big.radius, 9.0 * 0.2, 0.2);
  EXPECT_NEAR(small.radius, 8.0 * 0.2, 0.2);
  EXPECT_GT(big.modulus, big.radius / 3 * 0.9);  // a ball and its half of the bar: near a ball's radius / 3
  EXPECT_LT(big.modulus, big.radius / 2);
  EXPECT_TRUE(big.isolated);
  EXPECT_TRUE(small.isolated);
  EXPECT_NEAR(small.saddle, 2.5 * 0.2, 0.2);
  EXPECT_EQ(small.plateau_voxels, 8);
  EXPECT_TRUE(dist->inBox(small.voxel.x, small.voxel.y, small.voxel.z));
  EXPECT_TRUE(g.get(small.voxel.x, small.voxel.y, small.voxel.z));
  // nothing else stands out by a voxel
  EXPECT_EQ(spots->size(), 2u);
}

TEST(HotSpots, aPlateIsOnePlateauAndNoiseIsFiltered) {
  VoxelGrid g(Dims{30, 30, 10});
  test::fillBox(g, {0, 0, 2}, {30, 30, 7});  // 5 thick: the middle layer is one plateau, bar its rim
  auto dist = computeDistance(g);
  ASSERT_TRUE(dist.ok());
  auto spots = findHotSpots(*dist);
  ASSERT_TRUE(spots.ok());
  ASSERT_EQ(spots->size(), 1u);
  EXPECT_DOUBLE_EQ((*spots)[0].radius, 3.0);
  EXPECT_NEAR((*spots)[0].centre.x, 15.0, 1e-9);
  EXPECT_NEAR((*spots)[0].centre.z, 4.5, 1e-9);
  EXPECT_TRUE((*spots)[0].isolated);
  // a ball: one spot however its distance field wobbles
  auto ball = computeDistance(test::ballGrid(Dims{40, 40, 40}, {20.3, 19.6, 20.1}, 17.0));
  ASSERT_TRUE(ball.ok());
  auto bs = findHotSpots(*ball);
  ASSERT_TRUE(bs.ok());
  EXPECT_EQ(bs->size(), 1u);
  // every regional maximum, with no filter
  auto all = findHotSpots(*ball, HotSpotParams{0.0, 2.0});
  ASSERT_TRUE(all.ok());
  EXPECT_GE(all->size(), bs->size());
}

}  // namespace
}  // namespace vox
