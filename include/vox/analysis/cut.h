#pragma once
// One side of a section plane as a model of its own: what the window's cut-away shows, for exporting it.
#include <cstdint>

#include "vox/analysis/analysis.h"
#include "vox/core/section_plane.h"
#include "vox/core/voxel_grid.h"

namespace vox {

// The voxels of `grid` with coordinate <= index along `axis` (keep_above false) or >= index (keep_above true): the
// half the cut-away keeps, with the plane's own voxels (drawn as the cut face). Same dims and frame; layers that
// need no change are shared with `grid`. An index outside the grid keeps everything or nothing.
VoxelGrid cutAway(const VoxelGrid& grid, Axis axis, int32_t index, bool keep_above);

// The same for a plane at any angle (vox/core/section_plane.h): the voxels below its slab and in it (keep_above
// false), or in it and above it (keep_above true).
VoxelGrid cutAway(const VoxelGrid& grid, const SectionPlane& plane, bool keep_above);

}  // namespace vox
