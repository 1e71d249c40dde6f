// Solid voxelization: modes, parallel passes, memory limit, progress, warnings.
//
// Builds on:
//  - the thesis, section 4.3 (scan-line voxelization along X, layer by layer; 4.3.3: stray voxels with four or
//    more free faces are artefacts of thin sections and broken meshes);
//  - H. Edelsbrunner and E. P. Mücke, Simulation of Simplicity, ACM TOG 9(1), 1990 (ties; see ray_caster.cpp);
//  - F. S. Nooruddin and G. Turk, "Simplification and Repair of Polygonal Models Using Volumetric Techniques",
//    IEEE TVCG 9(2):191-205, 2003: parity counts along several directions and a per-voxel vote make a solid out of
//    a mesh with holes; voxmod uses the three axis directions and a majority of three.
//
// The crossings of each ray come from RayCaster as (first voxel past the crossing, sign) pairs, so filling is
// integer work, and it is done by toggles: a crossing toggles the bit of the first voxel past it, and a prefix XOR
// along the ray turns toggles into "inside", with word operations. Parity mode (rays along X) toggles at every
// crossing, in any order. Nonzero mode sorts each ray's crossings along it and toggles only where the winding
// number changes between zero and nonzero. Vote mode takes the parity along each axis: the prefix XOR runs within
// a row's words for rays along X, over the rows for rays along Y, over the layers for rays along Z (whose toggles
// are listed by layer and XORed into a running layer as the layer pass goes up). Rows of rays are independent, so
// the work is split over slabs of rows with std::thread; each thread writes only the Z layers of its own rows (rays
// along X and Y) or its own slab's toggle lists (rays along Z), so no two threads ever write the same word.
//
// This file strings the steps together (voxelizeSolid); each lives in a file named for what it does (passes.h lists
// them): planning (plan.cpp), the pass along X of parity and nonzero mode (fill.cpp), vote mode (vote.cpp) and the
// stray-voxel clean-up (strays.cpp).
#include "vox/voxelize/voxelize.h"

#include <algorithm>
#include <cstdint>
#include <new>
#include <string>
#include <thread>

#include "vox/core/mesh.h"
#include "vox/core/text.h"
#include "voxelize/passes.h"

namespace vox {

namespace voxelize_detail {

// Fails for a mesh that cannot be voxelized: no triangles, or more than the ray casters can index.
Status checkMesh(const TriangleMesh& mesh, const std::string& name) {
  if (mesh.triangles.empty()) return makeError(ErrorCode::kParse, name + " has no triangles");
  if (mesh.triangles.size() > UINT32_MAX) {  // the ray casters index triangles with 32 bits
    return makeError(ErrorCode::kLimit, name + " has " + std::to_string(mesh.triangles.size()) +
                                            " triangles; at most 4294967295 can be voxelized");
  }
  return Ok{};
}

// Warns about the degenerate triangles of `mesh` (counted by `topology` when given).
void warnAboutDegenerate(const TriangleMesh& mesh, const MeshTopology* topology, std::vector<std::string>& warnings) {
  int64_t degenerate = 0;
  if (topology) {
    degenerate = topology->degenerate_triangles;
  } else {
    for (const Triangle& t : mesh.triangles) degenerate += isDegenerate(t) ? 1 : 0;
  }
  if (degenerate > 0) {
    warnings.push_back(voxelize_detail::plural(degenerate, "degenerate triangle") +
                       " (zero area) ignored: they cross no ray");
  }
}

}  // namespace voxelize_detail

namespace {

using voxelize_detail::PassInput;
using voxelize_detail::ProgressGate;

// Why a pass stopped: memory ran out (kLimit), or progress asked to stop (kCancelled).
Error passFailure(bool out_of_memory, const std::string& name, const Dims& dims) {
  if (out_of_memory) {
    return makeError(ErrorCode::kLimit,
                     "ran out of memory while voxelizing " + name + " on a " + dimsText(dims) + " grid");
  }
  return makeError(ErrorCode::kCancelled, "voxelization cancelled");
}

}  // namespace

Result<VoxelizeResult> voxelizeSolid(const TriangleMesh& mesh, const VoxelizeParams& params, const ProgressFn& progress,
                                     const MeshTopology* topology) {
  const std::string name = mesh.name.empty() ? std::string("the mesh") : mesh.name;
  if (Status usable = voxelize_detail::checkMesh(mesh, name); !usable) return usable.error();
  auto plan_or = planVoxelization(mesh.bounds(), params);
  if (!plan_or) return plan_or.error();
  VoxelizePlan plan = std::move(plan_or).value();
  const Dims dims = plan.placement.dims;

  VoxelizeResult result;
  // Resolve the mode. Topology is only needed for auto (or given anyway, for the warning).
  MeshTopology computed;
  if (!topology && params.mode == FillMode::kAuto) {
    computed = analyzeTopology(mesh);
    topology = &computed;
  }
  voxelize_detail::chooseMode(params.mode, topology, name, result);
  const bool vote = result.mode_used == FillMode::kVote;

  // Refuse before allocating anything large.
  if (Status fits = voxelize_detail::checkMemoryLimit(plan, params, result.mode_used); !fits) return fits.error();
  voxelize_detail::warnAboutDegenerate(mesh, topology, result.warnings);

  const int threads = params.threads > 0 ? params.threads : std::max(1, int(std::thread::hardware_concurrency()));
  GridFrame frame = plan.placement.frame;
  frame.origin += glm::dvec3(plan.placement.first) * frame.voxel_size;  // the corner of voxel (0, 0, 0)
  frame.units = params.units;
  frame.source = mesh.name;

  const int64_t total_rows = vote ? int64_t(dims.nz) * 2 + dims.ny : int64_t(dims.nz);
  ProgressGate gate(progress, total_rows);
  bool out_of_memory = false;
  const PassInput in{mesh, plan.placement, frame, threads, gate, out_of_memory};
  try {
    const bool ok =
        vote ? voxelize_detail::fillByVote(in, result) : voxelize_detail::fillAlongX(in, result.mode_used, result);
    if (!ok) return passFailure(out_of_memory, name, dims);
    if (params.remove_strays) result.strays_removed = voxelize_detail::removeStrayVoxels(result.grid, threads);
  } catch (const std::bad_alloc&) {
    return passFailure(true, name, dims);
  }
  gate.finish();
  if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "voxelization cancelled");
  return result;
}

}  // namespace vox
