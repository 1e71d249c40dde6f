#pragma once
// A section plane on the voxel lattice and the slab of voxels it cuts: the rule the 3D view's cut-away draws by
// (render) and the cut-away export keeps by (analysis), so both agree voxel for voxel.
#include <cmath>

#include <glm/vec3.hpp>

namespace vox {

// The plane dot(normal, c) = offset, c a voxel's centre in voxel coordinates (voxel (i, j, k) has its centre at
// (i + 0.5, j + 0.5, k + 0.5)), normal of unit length. A voxel with s = dot(normal, c) - offset lies below the slab
// when s < -half, inside it when -half <= s < half, above it when s >= half. half is half the L1 norm of the normal,
// so the slab is the standard digital plane: one voxel thick, without gaps between face neighbours. An axis section
// at index i is the plane normal to its axis with offset i + 0.5, half 0.5; its slab the voxels of index i.
struct SectionPlane {
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  float offset = 0.0f;
  float half = 0.5f;
};

// The axis (0, 1, 2 for X, Y, Z) of a vector's largest component in magnitude (the first of equal ones).
template <class Vec>
int dominantAxis(const Vec& v) {
  const auto ax = v.x < 0 ? -v.x : v.x, ay = v.y < 0 ? -v.y : v.y, az = v.z < 0 ? -v.z : v.z;
  return ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
}

// The unit vector along v, scaled by its largest component first so that neither tiny nor huge components under- or
// overflow; false for a zero or non-finite v.
inline bool unitVector(const glm::dvec3& v, glm::dvec3& out) {
  const double big = std::abs(v[dominantAxis(v)]);
  if (!(big > 0.0) || !std::isfinite(big)) return false;
  const glm::dvec3 w = v / big;
  const double length = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
  if (!std::isfinite(length)) return false;
  out = w / length;
  return true;
}

// The plane with this unit normal and offset, its half-thickness from the normal.
inline SectionPlane sectionPlaneOf(const glm::vec3& normal, float offset) {
  const float l1 = (normal.x < 0 ? -normal.x : normal.x) + (normal.y < 0 ? -normal.y : normal.y) +
                   (normal.z < 0 ? -normal.z : normal.z);
  return SectionPlane{normal, offset, 0.5f * l1};
}

// -1 below the plane's slab, 0 inside it, +1 above it (the arithmetic the renderer's points.vert writes; a GPU may
// fuse its multiply-adds, so a voxel centre exactly on a face of the slab may fall either way there: the window moves
// its planes off the voxel centres, app/section_plane.h).
inline int sectionSlab(const SectionPlane& plane, const glm::ivec3& voxel) {
  const float cx = float(voxel.x) + 0.5f, cy = float(voxel.y) + 0.5f, cz = float(voxel.z) + 0.5f;
  const float s = plane.normal.x * cx + plane.normal.y * cy + plane.normal.z * cz - plane.offset;
  return s < -plane.half ? -1 : s >= plane.half ? 1 : 0;
}

}  // namespace vox
