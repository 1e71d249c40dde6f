// Printability on analytic parts (SPEC 11): a cantilever's overhang and support against the hand-computed values in
// any orientation, from the mesh's normals and from the voxels' surface; sealed voids found exactly and drained; the
// orientation search ranking directions by support.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "support/test_meshes.h"
#include "vox/analysis/printability.h"
#include "vox/voxelize/voxelize.h"

namespace vox {
namespace {

TriangleMesh cantilever() { return test::cantileverMesh(); }

VoxelGrid voxelize(const TriangleMesh& mesh, double h) {
  VoxelizeParams p;
  p.voxel_size = h;
  p.units = "mm";
  auto r = voxelizeSolid(mesh, p);
  EXPECT_TRUE(r.ok());
  return std::move(r->grid);
}

PrintSupport supportOf(const VoxelGrid& grid, const TriangleMesh* mesh, glm::dvec3 up, double angle = 45.0,
                       bool fields = false) {
  auto surface = makePrintSurface(grid, mesh);
  EXPECT_TRUE(surface.ok());
  PrintParams p;
  p.up = up;
  p.overhang_angle_deg = angle;
  p.fields = fields;
  auto s = computePrintSupport(*surface, grid, p);
  EXPECT_TRUE(s.ok());
  return std::move(s).value();
}

TEST(PrintSupport, aCantileversOverhangAndSupportAreTheHandComputedOnes) {
  const TriangleMesh mesh = cantilever();
  const VoxelGrid grid = voxelize(mesh, 0.5);
  const PrintSupport up = supportOf(grid, &mesh, {0, 0, 1}, 45.0, true);
  EXPECT_NEAR(up.overhang_area, 300.0, 0.01 * 300.0);  // the arm's underside; the column's foot lies on the plate
  EXPECT_NEAR(up.support_volume, 4500.0, 0.02 * 4500.0);
  EXPECT_NEAR(up.height, 20.0, 1e-9);
  // the fields: the arm's lowest layer over the overhang, and 15 mm of columns under it (voxel centres)
  ASSERT_TRUE(up.overhang && up.support);
  EXPECT_NEAR(double(up.overhang->filledCount()), 60.0 * 20.0, 60.0);
  EXPECT_NEAR(double(up.support->filledCount()) * 0.125, 4500.0, 0.05 * 4500.0);
  // a ceiling needs support at any angle under 90 degrees
  EXPECT_NEAR(supportOf(grid, &mesh, {0, 0, 1}, 80.0).support_volume, 4500.0, 0.02 * 4500.0);
}

TEST(PrintSupport, theCantileverUpsideDownOrOnItsSideNeedsNone) {
  const TriangleMesh mesh = cantilever();
  const VoxelGrid grid = voxelize(mesh, 0.5);
  for (const glm::dvec3 up : {glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0)}) {
    const PrintSupport s = supportOf(grid, &mesh, up);
    EXPECT_NEAR(s.support_volume, 0.0, 1e-9) << printDirectionName(up);
    EXPECT_NEAR(s.overhang_area, 0.0, 1e-9) << printDirectionName(up);
  }
  // on the column's outer side (+x up) nothing faces down either
  EXPECT_NEAR(supportOf(grid, &mesh, {1, 0, 0}).support_volume, 0.0, 1e-9);
  // on the arm's end (-x up) the column's inner side below the arm (10 x 15) is a ceiling 30 mm over the plate
  const PrintSupport minus_x = supportOf(grid, &mesh, {-1, 0, 0});
  EXPECT_NEAR(minus_x.overhang_area, 150.0, 0.01 * 150.0);
  EXPECT_NEAR(minus_x.support_volume, 4500.0, 0.02 * 4500.0);
}

TEST(PrintSupport, theCantileverTurnedReadsTheSameSupport) {
  // turned 30 degrees about z (the build direction stays +z) and turned as a whole with the build direction
  const TriangleMesh turned_z = test::transformed(cantilever(), test::rotation({0, 0, 1}, 30), {20, 5, 10});
  const VoxelGrid grid_z = voxelize(turned_z, 0.5);
  const PrintSupport a = supportOf(grid_z, &turned_z, {0, 0, 1});
  EXPECT_NEAR(a.overhang_area, 300.0, 0.01 * 300.0);
  EXPECT_NEAR(a.support_volume, 4500.0, 0.03 * 4500.0);
  const glm::dmat3 r = test::rotation(glm::normalize(glm::dvec3(1, 2, 3)), 37);
  const TriangleMesh turned = test::transformed(cantilever(), r, {20, 5, 10});
  const VoxelGrid grid = voxelize(turned, 0.5);
  const PrintSupport b = supportOf(grid, &turned, r * glm::dvec3(0, 0, 1));
  EXPECT_NEAR(b.overhang_area, 300.0, 0.01 * 300.0);
  EXPECT_NEAR(b.support_volume, 4500.0, 0.01 * 4500.0);
  EXPECT_NEAR(b.height, 20.0, 1e-3);
}

TEST(PrintSupport, fromTheVoxelsAloneTheCantileverReadsWithinAFewPercent) {
  const VoxelGrid grid = voxelize(cantilever(), 0.5);
  const PrintSupport s = supportOf(grid, nullptr, {0, 0, 1});
  EXPECT_NEAR(s.overhang_area, 300.0, 0.05 * 300.0);
  EXPECT_NEAR(s.support_volume, 4500.0, 0.03 * 4500.0);
}

TEST(PrintSupport, aSlopeNeedsSupportOnlyPastTheAngle) {
  // a prism along x whose underside faces down 30 degrees from the vertical (60 from the plate): y from 0 to 10 at
  // the foot, the underside rising from (0, 0) to (-10 tan 30, 10)... i.e. the side leaning out over the plate
  const double lean = 10.0 * std::tan(30.0 * 3.14159265358979 / 180.0);
  const TriangleMesh prism = test::prismAlongX({{0, 0}, {10, 0}, {10, 10}, {-lean, 10}}, 0, 20);
  const VoxelGrid grid = voxelize(prism, 0.25);
  const double side = 20.0 * 10.0 / std::cos(30.0 * 3.14159265358979 / 180.0);  // the leaning face's area
  EXPECT_NEAR(supportOf(grid, &prism, {0, 0, 1}, 45.0).overhang_area, 0.0, 1e-9);
  const PrintSupport steep = supportOf(grid, &prism, {0, 0, 1}, 20.0);
  EXPECT_NEAR(steep.overhang_area, side, 0.02 * side);
  EXPECT_NEAR(steep.support_volume, 0.5 * lean * 10.0 * 20.0, 0.03 * 0.5 * lean * 10.0 * 20.0);
  // from the voxels alone the leaning side is a slope too, not a staircase of small ceilings: at 45 degrees only the
  // strips where it meets the prism's ends (convex edges, read by their faces) hang, and at 20 degrees the whole side
  // does, within the width of those strips
  const PrintSupport voxels_45 = supportOf(grid, nullptr, {0, 0, 1}, 45.0);
  EXPECT_LT(voxels_45.overhang_area, 0.1 * side);
  EXPECT_LT(voxels_45.support_volume, 0.1 * 0.5 * lean * 10.0 * 20.0);
  const PrintSupport voxels = supportOf(grid, nullptr, {0, 0, 1}, 20.0);
  EXPECT_NEAR(voxels.overhang_area, side, 0.15 * side);
  EXPECT_NEAR(voxels.support_volume, 0.5 * lean * 10.0 * 20.0, 0.03 * 0.5 * lean * 10.0 * 20.0);
}

// A block of voxels [5, 35)^3 on a 40^3 grid of 0.5 mm voxels with a spherical void of radius 8 voxels at its centre.
VoxelGrid blockWithVoid(int radius = 8) {
  GridFrame f;
  f.voxel_size = 0.5;
  f.units = "mm";
  VoxelGrid g(Dims{40, 40, 40}, f);
  for (int z = 5; z < 35; ++z)
    for (int y = 5; y < 35; ++y)
      for (int x = 5; x < 35; ++x) {
        const glm::dvec3 p = glm::dvec3(x, y, z) + 0.5 - 20.0;
        if (glm::dot(p, p) >= double(radius * radius)) g.set(x, y, z);
      }
  return g;
}

TEST(TrappedCavities, aSealedVoidIsOneCavityOfItsVolumeWithTheShortestDrain) {
  const VoxelGrid g = blockWithVoid();
  const int64_t void_voxels = 30 * 30 * 30 - g.filledCount();
  auto cavities = findTrappedCavities(g);
  ASSERT_TRUE(cavities.ok());
  ASSERT_EQ(cavities->size(), 1u);
  const TrappedCavity& c = cavities->front();
  EXPECT_EQ(c.voxels, void_voxels);
  EXPECT_DOUBLE_EQ(c.volume, double(void_voxels) * 0.125);
  EXPECT_NEAR(glm::length(c.centre - glm::dvec3(10.0)), 0.0, 1e-9);
  // radius 8 voxels, the ball's voxels fill a sphere's volume within a few percent
  EXPECT_NEAR(c.volume, 4.0 / 3.0 * 3.14159265 * 64.0, 0.05 * 4.0 / 3.0 * 3.14159265 * 64.0);
  // the thinnest wall along a lattice line: from the void's voxel at x = 27 through x = 28..34 (7 voxels)
  ASSERT_TRUE(c.drain.has_value());
  EXPECT_DOUBLE_EQ(c.drain->length, 7 * 0.5);
  EXPECT_EQ(std::abs(c.drain->step.x) + std::abs(c.drain->step.y) + std::abs(c.drain->step.z), 1);
  EXPECT_EQ(trappedCavityGrid(g).filledCount(), void_voxels);
}

TEST(TrappedCavities, aDrainedVoidAndAnOpenPocketAreNotTrapped) {
  VoxelGrid g = blockWithVoid();
  for (int x = 27; x < 35; ++x) g.reset(x, 20, 20);  // a drain one voxel wide to the outside
  auto drained = findTrappedCavities(g);
  ASSERT_TRUE(drained.ok());
  EXPECT_TRUE(drained->empty());
  // a part filling the grid's box up to its border, with a pocket open through the border: not trapped
  GridFrame f;
  VoxelGrid box(Dims{10, 10, 10}, f);
  for (int z = 0; z < 10; ++z)
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x)
        if (!(x >= 3 && x < 7 && y >= 3 && y < 7 && z >= 5)) box.set(x, y, z);
  auto open = findTrappedCavities(box);
  ASSERT_TRUE(open.ok());
  EXPECT_TRUE(open->empty());
}

