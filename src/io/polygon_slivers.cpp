#include "io/polygon_slivers.h"

#include <glm/geometric.hpp>

namespace vox::io {
namespace {

// The corner k of a zero-area triangle that lies strictly inside the opposite edge, or -1. The cross product and
// dot products are of float coordinates promoted to double: exact enough to tell zero area (as isDegenerate does)
// and "strictly between" apart from a repeated corner.
int cornerInsideOppositeEdge(const TriangleIndices& t, const std::vector<glm::dvec3>& p) {
  const glm::dvec3 &p0 = p[t[0]], &p1 = p[t[1]], &p2 = p[t[2]];
  if (glm::cross(p1 - p0, p2 - p0) != glm::dvec3(0.0)) return -1;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3& v = p[t[k]];
    const glm::dvec3& a = p[t[(k + 2) % 3]];
    const glm::dvec3& b = p[t[(k + 1) % 3]];
    if (glm::dot(v - a, b - a) > 0.0 && glm::dot(v - b, a - b) > 0.0) return k;
  }
  return -1;
}

// The triangle (other than `skip`) with the directed edge a -> b, and the position of a in it; -1 if none.
int findEdge(std::span<const TriangleIndices> triangles, size_t skip, uint32_t a, uint32_t b, int& corner) {
  for (size_t i = 0; i < triangles.size(); ++i) {
    if (i == skip) continue;
    for (int k = 0; k < 3; ++k) {
      if (triangles[i][k] == a && triangles[i][(k + 1) % 3] == b) {
        corner = k;
        return int(i);
      }
    }
  }
  return -1;
}

bool removeOne(std::span<TriangleIndices> triangles, const std::vector<glm::dvec3>& positions) {
  for (size_t i = 0; i < triangles.size(); ++i) {
    const int k = cornerInsideOppositeEdge(triangles[i], positions);
    if (k < 0) continue;
    // The sliver runs a -> v -> b; its long edge b -> a is shared with a triangle running a -> b -> c.
    const uint32_t v = triangles[i][k], a = triangles[i][(k + 2) % 3], b = triangles[i][(k + 1) % 3];
    int corner = 0;
    const int j = findEdge(triangles, i, a, b, corner);
    if (j < 0) continue;
    const uint32_t c = triangles[size_t(j)][(corner + 2) % 3];
    triangles[i] = {a, v, c};
    triangles[size_t(j)] = {v, b, c};
    return true;
  }
  return false;
}

}  // namespace

int removePolygonSlivers(std::span<TriangleIndices> triangles, const std::vector<glm::dvec3>& positions) {
  int removed = 0;
  // Each split replaces a sliver by two triangles of positive area unless c is collinear too; bounded either way.
  for (size_t round = 0; round < 2 * triangles.size() && removeOne(triangles, positions); ++round) ++removed;
  return removed;
}

}  // namespace vox::io
