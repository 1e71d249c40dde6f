#include "vox/core/mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

namespace vox {

void Box3d::expand(const glm::dvec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

Box3d TriangleMesh::bounds() const {
  Box3d b;
  for (const Triangle& t : triangles) {
    for (const glm::vec3& v : t.v) b.expand(glm::dvec3(v));
  }
  return b;
}

bool isDegenerate(const Triangle& t) {
  if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[0] == t.v[2]) return true;
  const glm::dvec3 a(t.v[0]), b(t.v[1]), c(t.v[2]);
  const glm::dvec3 n = glm::cross(b - a, c - a);
  return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

namespace {

// Key for welding. Exact (tolerance 0): the float bits, with -0 folded onto +0. With a tolerance: each coordinate
// rounded to a multiple of it, so positions closer than the tolerance usually (not when they straddle a rounding
// boundary) share a key: enough to see through exporter noise such as 0 vs 1e-35.
std::array<int64_t, 3> positionKey(const glm::vec3& v, double tolerance) {
  std::array<int64_t, 3> k{};
  for (int i = 0; i < 3; ++i) {
    if (tolerance > 0.0) {
      k[size_t(i)] = std::llround(double(v[i]) / tolerance);
    } else {
      const float f = v[i] == 0.0f ? 0.0f : v[i];
      uint32_t bits = 0;
      std::memcpy(&bits, &f, sizeof(float));
      k[size_t(i)] = bits;
    }
  }
  return k;
}

}  // namespace

MeshTopology analyzeTopology(const TriangleMesh& mesh) {
  MeshTopology topo = analyzeTopologyWelded(mesh, 0.0);
  if (topo.boundary_edges > 0) {
    topo.closes_when_noise_welded = analyzeTopologyWelded(mesh, noiseWeldTolerance(mesh)).closedOriented();
  }
  return topo;
}

MeshTopology analyzeTopologyWelded(const TriangleMesh& mesh, double weld_tolerance) {
  MeshTopology topo;
  const size_t nt = mesh.triangles.size();
  // Weld: sort corner keys, give equal keys one id.
  struct Corner {
    std::array<int64_t, 3> key;
    uint32_t corner;
  };
  std::vector<Corner> corners(nt * 3);
  for (size_t t = 0; t < nt; ++t) {
    for (size_t c = 0; c < 3; ++c)
      corners[t * 3 + c] = {positionKey(mesh.triangles[t].v[c], weld_tolerance), uint32_t(t * 3 + c)};
  }
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) { return a.key < b.key; });
  std::vector<uint32_t> vid(nt * 3);
  uint32_t next = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (i > 0 && corners[i].key != corners[i - 1].key) ++next;
    vid[corners[i].corner] = next;
  }
  topo.vertices = corners.empty() ? 0 : int64_t(next) + 1;

  // Each directed edge as ((min id << 32) | max id, forward?); equal keys after sorting are one undirected edge.
  std::vector<std::pair<uint64_t, uint8_t>> de;
  de.reserve(nt * 3);
  for (size_t t = 0; t < nt; ++t) {
    if (isDegenerate(mesh.triangles[t])) ++topo.degenerate_triangles;
    for (size_t c = 0; c < 3; ++c) {
      const uint32_t a = vid[t * 3 + c], b = vid[t * 3 + (c + 1) % 3];
      if (a == b) continue;
      const uint64_t lo = std::min(a, b), hi = std::max(a, b);
      de.emplace_back(lo << 32 | hi, uint8_t(a < b ? 1 : 0));
    }
  }
  std::sort(de.begin(), de.end());
  for (size_t i = 0; i < de.size();) {
    size_t j = i;
    int forward = 0;
    while (j < de.size() && de[j].first == de[i].first) forward += de[j++].second;
    const size_t uses = j - i;
    ++topo.edges;
    if (uses == 1) ++topo.boundary_edges;
    if (uses >= 3) ++topo.nonmanifold_edges;
    if (uses == 2 && forward != 1) ++topo.inconsistent_edges;
    if (2 * size_t(forward) != uses) ++topo.unbalanced_edges;
    i = j;
  }
  return topo;
}

double noiseWeldTolerance(const TriangleMesh& mesh) {
  const Box3d b = mesh.bounds();
  return b.empty() ? 0.0 : 1e-9 * glm::length(b.extent());
}

double signedVolume(const TriangleMesh& mesh) {
  const Box3d b = mesh.bounds();
  if (b.empty()) return 0.0;
  const glm::dvec3 c = (b.min + b.max) * 0.5;
  double sum = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const glm::dvec3 p0 = glm::dvec3(t.v[0]) - c, p1 = glm::dvec3(t.v[1]) - c, p2 = glm::dvec3(t.v[2]) - c;
    sum += glm::dot(p0, glm::cross(p1, p2));
  }
  return sum / 6.0;
}

}  // namespace vox
