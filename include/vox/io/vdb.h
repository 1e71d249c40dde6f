#pragma once
// OpenVDB volumes (.vdb: Blender, Houdini), written through libopenvdb (docs/file-format.md, "Volume files").
//
// Every volume is a FloatGrid: the voxels as a grid named "voxels" of class fog volume (1 in filled voxels, active;
// background 0, inactive), each field as a grid under its own name (active where the value is not 0). A float fog
// volume is the grid both tools shade as a density: Blender's Volume object renders it through the Principled Volume
// shader (pick "voxels" as its density attribute; the shader looks for "density" by default), Houdini's VDB nodes
// take it as a density volume. A BoolGrid would be smaller but is a mask, not a density, to both. Index (i, j, k)
// of every grid is voxel (i, j, k); the transform maps it to the voxel's centre (scale = voxel size, translation =
// the centre of voxel (0, 0, 0)); each grid carries the units as string metadata "units" ("mm", ..., "model" when
// unknown) and the grid's dims (nx, ny, nz) as vec3i metadata "dims" (a VDB grid itself has no bounds). 8^3 blocks that
// are entirely filled are stored as active tiles, so a solid part costs little. Written with OpenVDB's default
// compression (Blosc) and its per-grid statistics (file_bbox_min/max, file_voxel_count, file_mem_bytes).
#include <cstdint>
#include <vector>

#include "vox/io/volume_export.h"

namespace vox::io {

// The file in memory. Errors: content that does not fit (volumeContentProblem), OpenVDB's own, cancellation.
Result<std::vector<uint8_t>> encodeVdb(const VolumeContent& content, const ProgressFn& progress = {});

}  // namespace vox::io
