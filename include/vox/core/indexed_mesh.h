#pragma once
// Triangles over shared vertices: what a surface extracted from voxels is, and what PLY, OBJ and 3MF store. STL
// stores a triangle soup (TriangleMesh, vox/core/mesh.h); toTriangleMesh() gives it.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/mesh.h"

namespace vox {

struct IndexedMesh {
  std::vector<glm::dvec3> vertices;                // model units
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  std::string name;

  TriangleMesh toTriangleMesh() const;
};

}  // namespace vox
