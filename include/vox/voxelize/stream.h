#pragma once
// Solid voxelization of a grid larger than memory, in slabs of Z layers (docs/file-format.md, "Streamed `.vxm`
// files"): each slab is voxelized exactly as voxelizeSolid would voxelize those layers (the same ray caster over the
// whole grid, restricted to the slab's rows, so the same voxels) and handed to a sink, lowest slab first, then
// freed. Peak memory: one slab, the mesh, the ray caster's index (8 bytes per triangle) and whatever the sink holds.
// Parity and nonzero mode only: vote mode's rays along Y and Z need every layer at once.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/voxelize/voxelize.h"

namespace vox {

// A slab at most this large: bigger slabs buy no speed (each slab costs one sweep set-up per thread).
inline constexpr uint64_t kMaxSlabBytes = uint64_t(512) << 20;

// Layers per slab when the grid of `params` over `bounds` does not fit under the memory limit in force (the grid's
// estimate, estimateGridBytes, above it) and so must be streamed; 0 when it fits. A slab takes what the limit leaves
// after `held_bytes` (the mesh and the ray caster's index) and at most kMaxSlabBytes, and at least one layer.
// `mode` is the resolved fill mode (vote mode is never streamed: 0).
Result<int32_t> streamSlabLayers(const Box3d& bounds, const VoxelizeParams& params, FillMode mode, uint64_t held_bytes);

// Bytes the mesh and the voxelizer's index of it take while a slab is voxelized (for streamSlabLayers).
uint64_t meshHeldBytes(const TriangleMesh& mesh);

// What the sink gets: layers [z_begin, z_end) of the grid, held as layers 0 .. z_end - z_begin of `slab` (dims nx,
// ny, z_end - z_begin; the grid's frame). A failure stops the voxelization and is returned.
using SlabSink = std::function<Status(const VoxelGrid& slab, int32_t z_begin, int32_t z_end)>;

// Rays along X that warn (an odd number of crossings; in nonzero mode, a winding that does not come back to zero),
// counted over the slabs voxelized, and the rays of the whole grid.
struct RayCounts {
  int64_t odd = 0, unbalanced = 0, rays = 0;
};

// A share of the slabs, for voxelizing one grid in several processes (MPI ranks): slab k (layers
// [k slab_layers, (k + 1) slab_layers)) is this share's when k % parts == part. Every share voxelizes its slabs
// exactly as the whole run would.
struct SlabShare {
  int32_t part = 0, parts = 1;
  bool owns(int32_t slab) const { return slab % parts == part; }
};

struct StreamedVoxelization {
  Dims dims;  // of the whole grid
  GridFrame frame;
  FillMode mode_used = FillMode::kParity;
  std::string mode_reason;
  // The warnings; of a share of the slabs (SlabShare::parts > 1), all but those about the rays, which the
  // counts of every share give (addRayWarnings).
  std::vector<std::string> warnings;
  RayCounts rays;                      // over the slabs voxelized here
  int64_t filled = 0;                  // in the slabs voxelized here
  int32_t slabs = 0, slab_layers = 0;  // slabs voxelized here; layers per slab
  uint64_t largest_slab_bytes = 0;     // VoxelGrid::memoryBytes of the largest slab
};

// Voxelizes `mesh` in slabs of `slab_layers` layers (> 0), calling `sink` for each (of `share`'s slabs only, in
// order). Fails like voxelizeSolid (kInvalidArgument, kCancelled, kLimit when a slab runs out of memory), with
// kUnsupported for vote mode or params.remove_strays, and with the sink's error.
Result<StreamedVoxelization> voxelizeInSlabs(const TriangleMesh& mesh, const VoxelizeParams& params,
                                             int32_t slab_layers, const SlabSink& sink, const ProgressFn& progress = {},
                                             const MeshTopology* topology = nullptr, const SlabShare& share = {});

// Appends to r.warnings the warnings about the rays that `counts` (summed over every share of the grid) give, as
// the whole run gives them.
void addRayWarnings(StreamedVoxelization& r, const RayCounts& counts);

}  // namespace vox
