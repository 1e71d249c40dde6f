#pragma once
// CPU side of the point renderer (thesis 5.1 and 6.2; the thesis's closing remark on a "display list" of visible
// voxels): the surface voxels of a grid packed as 8-byte points, sliced per Z layer and grouped by neighbour code.
//  - Per-layer slices: an edit of layers [z0, z1) re-extracts only those layers (and their two Z neighbours, whose
//    codes depend on them), not the whole grid.
//  - Grouped by code: all points of one code share their free faces, so a whole group whose free faces all face away
//    from the camera can be skipped at draw time (visibleCodes()).
// Also here: the section (cut-away) rule and its cut-face points, and the 2x downsampling for level of detail.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/section_plane.h"
#include "vox/core/voxel_grid.h"
#include "vox/render/camera.h"

namespace vox::render {

// One surface voxel as the GPU reads it (vertex attributes: uvec3 from 3 x GL_UNSIGNED_SHORT, uvec2 from
// 2 x GL_UNSIGNED_BYTE). 16-bit coordinates suffice because VoxelGrid::kMaxDim is 16384.
struct PackedPoint {
  uint16_t x = 0, y = 0, z = 0;
  uint8_t code = 0;   // face-neighbour code (docs/conventions.md, "Face-neighbour code"), < 63
  uint8_t flags = 0;  // kPointFlag* bits
  bool operator==(const PackedPoint&) const = default;
};
static_assert(sizeof(PackedPoint) == 8, "the vertex layout in points.vert assumes 8-byte points");

// A point of the section face (drawn in the cut colour, never clipped by the section).
inline constexpr uint8_t kPointFlagCut = 1;

inline constexpr int kCodeGroups = 64;  // group 63 (interior) is always empty

struct CutAway;  // below

// The surface points of one Z layer, sorted by code: points[group_first[c], group_first[c + 1]) have code c.
struct LayerSlice {
  std::vector<PackedPoint> points;
  std::array<uint32_t, kCodeGroups + 1> group_first{};
  uint32_t groupSize(int code) const { return group_first[size_t(code) + 1] - group_first[size_t(code)]; }
};

// Points of a whole grid in draw order: code-major (all code-0 points, then code 1, ...), each group in z, y, x
// order. group_first has 65 entries like LayerSlice's.
struct PointBuffer {
  std::vector<PackedPoint> points;
  std::array<int64_t, kCodeGroups + 1> group_first{};
  int64_t groupSize(int code) const { return group_first[size_t(code) + 1] - group_first[size_t(code)]; }
};

class PointCloud {
 public:
  PointCloud() = default;
  // Same as build(grid).
  explicit PointCloud(const VoxelGrid& grid) { build(grid); }

  // Extracts every surface voxel (code < 63). Cost O(grid words + surface voxels); layers are split among up to
  // `threads` threads (0 = hardware concurrency).
  void build(const VoxelGrid& grid, int threads = 0);
  // After an edit that changed voxels only in layers [z0, z1) (clamped to the grid), re-extracts those layers and
  // layers z0 - 1 and z1, whose codes see the edited layers. The grid must have the dims this cloud was built with;
  // if it does not (or the cloud is empty), this is build(grid). Afterwards the cloud equals PointCloud(grid).
  void rebuildLayers(const VoxelGrid& grid, int32_t z0, int32_t z1);

  const Dims& dims() const { return dims_; }
  int32_t layerCount() const { return int32_t(layers_.size()); }
  const LayerSlice& layer(int32_t z) const { return layers_[size_t(z)]; }
  // Total points, and per code, over all layers.
  int64_t size() const { return total_; }
  int64_t groupSize(int code) const { return group_totals_[size_t(code)]; }
  // Incremented by every build / rebuildLayers, so a GPU copy can tell that it is stale.
  uint64_t version() const { return version_; }

  // Tight box of the points in voxel-index space (the grid's box when there are none). O(points).
  Box3 bounds() const;
  // The same for what a section leaves: the kept half and the section plane (whose filled voxels the surface points
  // of the plane enclose). bounds() when nothing is kept or without a section.
  Box3 bounds(const CutAway& section) const;

  // Concatenates the layers in draw order (see PointBuffer). O(points).
  void assemble(PointBuffer& out) const;

