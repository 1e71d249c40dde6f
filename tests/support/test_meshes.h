#pragma once
// Meshes built in code for the voxelizer tests, each outward-oriented and closed unless its name says otherwise.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "vox/core/mesh.h"
#include "vox/core/voxel_grid.h"

namespace vox::test {

// Axis-aligned box [lo, hi], 12 triangles.
TriangleMesh boxMesh(glm::dvec3 lo, glm::dvec3 hi);
// Unit-radius icosphere about `centre` with `subdivisions` rounds of 4:1 splitting (20 * 4^n triangles), scaled.
TriangleMesh icosphere(glm::dvec3 centre, double radius, int subdivisions);
// Torus about the Z axis through `centre`: ring radius R, tube radius r, n x m quads split in two.
TriangleMesh torus(glm::dvec3 centre, double ring_radius, double tube_radius, int n, int m);
// Prism along X over a convex polygon given counter-clockwise in the (y, z) plane, from x0 to x1.
TriangleMesh prismAlongX(const std::vector<glm::dvec2>& yz, double x0, double x1);
// Regular octahedron |x - c|_1 <= r, 8 triangles.
TriangleMesh octahedron(glm::dvec3 centre, double r);
// A closed tetrahedron inside the cube [corner, corner + size]^3: small markers that set a mesh's bounding box
// without containing any voxel centre.
TriangleMesh tetrahedron(glm::dvec3 corner, double size);
// Every vertex mapped by p -> centre + rotation * (p - centre).
TriangleMesh transformed(const TriangleMesh& mesh, const glm::dmat3& rotation, glm::dvec3 centre);
// Rotation by `degrees` about the unit axis.
glm::dmat3 rotation(glm::dvec3 axis, double degrees);
// The two meshes' triangles in one soup.
TriangleMesh combined(const TriangleMesh& a, const TriangleMesh& b);

// A cantilever, mm: a 10 x 10 x 20 column on the plate and a 30 x 10 x 5 arm sticking out from its top along +x
// (two boxes touching). Printed along +z, the arm's underside (300 mm^2) hangs 15 mm over the plate: 4500 mm^3.
TriangleMesh cantileverMesh();

// Generalized winding number of the mesh at p (sum of signed solid angles / 4 pi, A. Jacobson et al. 2013): an
// independent inside test for points not within rounding distance of the surface.
double windingNumber(const TriangleMesh& mesh, const glm::dvec3& p);

// Number of voxels where the two grids differ; grids may have different dims (outside one grid reads as empty).
int64_t mismatches(const VoxelGrid& a, const VoxelGrid& b);
// Grid of the same dims and frame as `like`, filled where inside(centre) is true, centre as in docs/conventions.md,
// "Grid placement".
VoxelGrid gridFromPredicate(const VoxelGrid& like, const std::function<bool(const glm::dvec3&)>& inside);

}  // namespace vox::test
