#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/common.hpp>

#include "grids.h"
#include "vox/analysis/surface_mesh.h"
#include "vox/voxelize/voxelize.h"

namespace vox {
namespace {

// What every extracted surface must be: closed and manifold (welded by position, as STL readers and admesh do),
// consistently oriented, enclosing filled x h^3 (to within the split vertices' moves), and voxelized again on the
// same lattice, the same voxels.
void expectSurfaceOf(const VoxelGrid& g, bool merge, const std::string& what) {
  SCOPED_TRACE(what + (merge ? " (merged)" : " (voxel faces)"));
  SurfaceMeshStats stats;
  auto mesh = extractSurfaceMesh(g, SurfaceMeshParams{merge}, {}, &stats);
  ASSERT_TRUE(mesh.ok());
  const int64_t filled = g.filledCount();
  if (filled == 0) {
    EXPECT_TRUE(mesh->triangles.empty());
    return;
  }
  const TriangleMesh soup = mesh->toTriangleMesh();
  const MeshTopology topo = analyzeTopology(soup);
  EXPECT_EQ(topo.boundary_edges, 0);
  EXPECT_EQ(topo.nonmanifold_edges, 0);
  EXPECT_EQ(topo.inconsistent_edges, 0);
  EXPECT_EQ(topo.degenerate_triangles, 0);
  const double h = g.voxelSize();
  EXPECT_NEAR(signedVolume(soup), double(filled) * h * h * h,
              (1e-9 + double(stats.split_vertices) / 256.0) * h * h * h);
  if (merge) {
    EXPECT_LE(stats.rectangles, stats.voxel_faces);
  } else {
    EXPECT_EQ(stats.rectangles, stats.voxel_faces);
  }
  // Voxelized again with the same voxel size: the lattice starts at the mesh's box, the filled box of the grid.
  VoxelizeParams p;
  p.voxel_size = h;
  p.mode = FillMode::kNonzero;
  auto again = voxelizeSolid(soup, p);
  ASSERT_TRUE(again.ok());
  const Box3d b = soup.bounds();
  const glm::ivec3 off(glm::round((b.min - g.frame().origin) / h));
  int64_t mismatches = 0;
  for (int z = -1; z <= g.nz(); ++z)
    for (int y = -1; y <= g.ny(); ++y)
      for (int x = -1; x <= g.nx(); ++x) {
        const glm::ivec3 q = glm::ivec3(x, y, z) - off;
        const bool a = again->grid.inBounds(q.x, q.y, q.z) && again->grid.get(q.x, q.y, q.z);
        if (a != g.get(x, y, z)) ++mismatches;
      }
  EXPECT_EQ(mismatches, 0);
}

TEST(SurfaceMesh, randomGridsAreClosedManifoldAndGiveTheSameVoxelsBack) {
  int seed = 1;
  for (const Dims d : {Dims{1, 1, 1}, Dims{3, 5, 2}, Dims{17, 9, 13}, Dims{70, 5, 6}}) {
    for (const double p : {0.1, 0.5, 0.9, 1.0}) {
      const VoxelGrid g = test::randomGrid(d, p, uint32_t(seed++));
      for (bool merge : {false, true}) expectSurfaceOf(g, merge, "random " + std::to_string(p));
    }
  }
}

TEST(SurfaceMesh, voxelsTouchingAlongAnEdgeOrAtACornerAreSplit) {
  VoxelGrid edge(Dims{2, 2, 1});
  edge.set(0, 0, 0);
  edge.set(1, 1, 0);
  VoxelGrid corner(Dims{2, 2, 2});
  corner.set(0, 0, 0);
  corner.set(1, 1, 1);
  // Two cavities inside a block meeting along an edge, and two meeting at a corner.
  VoxelGrid cavities = test::boxGrid(Dims{6, 6, 6}, glm::ivec3(0), glm::ivec3(6));
  cavities.reset(2, 2, 2);
  cavities.reset(3, 3, 2);
  VoxelGrid cavity_corner = test::boxGrid(Dims{6, 6, 6}, glm::ivec3(0), glm::ivec3(6));
  cavity_corner.reset(2, 2, 2);
  cavity_corner.reset(3, 3, 3);
  for (const auto* g : {&edge, &corner, &cavities, &cavity_corner})
    for (bool merge : {false, true}) expectSurfaceOf(*g, merge, "contact");
  SurfaceMeshStats stats;
  ASSERT_TRUE(extractSurfaceMesh(edge, {}, {}, &stats).ok());
  EXPECT_EQ(stats.split_vertices, 6);  // both ends of the shared edge twice, and its middle once per voxel
}

TEST(SurfaceMesh, aBoxIsSixRectanglesAndTwelveTriangles) {
  GridFrame frame;
  frame.origin = glm::dvec3(-3.0, 1.0, 2.0);
  frame.voxel_size = 0.5;
  const VoxelGrid g = test::boxGrid(Dims{12, 7, 9}, glm::ivec3(1, 2, 3), glm::ivec3(11, 6, 8), frame);
  SurfaceMeshStats stats;
  auto mesh = extractSurfaceMesh(g, {}, {}, &stats);
  ASSERT_TRUE(mesh.ok());
  EXPECT_EQ(stats.rectangles, 6);
  EXPECT_EQ(stats.voxel_faces, 2 * (10 * 4 + 10 * 5 + 4 * 5));
  EXPECT_EQ(mesh->triangles.size(), 12u);
  EXPECT_EQ(mesh->vertices.size(), 8u);
  const Box3d b = mesh->toTriangleMesh().bounds();
  EXPECT_EQ(b.min, glm::dvec3(-2.5, 2.0, 3.5));
  EXPECT_EQ(b.max, glm::dvec3(2.5, 4.0, 6.0));
  expectSurfaceOf(g, true, "box");
}

TEST(SurfaceMesh, aBallMergesWithoutTJunctions) {
  const VoxelGrid g = test::ballGrid(Dims{40, 36, 30}, glm::dvec3(20.1, 18.3, 15.2), 13.7);
  SurfaceMeshStats stats;
  auto mesh = extractSurfaceMesh(g, {}, {}, &stats);
  ASSERT_TRUE(mesh.ok());
  EXPECT_LT(stats.rectangles * 2, stats.voxel_faces);
  expectSurfaceOf(g, true, "ball");
}

TEST(SurfaceMesh, smoothSurfaceStaysClosedAndWithinHalfAVoxel) {
  const VoxelGrid g = test::ballGrid(Dims{30, 30, 30}, glm::dvec3(15.2, 14.9, 15.1), 10.3);
  auto blocky = extractSurfaceMesh(g, SurfaceMeshParams{false, 0});
  auto smooth = extractSurfaceMesh(g, SurfaceMeshParams{true, 10});
  ASSERT_TRUE(blocky.ok());
  ASSERT_TRUE(smooth.ok());
  ASSERT_EQ(smooth->vertices.size(), blocky->vertices.size());  // the voxel faces' mesh, vertices moved
  EXPECT_EQ(smooth->triangles, blocky->triangles);
  double moved = 0.0;
  for (size_t i = 0; i < smooth->vertices.size(); ++i) {
    const glm::dvec3 d = glm::abs(smooth->vertices[i] - blocky->vertices[i]);
    EXPECT_LE(std::max({d.x, d.y, d.z}), 0.45 + 1e-12);
    moved = std::max(moved, std::max({d.x, d.y, d.z}));
  }
  EXPECT_GT(moved, 0.2);  // the steps are gone, not just nudged
  const TriangleMesh soup = smooth->toTriangleMesh();
  const MeshTopology topo = analyzeTopology(soup);
  EXPECT_TRUE(topo.watertight());
  EXPECT_EQ(topo.inconsistent_edges, 0);
  // Smoothing cuts the corners of the steps: the volume lies between that of the voxels and a little less, and
  // nearer the true ball's than the voxels' surface area is.
  const double filled = double(g.filledCount()), ball = 4.0 / 3.0 * 3.14159265358979 * 10.3 * 10.3 * 10.3;
  EXPECT_NEAR(signedVolume(soup), ball, 0.03 * ball);
  EXPECT_NEAR(filled, ball, 0.03 * ball);
}

}  // namespace
}  // namespace vox
