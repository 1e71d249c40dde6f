#pragma once
// Whole-grid scalar fields of the skin depth and the X-ray, for volume export (vox/io/volume_export.h) beside the
// thickness and distance fields of thickness_map.h. Each lies on the grid's lattice (GridFrame: the centre of voxel
// (i, j, k) is frame.voxelCentre(i, j, k)).
#include "vox/analysis/analysis.h"
#include "vox/core/scalar_field.h"

namespace vox {

// The skin layer that removes each voxel (1 = the outer skin, layers() = the core), 0 in empty voxels and in voxels
// a map stopped early did not reach. A count of layers, not a length. `frame` and dims are the peeled grid's.
// O(voxels x bits of depth).
ScalarField depthField(const DepthMap& depth, const VoxelGrid& grid);
// An X-ray as a slab one voxel thick: dims 1 along the X-ray's axis, the grid's along the other two, placed at the
// grid's first layer along the axis; each ray's thickness (min, max or total, as computed) in model units, 0 where
// the ray hits nothing. `grid` is the one the X-ray was computed from.
ScalarField xrayField(const XrayResult& xray, const VoxelGrid& grid);

}  // namespace vox