 private:
  void recount();

  Dims dims_{};
  std::vector<LayerSlice> layers_;
  std::array<int64_t, kCodeGroups> group_totals_{};
  int64_t total_ = 0;
  uint64_t version_ = 0;
};

// Extracts the surface points of layer z (one slice of PointCloud).
LayerSlice extractLayer(const VoxelGrid& grid, int32_t z);

// ---- Back-facing group culling ----

// Outward normals of the six faces in the code's bit order (bit 32 = y-1 face first): the normal of the face a
// neighbour bit refers to.
inline constexpr std::array<std::array<int, 3>, 6> kFaceNormals = {
    {{0, -1, 0}, {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}}};
inline constexpr std::array<uint8_t, 6> kFaceBits = {32, 16, 8, 4, 2, 1};

// Which of the six face directions (index as kFaceNormals) can be seen from the camera by some voxel face inside
// `box` (voxel-index space). Orthographic: a face is visible when its normal points towards the eye direction
// (dot > 0). Perspective, conservatively: the +X faces can be seen when the eye lies beyond the smallest x a +X face
// plane can take inside the box (eye.x > box.min.x), and so on; a face whose plane contains the eye counts as unseen.
std::array<bool, 6> visibleFaceDirections(const Camera& camera, const Box3& box);

// Which code groups have at least one free face in a visible direction (code 0, all faces free, whenever any
// direction is visible; code 63 never). A group that fails this has all its free faces facing away from the eye, so
// on a closed surface its points are hidden behind nearer ones and can be skipped.
std::array<bool, kCodeGroups> visibleCodes(const std::array<bool, 6>& visible_directions);

// ---- Cut-away (a section plane in the 3D view) ----

// kX, kY, kZ: a plane perpendicular to that axis at a voxel index; kPlane: a plane at any angle.
enum class SectionAxis { kNone, kX, kY, kZ, kPlane };
// Which half is kept: voxels with coordinate < index (kBelow) or > index (kAbove) along the axis; for kPlane, voxels
// below or above the plane's slab (sectionSlab). The filled voxels of the plane (coordinate == index, or inside the
// slab) are drawn as the cut face.
enum class SectionSide { kBelow, kAbove };

struct CutAway {
  SectionAxis axis = SectionAxis::kNone;
  int32_t index = 0;  // voxel index along the axis
  SectionSide side = SectionSide::kBelow;
  // kPlane: the plane dot(normal, c) = offset, c a voxel's centre in voxel coordinates (voxel (i, j, k) has its centre
  // at (i + 0.5, j + 0.5, k + 0.5)); normal of unit length.
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  float offset = 0.0f;
  bool active() const { return axis != SectionAxis::kNone; }
  bool operator==(const CutAway&) const = default;
};

// The plane of an active section (vox/core/section_plane.h) in the coordinates of the level of detail with 2^level
// fine voxels per point.
SectionPlane sectionPlane(const CutAway& section, int level = 0);

// Whether a surface point at these voxel coordinates is drawn under this section (mirrors points.vert). Always true
// without a section.
bool keepsPoint(const CutAway& section, const glm::ivec3& voxel);

// The cut face: every filled voxel of the section plane (interior or not; for kPlane, of its slab), flagged
// kPointFlagCut, with the code the voxel has in the grid. Empty without a section or when the plane lies outside the
// grid. Cost O(plane area) bit reads for X, Y and any-angle sections, O(layer words) for Z.
std::vector<PackedPoint> sectionPoints(const VoxelGrid& grid, const CutAway& section);

// ---- Level of detail ----

// The grid at half resolution: coarse voxel (i, j, k) is filled when any of fine voxels (2i..2i+1, 2j..2j+1,
// 2k..2k+1) is; dims are ceil(n / 2). The frame's voxel size doubles. Cost O(fine words) with word operations.
// Layers [z0, z1) of the coarse grid only, into an existing coarse grid, when z1 > z0 (for incremental edits).
VoxelGrid downsample2(const VoxelGrid& fine);
void downsample2Layers(const VoxelGrid& fine, VoxelGrid& coarse, int32_t z0, int32_t z1);

}  // namespace vox::render
