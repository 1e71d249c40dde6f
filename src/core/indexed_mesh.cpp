#include "vox/core/indexed_mesh.h"

namespace vox {

TriangleMesh IndexedMesh::toTriangleMesh() const {
  TriangleMesh m;
  m.name = name;
  m.triangles.reserve(triangles.size());
  for (const auto& t : triangles) {
    m.triangles.push_back(Triangle{{glm::vec3(vertices[t[0]]), glm::vec3(vertices[t[1]]), glm::vec3(vertices[t[2]])}});
  }
  return m;
}

}  // namespace vox
