#pragma once
// The bodies (shells) of a triangle soup: triangles connected through shared vertices, after welding exactly equal
// positions (docs/conventions.md, "Assemblies"). Body i is the one whose first triangle comes i-th in the file, so
// the numbering depends only on the file.
#include <cstdint>
#include <vector>

#include "vox/core/mesh.h"

namespace vox {

struct MeshBodies {
  std::vector<uint32_t> body_of;                 // per triangle: its body
  std::vector<std::vector<uint32_t>> triangles;  // per body: its triangles' indices, in file order
  size_t count() const { return triangles.size(); }
};

// Expected O(T) time (a hash table of positions, then union-find over the triangles' vertices); about 24 bytes per
// triangle. Degenerate triangles join the bodies their vertices touch like any other.
MeshBodies splitBodies(const TriangleMesh& mesh);

// Body `i` as a mesh of its own (its triangles in file order), named "<mesh name> body <i>".
TriangleMesh bodyMesh(const TriangleMesh& mesh, const MeshBodies& bodies, size_t i);

}  // namespace vox
