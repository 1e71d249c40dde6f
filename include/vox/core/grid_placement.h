#pragma once
// Grid placement from a mesh's bounding box (docs/conventions.md, "Grid placement"): h = largest extent / R, origin =
// bbox min, n_axis = max(1, ceil(extent_axis / h)), so the longest axis has exactly R voxels.
#include <cstdint>

#include "vox/core/mesh.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

inline constexpr int32_t kMaxResolution = 16384;  // VoxelGrid::kMaxDim; past about 4096 only a streamed .vxm fits

struct GridPlacement {
  Dims dims;
  GridFrame frame;         // origin and voxel size; units and source left for the caller
  int32_t resolution = 0;  // voxels along the longest axis
  // Lattice index of voxel (0, 0, 0): its centres are frame.origin + ((first + i + 0.5) h, ...), computed exactly so,
  // with frame.origin the lattice's origin. Nonzero for a grid covering part of a larger grid's lattice (a body of an
  // assembly voxelized over its own box, docs/conventions.md "Assemblies"), whose voxels then equal that grid's.
  glm::ivec3 first{0};
};

// From a resolution R in [1, kMaxResolution]. Fails for an empty or non-finite box, or a box with zero extent (kParse:
// the input mesh is unusable; an out-of-range R is kInvalidArgument).
Result<GridPlacement> placeGridByResolution(const Box3d& bounds, int64_t resolution);
// From a voxel size h > 0 in model units: R = ceil(largest extent / h). Fails when R exceeds kMaxResolution.
Result<GridPlacement> placeGridByVoxelSize(const Box3d& bounds, double voxel_size);
// The voxels [first, first + dims) of the lattice `lattice` (its origin and voxel size), as a placement. dims must each
// be at least 1.
GridPlacement placeGridOnLattice(const GridFrame& lattice, const glm::ivec3& first, const Dims& dims);
// The box of lattice voxels (of the lattice with `lattice`'s origin and voxel size) whose centres may lie inside
// `bounds`, with a voxel of margin on every side, as a placement: how a mesh joins an assembly whose lattice is already
// fixed. Fails (kLimit) when that box would be longer than kMaxResolution voxels, or lies more than 2^30 voxels from
// the lattice origin (kInvalidArgument for an empty or non-finite box).
Result<GridPlacement> placeBoundsOnLattice(const GridFrame& lattice, const Box3d& bounds);
// The lattice voxels whose centres may lie inside `bounds` (model units) on `placement`'s lattice: from the first
// centre at or above bounds.min to the last at or below bounds.max on each axis, clamped to the placement's voxels
// [first, first + dims). Empty (first == end on some axis) when no centre lies inside on some axis.
void latticeRange(const GridPlacement& placement, const Box3d& bounds, glm::ivec3& begin, glm::ivec3& end);

}  // namespace vox
