#pragma once
// The bodies of an assembly mesh voxelized on the whole mesh's lattice (docs/conventions.md, "Assemblies"): body i
// (vox/core/mesh_bodies.h) is voxelized alone, over its own box of the lattice of the grid the whole mesh gets with
// these params, so its voxels are exactly the voxels it would have in a grid of the whole mesh. The cost is about one
// voxelization of the whole mesh: every body casts only the rays through its own box, and no body allocates more
// than its box (bodies are spread over the threads, one thread each).
#include <cstdint>
#include <string>
#include <vector>

#include "vox/core/lattice.h"
#include "vox/core/mesh.h"
#include "vox/core/mesh_bodies.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/voxelize/voxelize.h"

namespace vox {

struct BodyVoxels {
  LatticeGrid voxels;     // the body's box of the lattice (an empty body still has a 1-voxel grid)
  int64_t triangles = 0;  // in the body
  int64_t filled = 0;     // voxels filled
  FillMode mode_used = FillMode::kNonzero;
};

struct BodiesResult {
  GridPlacement placement;  // the whole mesh's grid: the lattice (first = 0) and its dims
  Lattice lattice;          // the same lattice, with the params' units
  std::vector<BodyVoxels> bodies;
  std::vector<std::string> warnings;  // each prefixed "body N: "
};

// Voxelizes every body of `mesh` (split by splitBodies unless `bodies` is given). params.mode applies to each body
// (auto: by the body's own topology); params.placement, when set, is the lattice grid to use instead of the mesh's
// own. Fails like voxelizeSolid (bad params, memory limit, cancelled; kParse for a mesh without triangles).
Result<BodiesResult> voxelizeBodies(const TriangleMesh& mesh, const VoxelizeParams& params,
                                    const ProgressFn& progress = {}, const MeshBodies* bodies = nullptr);

}  // namespace vox