TEST(TrappedCavities, twoVoidsAreListedLargestFirst) {
  VoxelGrid g = blockWithVoid(4);
  for (int z = 8; z < 11; ++z)
    for (int y = 8; y < 11; ++y)
      for (int x = 8; x < 11; ++x) g.reset(x, y, z);  // a 3^3 void near a corner
  auto cavities = findTrappedCavities(g);
  ASSERT_TRUE(cavities.ok());
  ASSERT_EQ(cavities->size(), 2u);
  EXPECT_GT((*cavities)[0].volume, (*cavities)[1].volume);
  EXPECT_EQ((*cavities)[1].voxels, 27);
  EXPECT_EQ((*cavities)[1].box_min, glm::ivec3(8));
  EXPECT_EQ((*cavities)[1].box_max, glm::ivec3(10));
  // the small void's shortest drain is its 3 voxels of wall to the block's faces at 5
  ASSERT_TRUE((*cavities)[1].drain.has_value());
  EXPECT_DOUBLE_EQ((*cavities)[1].drain->length, 3 * 0.5);
}

TEST(PrintOrientation, theBestDirectionNeedsNoMoreSupportThanAnyListed) {
  const TriangleMesh mesh = cantilever();
  const VoxelGrid grid = voxelize(mesh, 0.5);
  auto surface = makePrintSurface(grid, &mesh);
  ASSERT_TRUE(surface.ok());
  const std::vector<glm::dvec3> directions = printDirections(100);
  ASSERT_EQ(directions.size(), 106u);
  for (const glm::dvec3& d : directions) EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
  auto found = searchPrintOrientations(*surface, grid, directions, PrintParams{});
  ASSERT_TRUE(found.ok());
  ASSERT_EQ(found->size(), directions.size());
  for (const PrintSupport& s : *found) EXPECT_LE(found->front().support_volume, s.support_volume);
  // lying on its side (+y or -y) or upside down the cantilever needs none
  EXPECT_NEAR(found->front().support_volume, 0.0, 1e-9);
  // each entry is what the single direction reads
  for (const PrintSupport& s : *found) {
    if (printDirectionName(s.direction) != "+z") continue;
    EXPECT_NEAR(s.support_volume, supportOf(grid, &mesh, {0, 0, 1}).support_volume, 1e-9);
  }
}

TEST(PrintDirection, parsesAxesAndVectorsAndRefusesTheRest) {
  EXPECT_EQ(*parsePrintDirection("-y"), glm::dvec3(0, -1, 0));
  const auto v = parsePrintDirection("0, 3,4");
  ASSERT_TRUE(v.ok());
  EXPECT_NEAR(glm::length(*v - glm::dvec3(0, 0.6, 0.8)), 0.0, 1e-12);
  for (const char* bad : {"z", "0,0,0", "1,2", "1,,2,3", "1,2,nan", "up"}) {
    EXPECT_FALSE(parsePrintDirection(bad).ok()) << bad;
  }
  EXPECT_EQ(printDirectionName({0, 0, -1}), "-z");
}

}  // namespace
}  // namespace vox
