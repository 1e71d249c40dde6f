#pragma once
// MagicaVoxel .vox (docs/file-format.md, "Volume files"), written here: Debian packages no library for it. The
// format is the public one (github.com/ephtracy/voxel-model: MagicaVoxel-file-format-vox.txt and -extension.txt):
// "VOX " version 150, a MAIN chunk holding the models (SIZE + XYZI chunks), the scene graph (nTRN / nGRP / nSHP),
// one layer (LAYR) and the palette (RGBA). All integers little-endian.
//
// A model is at most 256 voxels along each axis (its coordinates are bytes), so a larger grid is split into 256^3
// blocks (the last along each axis shorter), one model per block that holds a filled voxel, each placed by its own
// transform node where the block lies: model voxel (x, y, z) of the block starting at (x0, y0, z0) is grid voxel
// (x0 + x, y0 + y, z0 + z), and MagicaVoxel's world coordinates are the grid's voxel indices (z up, as in voxmod).
// MagicaVoxel anchors a model's translation at its centre, floor(size / 2) voxels from its first voxel. Every filled
// voxel has colour index 1 (light grey in the palette). The voxel size, origin and units are not stored: MagicaVoxel
// voxels are unit cubes.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/io/file_util.h"

namespace vox::io {

inline constexpr int32_t kMagicaVoxelModelSize = 256;

// One model of the scene: the block of the grid it covers and its filled voxels.
struct MagicaVoxelModel {
  glm::ivec3 first{0};  // the block's first voxel in the grid (multiples of 256)
  glm::ivec3 size{0};   // the block's size, 1..256 per axis (clipped to the grid)
  int64_t voxels = 0;   // filled voxels in it (> 0)
};

// The models a grid becomes: the 256^3 blocks that hold at least one filled voxel, x fastest, then y, then z. An
// empty grid gives one empty model (MagicaVoxel needs one). O(rows x blocks along x), word popcounts.
std::vector<MagicaVoxelModel> planMagicaVoxel(const VoxelGrid& grid);
// Bytes the file will take (header, models, scene graph, palette).
uint64_t magicaVoxelFileBytes(const std::vector<MagicaVoxelModel>& models);

// Streams the file into `sink`. Refused (ErrorCode::kLimit, nothing written) when it would exceed the 2 GiB a .vox
// file's 32-bit chunk sizes can hold: the message says how many filled voxels that is and what to do instead.
Status writeMagicaVoxel(const VoxelGrid& grid, ByteSink& sink, const ProgressFn& progress = {});
Result<std::vector<uint8_t>> encodeMagicaVoxel(const VoxelGrid& grid, const ProgressFn& progress = {});

}  // namespace vox::io
