#include "vox/core/mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>

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

// The surface of the unit cube with each face cut into n x n squares of two triangles: V - E + F = 2.
TriangleMesh tessellatedCube(int n) {
  TriangleMesh m;
  const float s = 1.0f / float(n);
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          auto p = [&](int a, int b) {
            glm::vec3 v(0.0f);
            v[axis] = float(side);
            v[(axis + 1) % 3] = float(a) * s;
            v[(axis + 2) % 3] = float(b) * s;
            return v;
          };
          Triangle t1{{p(i, j), p(i + 1, j), p(i + 1, j + 1)}};
          Triangle t2{{p(i, j), p(i + 1, j + 1), p(i, j + 1)}};
          if (side == 0) {  // outward: reverse the winding on the low side
            std::swap(t1.v[1], t1.v[2]);
            std::swap(t2.v[1], t2.v[2]);
          }
          m.triangles.push_back(t1);
          m.triangles.push_back(t2);
        }
      }
    }
  }
  return m;
}

TEST(MeshTopology, tessellatedCubeSatisfiesEulersFormula) {
  for (int n : {1, 7, 40}) {
    const TriangleMesh m = tessellatedCube(n);
    const MeshTopology t = analyzeTopology(m);
    SCOPED_TRACE("n = " + std::to_string(n));
    EXPECT_EQ(int64_t(m.triangles.size()), 12 * n * n);
    EXPECT_EQ(t.edges, 18 * n * n);
    EXPECT_EQ(t.vertices, 6 * n * n + 2);
    EXPECT_TRUE(t.watertight());
    EXPECT_EQ(t.inconsistent_edges, 0);
    EXPECT_EQ(t.unbalanced_edges, 0);
    EXPECT_NEAR(signedVolume(m), 1.0, 1e-5);
  }
}

TEST(MeshTopology, triangleSoupHasThreeVerticesAndBoundaryEdgesPerTriangle) {
  // Every vertex distinct: three times as many vertices as triangles, more than the welding table starts with.
  TriangleMesh m;
  for (int i = 0; i < 5000; ++i) {
    const float x = float(i);
    m.triangles.push_back({{{x, 0, 0}, {x + 0.5f, 1, 0}, {x, 0, 1}}});
  }
  const MeshTopology t = analyzeTopology(m);
  EXPECT_EQ(t.vertices, 15000);
  EXPECT_EQ(t.edges, 15000);
  EXPECT_EQ(t.boundary_edges, 15000);
  EXPECT_EQ(t.unbalanced_edges, 15000);
  EXPECT_FALSE(t.closes_when_noise_welded);
}

TEST(MeshTopology, countsMatchAStraightforwardReferenceOnRandomMeshes) {
  // Triangles over a small pool of points (shared edges, non-manifold edges, both directions, repeated vertices),
  // checked against an obvious map-based count.
  std::mt19937 rng(12345);
  for (int trial = 0; trial < 20; ++trial) {
    const int pool = 4 + trial * 3;
    std::vector<glm::vec3> points;
    std::uniform_int_distribution<int> coord(-3, 3);
    for (int i = 0; i < pool; ++i) points.emplace_back(coord(rng), coord(rng), coord(rng));
    std::uniform_int_distribution<int> pick(0, pool - 1);
    TriangleMesh m;
    for (int i = 0; i < 10 * pool; ++i)
      m.triangles.push_back({{points[size_t(pick(rng))], points[size_t(pick(rng))], points[size_t(pick(rng))]}});
    std::map<std::array<float, 3>, int> ids;
    auto id = [&](const glm::vec3& v) {
      return ids.emplace(std::array<float, 3>{v.x, v.y, v.z}, int(ids.size())).first->second;
    };
    std::map<std::pair<int, int>, std::pair<int, int>> uses;  // (lo, hi) -> (uses, forward)
    int64_t degenerate = 0;
    for (const Triangle& t : m.triangles) {
      degenerate += isDegenerate(t) ? 1 : 0;
      for (int c = 0; c < 3; ++c) {
        const int a = id(t.v[c]), b = id(t.v[(c + 1) % 3]);
        if (a == b) continue;
        auto& u = uses[{std::min(a, b), std::max(a, b)}];
        ++u.first;
        u.second += a < b ? 1 : 0;
      }
    }
    MeshTopology want;
    want.vertices = int64_t(ids.size());
    want.degenerate_triangles = degenerate;
    for (const auto& [edge, u] : uses) {
      ++want.edges;
      want.boundary_edges += u.first == 1;
      want.nonmanifold_edges += u.first >= 3;
      want.inconsistent_edges += u.first == 2 && u.second != 1;
      want.unbalanced_edges += 2 * u.second != u.first;
    }
    const MeshTopology got = analyzeTopologyWelded(m, 0.0);
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_EQ(got.vertices, want.vertices);
    EXPECT_EQ(got.edges, want.edges);
    EXPECT_EQ(got.boundary_edges, want.boundary_edges);
    EXPECT_EQ(got.nonmanifold_edges, want.nonmanifold_edges);
    EXPECT_EQ(got.inconsistent_edges, want.inconsistent_edges);
    EXPECT_EQ(got.unbalanced_edges, want.unbalanced_edges);
    EXPECT_EQ(got.degenerate_triangles, want.degenerate_triangles);
    // Integer coordinates: welding within a small tolerance changes nothing.
    const MeshTopology rounded = analyzeTopologyWelded(m, 1e-3);
    EXPECT_EQ(rounded.vertices, want.vertices);
    EXPECT_EQ(rounded.unbalanced_edges, want.unbalanced_edges);
  }
}

TEST(Box3d, boundsOfMeshAndEmptyBox) {
  EXPECT_TRUE(TriangleMesh{}.bounds().empty());
  const Box3d b = test::unitCubeMesh().bounds();
  EXPECT_EQ(b.min, glm::dvec3(0));
  EXPECT_EQ(b.max, glm::dvec3(1));
}

}  // namespace
}  // namespace vox
