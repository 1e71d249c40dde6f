#pragma once
// The thickness pipeline both front ends run (docs/conventions.md, "Distance and thickness"): the exact distance
// field, the hot spots and the wall ridge on it, then local thickness painted from it. `voxmod thickness` and the
// window's Thickness panel call this one function; each reports progress its own way (a terminal line per stage, one
// bar).
#include <functional>
#include <optional>
#include <vector>

#include "vox/analysis/distance.h"
#include "vox/analysis/ray_thickness.h"
#include "vox/analysis/thickness.h"
#include "vox/analysis/walls.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox::workflow {

enum class ThicknessStage { kDistance, kHotSpots, kThickness, kWalls, kRays };

// Progress within one stage (fraction in [0, 1]); returning false stops the run, which then fails with kCancelled.
using StageProgress = std::function<bool(ThicknessStage stage, double fraction)>;

struct ThicknessRunOptions {
  bool keep_distance = false;  // keep the distance field (else local thickness paints into it)
  ThicknessParams thickness;
  HotSpotParams hot_spots;
  // The wall stops (vox/analysis/walls.h), from which the walls under any minimum wall are found; none: not sought.
  std::optional<WallRidgeParams> walls;
  // The ray thickness (vox/analysis/ray_thickness.h) against this mesh, the grid's own (model units); null: none.
  const TriangleMesh* ray_mesh = nullptr;
  RayThicknessParams ray;
};

struct ThicknessRun {
  Thickness thickness;
  std::vector<HotSpot> hot_spots;
  std::optional<DistanceField> distance;  // with keep_distance
  std::optional<WallRidge> ridge;         // with options.walls
  std::optional<RayThicknessResult> ray;  // with options.ray_mesh
  double distance_max = 0.0;              // the deepest voxel's distance from the surface, model units
  double distance_s = 0.0, hot_spots_s = 0.0, walls_s = 0.0, thickness_s = 0.0, ray_s = 0.0;  // each stage's time
};

Result<ThicknessRun> runThickness(const VoxelGrid& grid, const ThicknessRunOptions& options = {},
                                  const StageProgress& progress = {});

// The ray thickness of `grid` against its own mesh (model units), on its own: the window casts the rays as a job of
// their own once the thickness is known. `distance_max` (ThicknessRun::distance_max) sets the paint limit when
// params leave it at 0: rays longer than twice the deepest voxel paint only their ends (no wall is that thick).
Result<RayThicknessResult> runRayThickness(const TriangleMesh& mesh, const VoxelGrid& grid, double distance_max,
                                           RayThicknessParams params, const ProgressFn& progress = {});

}  // namespace vox::workflow
