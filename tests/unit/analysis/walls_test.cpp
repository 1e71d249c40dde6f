// Walls, not edges, on analytic parts: a cube has no thin wall, a fin is one region at its thickness at any turn and
// resolution, a thin tube is one region and a thick one none, and a plate reads the same at any angle.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "grids.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/walls.h"

namespace vox {
namespace {

using Inside = std::function<bool(glm::dvec3)>;  // model units, mm

// Rotation by `yaw` about z then `pitch` about x (degrees), applied to the part: a point p of the grid is in the
// turned part when the inverse rotation of p about `centre` is in the part.
glm::dvec3 unturn(glm::dvec3 p, glm::dvec3 centre, double yaw, double pitch) {
  const double a = -yaw * std::numbers::pi / 180, b = -pitch * std::numbers::pi / 180;
  glm::dvec3 q = p - centre;
  q = {q.x, q.y * std::cos(b) - q.z * std::sin(b), q.y * std::sin(b) + q.z * std::cos(b)};
  q = {q.x * std::cos(a) - q.y * std::sin(a), q.x * std::sin(a) + q.y * std::cos(a), q.z};
  return q + centre;
}

// The part sampled at voxel centres on a cubic grid of `extent` mm per side and voxel size h, origin 0.
VoxelGrid sample(const Inside& inside, double extent, double h, double yaw = 0, double pitch = 0) {
  const int n = int(std::ceil(extent / h));
  GridFrame frame;
  frame.voxel_size = h;
  frame.units = "mm";
  VoxelGrid g(Dims{n, n, n}, frame);
  const glm::dvec3 centre(extent / 2);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        if (inside(unturn(glm::dvec3(x + 0.5, y + 0.5, z + 0.5) * h, centre, yaw, pitch))) g.set(x, y, z);
  return g;
}

bool inBox(glm::dvec3 p, glm::dvec3 lo, glm::dvec3 hi) {
  return p.x > lo.x && p.y > lo.y && p.z > lo.z && p.x < hi.x && p.y < hi.y && p.z < hi.z;
}

Walls wallsOf(const VoxelGrid& g, double min_wall, double min_area = -1) {
  auto dist = computeDistance(g, {}, DistanceLayout::kDense);
  EXPECT_TRUE(dist.ok());
  auto ridge = findWallRidge(*dist);
  EXPECT_TRUE(ridge.ok());
  auto walls = findWalls(*ridge, *dist, WallParams{min_wall, min_area});
  EXPECT_TRUE(walls.ok());
  return std::move(walls).value();
}

struct Turn {
  double yaw, pitch;
};
const Turn kTurns[] = {{0, 0}, {30, 20}, {45, 35}, {17, 61}};

TEST(Walls, aSolidCubeHasNoThinWallAndItsWallIsItsSize) {
  for (const Turn& t : kTurns) {
    for (double h : {0.5, 0.35}) {
      SCOPED_TRACE("turned " + std::to_string(t.yaw) + ", " + std::to_string(t.pitch) + ", h " + std::to_string(h));
      const Inside cube = [](glm::dvec3 p) { return inBox(p, glm::dvec3(8), glm::dvec3(28)); };  // 20 mm
      const VoxelGrid g = sample(cube, 36, h, t.yaw, t.pitch);
      const Walls w = wallsOf(g, 4.0);
      EXPECT_EQ(w.regions.size(), 0u);
      EXPECT_EQ(w.voxels, 0);
      EXPECT_NEAR(w.wall_min, 20.0, 2 * h);
    }
  }
}

// A 10 x 10 x 5 mm block with a fin 0.6 mm thick, 6 mm long and 4 mm high standing on its top.
bool blockWithFin(glm::dvec3 p) { return inBox(p, {3, 3, 3}, {13, 13, 8}) || inBox(p, {5, 7.7, 7.9}, {11, 8.3, 12}); }

TEST(Walls, aFinIsOneRegionAtItsThicknessTurnedAndAtEachResolution) {
  for (const Turn& t : kTurns) {
    for (double h : {0.1, 0.15, 0.2}) {
      SCOPED_TRACE("turned " + std::to_string(t.yaw) + ", " + std::to_string(t.pitch) + ", h " + std::to_string(h));
      const VoxelGrid g = sample(blockWithFin, 16, h, t.yaw, t.pitch);
      const Walls w = wallsOf(g, 1.0);
      ASSERT_EQ(w.regions.size(), 1u);
      const ThinWallRegion& fin = w.regions[0];
      EXPECT_NEAR(fin.min, 0.6, 2 * h);
      EXPECT_NEAR(w.wall_min, fin.min, 1e-12);
      // the region is the fin: its voxels are about the fin's volume (0.6 x 6 x 4 mm; less its root)
      const double volume = double(fin.voxels) * h * h * h;
      EXPECT_GT(volume, 0.5 * 0.6 * 6 * 4);
      EXPECT_LT(volume, 1.6 * 0.6 * 6 * 4);
      // and lies where the fin is: its centre turned back is over the block's top
      const glm::dvec3 c = unturn(0.5 * (fin.bbox.min + fin.bbox.max), glm::dvec3(8), t.yaw, t.pitch);
      EXPECT_NEAR(c.x, 8.0, 1.0);
      EXPECT_NEAR(c.y, 8.0, 1.0);
      EXPECT_GT(c.z, 8.5);
    }
  }
}

bool tube(glm::dvec3 p, double wall) {
  const double r = std::hypot(p.x - 8, p.y - 8);
  return r < 5.0 && r > 5.0 - wall && p.z > 3 && p.z < 13;
}

TEST(Walls, aThinTubeIsOneRegionAndAThickOneNone) {
  for (const Turn& t : {kTurns[0], kTurns[1]}) {
    SCOPED_TRACE("turned " + std::to_string(t.yaw) + ", " + std::to_string(t.pitch));
    const double h = 0.1;
    const Walls thin = wallsOf(sample([](glm::dvec3 p) { return tube(p, 0.6); }, 16, h, t.yaw, t.pitch), 1.0);
    ASSERT_EQ(thin.regions.size(), 1u);
    EXPECT_NEAR(thin.regions[0].min, 0.6, 2 * h);
    const Walls thick = wallsOf(sample([](glm::dvec3 p) { return tube(p, 1.6); }, 16, h, t.yaw, t.pitch), 1.0);
    EXPECT_EQ(thick.regions.size(), 0u);
    EXPECT_NEAR(thick.wall_min, 1.6, 2 * h);
  }
}

TEST(Walls, aPlateReadsItsThicknessAtEveryAngle) {
  const double h = 0.1;
  for (double angle : {0.0, 30.0, 45.0}) {
    SCOPED_TRACE("plate at " + std::to_string(angle));
    const Inside plate = [](glm::dvec3 p) { return inBox(p, {3, 3, 7}, {13, 13, 9}); };  // 2 mm thick
    const Walls w = wallsOf(sample(plate, 16, h, 0, angle), 3.0);
    ASSERT_EQ(w.regions.size(), 1u);
    EXPECT_NEAR(w.regions[0].min, 2.0, 2 * h);
    // all of the plate but its rim is wall
    EXPECT_GT(double(w.regions[0].voxels) * h * h * h, 0.8 * 200);
  }
}

TEST(Walls, specksUnderTheMinimumAreaAreCountedNotListed) {
  const double h = 0.1;
  const VoxelGrid g = sample(blockWithFin, 16, h);
  const Walls all = wallsOf(g, 1.0, 0.0);
  ASSERT_EQ(all.regions.size(), 1u);
  const Walls none = wallsOf(g, 1.0, all.regions[0].area * 1.01);  // the fin is a speck
  EXPECT_EQ(none.regions.size(), 0u);
  EXPECT_EQ(none.specks, 1);
  EXPECT_EQ(none.voxels, 0);
  EXPECT_NEAR(none.wall_min, all.regions[0].min, 1e-12);  // a speck's wall is still the part's thinnest
}

TEST(Walls, theMaskHoldsTheListedWalls) {
  GridFrame frame;
  frame.voxel_size = 0.5;
  VoxelGrid g(Dims{20, 20, 20}, frame);
  test::fillBox(g, {3, 4, 5}, {5, 16, 17});  // a lone plate 2 voxels (1 mm) thick
  const Walls w = wallsOf(g, 1.5);
  ASSERT_EQ(w.regions.size(), 1u);
  EXPECT_EQ(w.regions[0].voxels, 2 * 12 * 12);
  EXPECT_DOUBLE_EQ(w.regions[0].min, 1.0);
  EXPECT_TRUE(w.inWall(3, 10, 10));
  EXPECT_FALSE(w.inWall(5, 10, 10));
  EXPECT_FALSE(w.inWall(-1, 10, 10));
}

// The thin walls' voxels are the union of the inscribed balls of the stops thinner than the minimum, painted ball by
// ball or as the envelope of their paraboloids: both equal a brute force over the stops.
TEST(Walls, theWallsAreTheUnionOfTheThinStopsBallsByEitherPainting) {
  for (uint32_t seed = 1; seed <= 3; ++seed) {
    const VoxelGrid g = test::randomBoxes(Dims{26, 22, 18}, 6, seed);
    auto dist = computeDistance(g, {}, DistanceLayout::kDense);
    ASSERT_TRUE(dist.ok());
    auto ridge = findWallRidge(*dist);
    ASSERT_TRUE(ridge.ok());
    for (double wall : {3.0, 6.0, 100.0}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", wall " + std::to_string(wall));
      WallParams p{wall, 0.0};
      p.paint = WallParams::Paint::kBalls;
      auto balls = findWalls(*ridge, *dist, p);
      p.paint = WallParams::Paint::kEnvelope;
      auto envelope = findWalls(*ridge, *dist, p);
      ASSERT_TRUE(balls.ok() && envelope.ok());
      EXPECT_EQ(balls->mask, envelope->mask);
      EXPECT_EQ(balls->voxels, envelope->voxels);
      int64_t brute = 0;
      const Dims d = ridge->box_dims;
      for (int64_t i = 0; i < d.count(); ++i) {
        const int64_t x = i % d.nx, y = (i / d.nx) % d.ny, z = i / (int64_t(d.nx) * d.ny);
        bool in = false;
        for (const WallRidge::Stop& s : ridge->stops) {
          if (4.0 * double(s.squared) >= wall * wall) break;  // thinnest first
          const int64_t sx = s.index % d.nx, sy = (s.index / d.nx) % d.ny, sz = s.index / (int64_t(d.nx) * d.ny);
          const int64_t q = (x - sx) * (x - sx) + (y - sy) * (y - sy) + (z - sz) * (z - sz);
          if (q < int64_t(s.squared)) {
            in = true;
            break;
          }
        }
        brute += in;
        EXPECT_EQ(in, bool((envelope->mask[size_t(i >> 6)] >> (i & 63)) & 1)) << x << " " << y << " " << z;
      }
      EXPECT_EQ(brute, envelope->voxels);  // every region listed (no speck limit)
    }
  }
}

// A part a few voxels across has only stops near its surface: they are kept, and it is one wall.
TEST(Walls, aTinyPartKeepsItsStops) {
  VoxelGrid g(Dims{9, 9, 9});
  test::fillBox(g, {2, 2, 2}, {7, 7, 7});  // 5 voxels
  const Walls w = wallsOf(g, 100.0, 0.0);
  EXPECT_NEAR(w.wall_min, 6.0, 1.0);
  ASSERT_EQ(w.regions.size(), 1u);
}

TEST(Walls, refusesBadParameters) {
  VoxelGrid g(Dims{4, 4, 4});
  test::fillBox(g, {1, 1, 1}, {3, 3, 3});
  auto dist = computeDistance(g, {}, DistanceLayout::kDense);
  ASSERT_TRUE(dist.ok());
  EXPECT_FALSE(findWallRidge(*dist, WallRidgeParams{0.0, 2}).ok());
  EXPECT_FALSE(findWallRidge(*dist, WallRidgeParams{30.0, 0}).ok());
  auto ridge = findWallRidge(*dist);
  ASSERT_TRUE(ridge.ok());
  EXPECT_FALSE(findWalls(*ridge, *dist, WallParams{-1.0}).ok());
}

}  // namespace
}  // namespace vox
