#include "vox/core/mesh.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_support.h"

namespace vox {
namespace {

TEST(MeshTopology, closedCubeIsWatertightWithPositiveVolume) {
  const TriangleMesh m = test::unitCubeMesh();
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.vertices, 8);
  EXPECT_EQ(t.edges, 18);
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.inconsistent_edges, 0);
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-12);
}

TEST(MeshTopology, missingTriangleLeavesThreeBoundaryEdges) {
  TriangleMesh m = test::unitCubeMesh();
  m.triangles.pop_back();
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.boundary_edges, 3);
  EXPECT_FALSE(t.watertight());
}

TEST(MeshTopology, flippedTriangleIsInconsistentAndDuplicateMakesNonManifoldEdges) {
  TriangleMesh m = test::unitCubeMesh();
  std::swap(m.triangles[0].v[1], m.triangles[0].v[2]);
  EXPECT_EQ(analyzeTopology(m).inconsistent_edges, 3);
  TriangleMesh d = test::unitCubeMesh();
  d.triangles.push_back(d.triangles[0]);
  EXPECT_EQ(analyzeTopology(d).nonmanifold_edges, 3);
}

TEST(MeshTopology, touchingClosedBodiesAreNonManifoldButBalanced) {
  // Two unit cubes sharing the face x = 1: the shared edges are used four times, twice in each direction.
  TriangleMesh m = test::unitCubeMesh();
  for (Triangle t : test::unitCubeMesh().triangles) {
    for (auto& v : t.v) v.x += 1.0f;
    m.triangles.push_back(t);
  }
  const MeshTopology t = analyzeTopology(m);
  EXPECT_GT(t.nonmanifold_edges, 0);
  EXPECT_FALSE(t.watertight());
  EXPECT_EQ(t.unbalanced_edges, 0);
  EXPECT_TRUE(t.closedOriented());
  TriangleMesh open = test::unitCubeMesh();
  open.triangles.pop_back();
  EXPECT_EQ(analyzeTopology(open).unbalanced_edges, 3);
  EXPECT_FALSE(analyzeTopology(open).closedOriented());
}

TEST(MeshTopology, exporterNoiseOpensTheMeshExactlyButWeldsWithinTheNoiseTolerance) {
  // As in featuretype.stl: one corner written as 1e-35 in some triangles and 0 in others.
  TriangleMesh m = test::unitCubeMesh();
  for (size_t i = 0; i < m.triangles.size(); i += 2)
    for (auto& v : m.triangles[i].v)
      if (v == glm::vec3(0, 0, 0)) v.x = 1e-35f;
  const MeshTopology exact = analyzeTopology(m);
  EXPECT_GT(exact.boundary_edges, 0);
  EXPECT_TRUE(exact.closes_when_noise_welded);
  EXPECT_NEAR(noiseWeldTolerance(m), 1e-9 * std::sqrt(3.0), 1e-15);
  const MeshTopology welded = analyzeTopologyWelded(m, noiseWeldTolerance(m));
  EXPECT_TRUE(welded.watertight());
  EXPECT_TRUE(welded.closedOriented());
  // A real gap (a missing triangle) stays open at any small tolerance.
  m.triangles.pop_back();
  EXPECT_FALSE(analyzeTopology(m).closes_when_noise_welded);
}

TEST(MeshTopology, negativeZeroWeldsWithPositiveZero) {
  TriangleMesh m = test::unitCubeMesh();
  for (auto& t : m.triangles)
    for (auto& v : t.v)
      if (v.x == 0.0f) v.x = -0.0f;
  m.triangles[0].v[0].x = 0.0f;
  EXPECT_TRUE(analyzeTopology(m).watertight());
}

TEST(MeshTopology, degenerateTrianglesAreCounted) {
  TriangleMesh m = test::unitCubeMesh();
  m.triangles.push_back({{{0, 0, 0}, {0, 0, 0}, {1, 1, 1}}});  // repeated vertex
  m.triangles.push_back({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}});  // collinear: zero area
  EXPECT_EQ(analyzeTopology(m).degenerate_triangles, 2);
  EXPECT_FALSE(isDegenerate(m.triangles[0]));
}

TEST(Box3d, boundsOfMeshAndEmptyBox) {
  EXPECT_TRUE(TriangleMesh{}.bounds().empty());
  const Box3d b = test::unitCubeMesh().bounds();
  EXPECT_EQ(b.min, glm::dvec3(0));
  EXPECT_EQ(b.max, glm::dvec3(1));
}

}  // namespace
}  // namespace vox
