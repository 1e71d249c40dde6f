#pragma once
// Solid voxelization of a triangle mesh (thesis 4.3, 2.4.5-2.4.6; docs/conventions.md, "Grid placement"). Rays parallel
// to X through the voxel centres; crossings are decided exactly with Simulation of Simplicity, so closed meshes give
// crack-free, reproducible grids that match ../shared/reference voxel for voxel (docs/accuracy.md). No tolerance
// anywhere: the result depends only on the float32 vertices and the grid, and is identical for any number of threads.
//
// Cost: O(T + R^2 + crossings) time for the rays plus writing the grid (word operations); vote mode casts three
// ray families. Memory: the grid (estimateGridBytes, layers allocated only where the model is); in vote mode also
// the disputed voxels (for each row holding any, its words from the first such voxel to the last and one more word)
// and 4 bytes per crossing along Z; plus 8 bytes per triangle for the ray caster's row index (it reads vertices from
// the mesh, which must stay alive) and, in vote mode, a few scratch layers per thread.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vox/core/grid_placement.h"
#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/sparse_voxels.h"
#include "vox/core/voxel_grid.h"

namespace vox {

enum class FillMode {
  kAuto,     // nonzero for closed meshes, vote otherwise (the result says which and why)
  kParity,   // odd number of crossings along +X (the thesis)
  kNonzero,  // winding number along +X not zero: overlapping closed bodies become their union
  kVote,     // for broken meshes: parity along X, Y and Z, majority per voxel; disagreements kept (the disputed set)
};
// Ties (a centre on the surface, a ray through an edge or vertex) follow docs/conventions.md, "Grid placement"
// (Simulation of Simplicity, Edelsbrunner & Mücke 1990): the centre is displaced by
// (eps, eps^3, eps^2) in (x, y, z). Vote mode's rays along Y and Z displace the centre the same way in their own
// frame, (y, x, z) resp. (z, x, y) taking the roles of (x, y, z): consistent, so closed meshes stay crack-free along
// every axis, but a centre exactly on the surface may then be decided differently per axis (and be disputed).
// Every fill mode, in the order menus and help list them.
inline constexpr FillMode kFillModes[] = {FillMode::kAuto, FillMode::kParity, FillMode::kNonzero, FillMode::kVote};
const char* fillModeName(FillMode m);  // "auto", "parity", "nonzero", "vote"
std::optional<FillMode> parseFillMode(const std::string& s);
std::string fillModeNames(const char* separator = ", ");  // "auto, parity, nonzero, vote"
std::vector<std::string> fillModeNameList();

struct VoxelizeParams {
  int64_t resolution = 200;  // voxels along the longest axis, 1..kMaxResolution; ignored when voxel_size > 0
  double voxel_size = 0.0;   // model units; > 0 overrides resolution
  FillMode mode = FillMode::kAuto;
  int threads = 0;  // 0: all hardware threads; negative is an error
  // Thesis 4.3.3: one pass, decided on the grid before the pass, removing every voxel with four or more free faces
  // (at most two filled face neighbours): isolated voxels, voxel lines and line ends, corners of one-voxel sheets.
  bool remove_strays = false;
  uint64_t memory_limit_bytes = 0;  // 0: 80% of physical memory
  std::string units = "model";
  // Set: voxelize on exactly this grid instead of the one fitted to the mesh (resolution and voxel_size are then
  // ignored), e.g. a body of an assembly over its own box of the assembly's lattice (placeGridOnLattice). The result's
  // frame origin is the corner of its voxel (0, 0, 0); its voxels equal the lattice grid's voxels there.
  std::optional<GridPlacement> placement = std::nullopt;
};

struct VoxelizeResult {
  VoxelGrid grid;
  FillMode mode_used = FillMode::kParity;
  // e.g. "mesh is closed (0 boundary edges, 0 non-manifold edges): using nonzero",
  // "mesh is not watertight (223 boundary edges, 0 non-manifold edges): using vote", "requested: parity"
  std::string mode_reason;
  // Vote mode: the voxels on which the three axes did not all agree (sparse: usually few words of a grid's rows;
  // toGrid() for a grid of the result's dims).
  std::optional<SparseVoxels> disputed;
  int64_t disputed_count = 0;
  int64_t strays_removed = 0;
  // E.g. a mesh that is not watertight used with parity/nonzero, degenerate triangles ignored, rays with an odd
  // number of crossings or a nonzero total winding (0 on a closed mesh), voxels disputed by the vote.
  std::vector<std::string> warnings;
};

// Grid placement and memory estimate for these parameters, without voxelizing (the GUI shows it before starting).
struct VoxelizePlan {
  GridPlacement placement;
  // Estimated peak bytes for the results: the grid, and in vote mode the disputed voxels at their largest
  // (SparseVoxels::maxBytes), counted for kAuto too (its worst case: the plan does not see the mesh's topology;
  // voxelizeSolid checks the mode it resolves to).
  uint64_t bytes = 0;
  uint64_t limit_bytes = 0;  // the limit in force
};
Result<VoxelizePlan> planVoxelization(const Box3d& bounds, const VoxelizeParams& params);

// What FillMode::kAuto resolves to for a mesh of this topology, and why (the words voxelizeSolid reports as
// mode_reason): nonzero for closed meshes, for touching or overlapping closed bodies and for meshes that close when
// exporter noise is welded; vote for meshes with holes.
struct ModeChoice {
  FillMode mode = FillMode::kNonzero;
  std::string reason;  // e.g. "mesh is closed (0 boundary edges, 0 non-manifold edges): using nonzero"
};
ModeChoice resolveAutoMode(const MeshTopology& topology);

// Voxelizes `mesh`. `topology`, when given, avoids recomputing it for kAuto (and enables the warning about open
// meshes in the other modes). Fails with kLimit when the estimate exceeds the memory limit (before allocating) or
// memory runs out, kInvalidArgument for bad parameters or an empty mesh, kCancelled when progress says so. Progress
// is reported from the worker threads, serialised, at most about 200 times, monotone, ending with 1.0.
Result<VoxelizeResult> voxelizeSolid(const TriangleMesh& mesh, const VoxelizeParams& params,
                                     const ProgressFn& progress = {}, const MeshTopology* topology = nullptr);

}  // namespace vox
