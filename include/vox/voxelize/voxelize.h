#pragma once
// Solid voxelization of a triangle mesh (thesis 4.3, 2.4.5-2.4.6; SPEC section 1). Rays parallel to X through the
// voxel centres; crossings are decided exactly with Simulation of Simplicity, so closed meshes give crack-free,
// reproducible grids that match ../shared/reference voxel for voxel.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vox/core/grid_placement.h"
#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

enum class FillMode {
  kAuto,     // nonzero for closed meshes, vote otherwise (the result says which and why)
  kParity,   // odd number of crossings along +X (the thesis)
  kNonzero,  // winding number along +X not zero: overlapping closed bodies become their union
  kVote,     // for broken meshes: parity along X, Y and Z, majority per voxel; disagreements kept as a mask
};
const char* fillModeName(FillMode m);                       // "auto", "parity", "nonzero", "vote"
std::optional<FillMode> parseFillMode(const std::string& s);

struct VoxelizeParams {
  int64_t resolution = 200;   // voxels along the longest axis, 1..kMaxResolution; ignored when voxel_size > 0
  double voxel_size = 0.0;    // model units; > 0 overrides resolution
  FillMode mode = FillMode::kAuto;
  int threads = 0;            // 0: all hardware threads
  bool remove_strays = false; // thesis 4.3.3: remove voxels with four or five free faces (1D/2D structures)
  uint64_t memory_limit_bytes = 0;  // 0: 80% of physical memory
  std::string units = "model";
};

struct VoxelizeResult {
  VoxelGrid grid;
  FillMode mode_used = FillMode::kParity;
  std::string mode_reason;          // e.g. "mesh is closed (0 boundary, 0 non-manifold edges)"
  std::optional<VoxelGrid> disputed;  // vote mode: voxels on which the three axes did not all agree
  int64_t disputed_count = 0;
  int64_t strays_removed = 0;
  std::vector<std::string> warnings;
};

// Grid placement and memory estimate for these parameters, without voxelizing (the GUI shows it before starting).
struct VoxelizePlan {
  GridPlacement placement;
  uint64_t bytes = 0;        // estimated peak bytes for the grid(s) (three grids in vote mode)
  uint64_t limit_bytes = 0;  // the limit in force
};
Result<VoxelizePlan> planVoxelization(const Box3d& bounds, const VoxelizeParams& params);

// Voxelizes `mesh`. `topology`, when given, avoids recomputing it for kAuto. Fails with kLimit when the estimate
// exceeds the memory limit, kInvalidArgument for bad parameters or an empty mesh, kCancelled when progress says so.
Result<VoxelizeResult> voxelizeSolid(const TriangleMesh& mesh, const VoxelizeParams& params,
                                     const ProgressFn& progress = {},
                                     const MeshTopology* topology = nullptr);

// Physical memory of this machine in bytes (0 if unknown).
uint64_t physicalMemoryBytes();

}  // namespace vox
