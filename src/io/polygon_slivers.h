#pragma once
// Slivers left by triangulating a polygon. A polygon with three consecutive collinear corners (a face of a block
// whose edge carries the corner of a slot, as in ../shared/meshes/cad/wallhole.obj) can be ear-clipped into a
// zero-area "ear" (a, v, b), v on the segment ab, next to a triangle (a, b, c) that spans the whole segment. The
// surface is right, but the sliver is a degenerate triangle and the long edge ab meets the neighbouring face's two
// short edges av and vb, which the topology report counts as a defect. Splitting (a, b, c) at v into (a, v, c) and
// (v, b, c) and dropping the sliver covers exactly the same area with no degenerate triangle and no T-junction: the
// voxels do not change (the sliver crosses no ray) and the report sees the polygon mesh the file holds.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace vox::io {

using TriangleIndices = std::array<uint32_t, 3>;

// `triangles` are one polygon's (indices into `positions`, consistently oriented); rewritten in place, same count.
// Only slivers whose long edge another of these triangles shares are removed. Returns how many were.
int removePolygonSlivers(std::span<TriangleIndices> triangles, const std::vector<glm::dvec3>& positions);

}  // namespace vox::io
