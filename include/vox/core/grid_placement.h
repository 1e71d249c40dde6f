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
};

// From a resolution R in [1, kMaxResolution]. Fails for an empty or non-finite box, or a box with zero extent (kParse:
// the input mesh is unusable; an out-of-range R is kInvalidArgument).
Result<GridPlacement> placeGridByResolution(const Box3d& bounds, int64_t resolution);
// From a voxel size h > 0 in model units: R = ceil(largest extent / h). Fails when R exceeds kMaxResolution.
Result<GridPlacement> placeGridByVoxelSize(const Box3d& bounds, double voxel_size);

}  // namespace vox
