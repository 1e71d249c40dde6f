// Solid voxelization in slabs of Z layers, for grids larger than memory (vox/voxelize/stream.h). The pass along X
// (fill.cpp) fills each layer from that layer's row of rays alone, so a slab of layers is voxelized by the same ray
// caster, made once for the whole grid, restricted to the slab's rows (LayerFiller): the voxels are those
// voxelizeSolid gives, bit for bit, and the warnings count the same rays.
#include "vox/voxelize/stream.h"

#include <algorithm>
#include <bit>
#include <new>
#include <thread>

#include "vox/core/text.h"
#include "voxelize/passes.h"

namespace vox {

namespace {

// Bytes of one allocated layer of a grid with these dims.
uint64_t layerBytes(const Dims& d) {
  return estimateGridBytes(Dims{d.nx, d.ny, 1}) - estimateGridBytes(Dims{d.nx, d.ny, 0});
}

int64_t filledInLayers(const VoxelGrid& g, int32_t z0, int32_t z1) {
  int64_t n = 0;
  const int64_t words = g.wordsPerLayer();
  for (int32_t z = z0; z < z1; ++z) {
    if (!g.layerAllocated(z)) continue;
    const uint64_t* w = g.layerWords(z);
    for (int64_t i = 0; i < words; ++i) n += std::popcount(w[i]);
  }
  return n;
}

}  // namespace

uint64_t meshHeldBytes(const TriangleMesh& mesh) {
  // The triangles, and the ray caster's index: its entry (8 bytes) and, while it is built, the rows of each (8).
  return uint64_t(mesh.triangles.size()) * (sizeof(Triangle) + 16);
}

Result<int32_t> streamSlabLayers(const Box3d& bounds, const VoxelizeParams& params, FillMode mode,
                                 uint64_t held_bytes) {
  auto plan = planVoxelization(bounds, params);
  if (!plan) return plan.error();
  const Dims dims = plan->placement.dims;
  if (mode == FillMode::kVote || estimateGridBytes(dims) <= plan->limit_bytes) return 0;
  const uint64_t left = plan->limit_bytes > held_bytes ? plan->limit_bytes - held_bytes : 0;
  const uint64_t per_layer = std::max<uint64_t>(1, layerBytes(dims));
  const uint64_t layers = std::min(left, kMaxSlabBytes) / per_layer;
  return int32_t(std::clamp<uint64_t>(layers, 1, uint64_t(dims.nz)));
}

Result<StreamedVoxelization> voxelizeInSlabs(const TriangleMesh& mesh, const VoxelizeParams& params,
                                             int32_t slab_layers, const SlabSink& sink, const ProgressFn& progress,
                                             const MeshTopology* topology, const SlabShare& share) {
  const std::string name = mesh.name.empty() ? std::string("the mesh") : mesh.name;
  if (Status usable = voxelize_detail::checkMesh(mesh, name); !usable) return usable.error();
  auto plan = planVoxelization(mesh.bounds(), params);
  if (!plan) return plan.error();
  const Dims dims = plan->placement.dims;
  MeshTopology computed;
  if (!topology && params.mode == FillMode::kAuto) {
    computed = analyzeTopology(mesh);
    topology = &computed;
  }
  VoxelizeResult modes;  // the mode, its reason and the warnings, as voxelizeSolid decides them
  voxelize_detail::chooseMode(params.mode, topology, name, modes);
  if (modes.mode_used == FillMode::kVote) {
    return makeError(ErrorCode::kLimit, "a " + dimsText(dims) +
                                            " grid does not fit in memory and vote mode cannot be streamed in "
                                            "slabs (its rays along Y and Z need every layer); " +
                                            modes.mode_reason + ": use a lower resolution, or parity/nonzero");
  }
  if (params.remove_strays) {
    return makeError(ErrorCode::kLimit,
                     "a " + dimsText(dims) + " grid does not fit in memory and --remove-strays cannot be streamed");
  }
  voxelize_detail::warnAboutDegenerate(mesh, topology, modes.warnings);

  StreamedVoxelization r;
  r.dims = dims;
  r.frame = plan->placement.frame;
  r.frame.units = params.units;
  r.frame.source = mesh.name;
  r.mode_used = modes.mode_used;
  r.mode_reason = modes.mode_reason;
  r.slab_layers = std::clamp(slab_layers, 1, dims.nz);
  if (share.parts < 1 || share.part < 0 || share.part >= share.parts) {
    return makeError(ErrorCode::kInvalidArgument,
                     "voxelizeInSlabs: share " + std::to_string(share.part) + " of " + std::to_string(share.parts));
  }
  const int threads = params.threads > 0 ? params.threads : std::max(1, int(std::thread::hardware_concurrency()));
  int64_t own_layers = 0;  // the progress counts this share's layers
  for (int32_t z0 = 0, k = 0; z0 < dims.nz; z0 += r.slab_layers, ++k)
    if (share.owns(k)) own_layers += std::min(dims.nz, z0 + r.slab_layers) - z0;
  voxelize_detail::ProgressGate gate(progress, own_layers);
  bool out_of_memory = false;
  const voxelize_detail::PassInput in{mesh, plan->placement, r.frame, threads, gate, out_of_memory};
  try {
    voxelize_detail::LayerFiller filler(in, r.mode_used);
    for (int32_t z0 = 0, k = 0; z0 < dims.nz; z0 += r.slab_layers, ++k) {
      if (!share.owns(k)) continue;
      const int32_t z1 = std::min(dims.nz, z0 + r.slab_layers);
      VoxelGrid slab(Dims{dims.nx, dims.ny, z1 - z0}, r.frame);
      if (!filler.fill(z0, z1, slab, z0)) {
        if (out_of_memory) break;
        return makeError(ErrorCode::kCancelled, "voxelization cancelled");
      }
      r.filled += filledInLayers(slab, 0, slab.nz());
      r.largest_slab_bytes = std::max<uint64_t>(r.largest_slab_bytes, slab.memoryBytes());
      ++r.slabs;
      if (Status s = sink(slab, z0, z1); !s) return s.error();
    }
    r.rays = filler.counts();
  } catch (const std::bad_alloc&) {
    out_of_memory = true;
  }
  if (out_of_memory) {
    return makeError(ErrorCode::kLimit, "ran out of memory while voxelizing " + name + " in slabs of " +
                                            std::to_string(r.slab_layers) + " layers of a " + dimsText(dims) + " grid");
  }
  gate.finish();
  if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "voxelization cancelled");
  r.warnings = std::move(modes.warnings);
  if (share.parts == 1) addRayWarnings(r, r.rays);
  return r;
}

void addRayWarnings(StreamedVoxelization& r, const RayCounts& counts) {
  voxelize_detail::warnAboutRayCounts(counts, r.mode_used, r.warnings);
}

}  // namespace vox
