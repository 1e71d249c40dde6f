#include "vox/core/mesh.h"

#include <gtest/gtest.h>

namespace vox {
namespace {

// Unit cube from 12 outward-facing triangles.
TriangleMesh cube() {
  const glm::vec3 p[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  TriangleMesh m;
  for (auto& t : f) m.triangles.push_back({{p[t[0]], p[t[1]], p[t[2]]}});
  return m;
}

TEST(MeshTopology, closedCubeIsWatertightWithPositiveVolume) {
  const TriangleMesh m = cube();
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.vertices, 8);
  EXPECT_EQ(t.edges, 18);
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.inconsistent_edges, 0);
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-12);
}

TEST(MeshTopology, missingTriangleLeavesThreeBoundaryEdges) {
  TriangleMesh m = cube();
  m.triangles.pop_back();
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.boundary_edges, 3);
  EXPECT_FALSE(t.watertight());
}

TEST(MeshTopology, flippedTriangleIsInconsistentAndDuplicateMakesNonManifoldEdges) {
  TriangleMesh m = cube();
  std::swap(m.triangles[0].v[1], m.triangles[0].v[2]);
  EXPECT_EQ(analyzeTopology(m).inconsistent_edges, 3);
  TriangleMesh d = cube();
  d.triangles.push_back(d.triangles[0]);
  EXPECT_EQ(analyzeTopology(d).nonmanifold_edges, 3);
}

TEST(MeshTopology, touchingClosedBodiesAreNonManifoldButBalanced) {
  // Two unit cubes sharing the face x = 1: the shared edges are used four times, twice in each direction.
  TriangleMesh m = cube();
  for (Triangle t : cube().triangles) {
    for (auto& v : t.v) v.x += 1.0f;
    m.triangles.push_back(t);
  }
  const MeshTopology t = analyzeTopology(m);
  EXPECT_GT(t.nonmanifold_edges, 0);
  EXPECT_FALSE(t.watertight());
  EXPECT_EQ(t.unbalanced_edges, 0);
  EXPECT_TRUE(t.closedOriented());
  TriangleMesh open = cube();
  open.triangles.pop_back();
  EXPECT_EQ(analyzeTopology(open).unbalanced_edges, 3);
  EXPECT_FALSE(analyzeTopology(open).closedOriented());
}

TEST(MeshTopology, negativeZeroWeldsWithPositiveZero) {
  TriangleMesh m = cube();
  for (auto& t : m.triangles)
    for (auto& v : t.v)
      if (v.x == 0.0f) v.x = -0.0f;
  m.triangles[0].v[0].x = 0.0f;
  EXPECT_TRUE(analyzeTopology(m).watertight());
}

TEST(MeshTopology, degenerateTrianglesAreCounted) {
  TriangleMesh m = cube();
  m.triangles.push_back({{{0, 0, 0}, {0, 0, 0}, {1, 1, 1}}});  // repeated vertex
  m.triangles.push_back({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}});  // collinear: zero area
  EXPECT_EQ(analyzeTopology(m).degenerate_triangles, 2);
  EXPECT_FALSE(isDegenerate(m.triangles[0]));
}

TEST(Box3d, boundsOfMeshAndEmptyBox) {
  EXPECT_TRUE(TriangleMesh{}.bounds().empty());
  const Box3d b = cube().bounds();
  EXPECT_EQ(b.min, glm::dvec3(0));
  EXPECT_EQ(b.max, glm::dvec3(1));
}

}  // namespace
}  // namespace vox
