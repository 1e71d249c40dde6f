#pragma once
// Triangle soup as read from an STL file: vertices as stored (float32), no shared-vertex structure. Topology
// (watertightness) is measured by welding vertices with exactly equal coordinates, as the shared corpus does.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace vox {

struct Triangle {
  glm::vec3 v[3];
};

// Axis-aligned box in model units. An empty box has min > max.
struct Box3d {
  glm::dvec3 min{1e300};
  glm::dvec3 max{-1e300};
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  glm::dvec3 extent() const { return empty() ? glm::dvec3(0) : max - min; }
  void expand(const glm::dvec3& p);
};

struct TriangleMesh {
  std::vector<Triangle> triangles;
  std::string name;  // usually the source file's name; used in messages

  // Bounding box of all vertices, float32 promoted to double (docs/conventions.md, "Grid placement").
  Box3d bounds() const;
};

struct MeshTopology {
  int64_t vertices = 0;            // distinct positions (exact float equality; -0 == +0)
  int64_t edges = 0;               // distinct undirected edges
  int64_t boundary_edges = 0;      // used by exactly one triangle
  int64_t nonmanifold_edges = 0;   // used by three or more triangles
  int64_t inconsistent_edges = 0;  // two-triangle edges traversed in the same direction by both (mixed winding)
  // Edges not traversed equally often in both directions (boundary edges among them). When there are none, the
  // surface is a closed oriented cycle: the winding number is defined everywhere, even where closed bodies touch
  // or overlap (non-manifold edges used 2 + 2 times), so the nonzero rule gives their union exactly.
  int64_t unbalanced_edges = 0;
  int64_t degenerate_triangles = 0;  // a repeated vertex or exactly zero area
  // Exact welding found boundary edges, but welding vertices within noiseWeldTolerance() closes the surface
  // (exporter noise, e.g. a corner written as 0 in one triangle and 1e-35 in the next).
  bool closes_when_noise_welded = false;
  bool watertight() const { return boundary_edges == 0 && nonmanifold_edges == 0; }
  bool closedOriented() const { return edges > 0 && unbalanced_edges == 0; }
};

// Welds vertices by exact coordinate equality and counts edges by use; when that leaves boundary edges, a second
// pass welds within noiseWeldTolerance() to fill closes_when_noise_welded. Expected O(T) time (a hash table of
// positions, then edges bucketed by vertex) and about 16 bytes per triangle of scratch memory. Throws
// std::length_error beyond UINT32_MAX / 3 triangles (corners are numbered in 32 bits; the STL reader refuses such
// files first).
MeshTopology analyzeTopology(const TriangleMesh& mesh);
// Vertex ids of the 3 T corners (corner c = triangle c / 3, vertex c % 3) after welding exactly equal positions
// (-0 == +0), numbered from 0 in order of first appearance; `vertices` gets how many there are. Expected O(T).
std::vector<uint32_t> weldExactVertices(const TriangleMesh& mesh, int64_t& vertices);
// One pass, welding by rounding coordinates to multiples of weld_tolerance (model units; 0 = exact equality).
MeshTopology analyzeTopologyWelded(const TriangleMesh& mesh, double weld_tolerance);

// The tolerance the shared corpus uses to tell exporter noise from real gaps: 1e-9 of the bounding-box diagonal.
double noiseWeldTolerance(const TriangleMesh& mesh);

// Signed volume by the divergence theorem (positive for an outward-oriented closed mesh), in model units cubed.
// Summed about the bounding-box centre to limit cancellation.
double signedVolume(const TriangleMesh& mesh);

// True when the triangle has a repeated vertex or exactly zero area (its cross product is zero in double).
bool isDegenerate(const Triangle& t);

}  // namespace vox
