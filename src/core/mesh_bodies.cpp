// Shells of a triangle soup by union-find over welded vertex ids (each triangle joins its three vertices), then
// numbered by first triangle.
#include "vox/core/mesh_bodies.h"

#include <numeric>
#include <string>

namespace vox {
namespace {

// Union-find with path halving and union by index (the smaller root wins, so roots stay stable and cheap).
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

void join(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a == b) return;
  if (a < b) {
    parent[b] = a;
  } else {
    parent[a] = b;
  }
}

}  // namespace

MeshBodies splitBodies(const TriangleMesh& mesh) {
  MeshBodies out;
  const size_t nt = mesh.triangles.size();
  if (nt == 0) return out;
  int64_t vertices = 0;
  const std::vector<uint32_t> vid = weldExactVertices(mesh, vertices);
  std::vector<uint32_t> parent(static_cast<size_t>(vertices));
  std::iota(parent.begin(), parent.end(), 0u);
  for (size_t t = 0; t < nt; ++t) {
    join(parent, vid[3 * t], vid[3 * t + 1]);
    join(parent, vid[3 * t], vid[3 * t + 2]);
  }
  // Number the roots by first triangle: a root's body is the next number when one of its triangles is first seen.
  constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> body_of_root(static_cast<size_t>(vertices), kNone);
  out.body_of.resize(nt);
  for (size_t t = 0; t < nt; ++t) {
    const uint32_t root = findRoot(parent, vid[3 * t]);
    uint32_t& b = body_of_root[root];
    if (b == kNone) {
      b = uint32_t(out.triangles.size());
      out.triangles.emplace_back();
    }
    out.body_of[t] = b;
    out.triangles[b].push_back(uint32_t(t));
  }
  return out;
}

TriangleMesh bodyMesh(const TriangleMesh& mesh, const MeshBodies& bodies, size_t i) {
  TriangleMesh m;
  m.name = (mesh.name.empty() ? std::string("mesh") : mesh.name) + " body " + std::to_string(i);
  m.triangles.reserve(bodies.triangles[i].size());
  for (uint32_t t : bodies.triangles[i]) m.triangles.push_back(mesh.triangles[t]);
  return m;
}

}  // namespace vox
