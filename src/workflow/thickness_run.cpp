#include "vox/workflow/thickness_run.h"

#include <utility>

#include "vox/core/text.h"

namespace vox::workflow {

Result<ThicknessRun> runThickness(const VoxelGrid& grid, const ThicknessRunOptions& options,
                                  const StageProgress& progress) {
  const auto stage = [&progress](ThicknessStage s) {
    if (!progress) return ProgressFn();
    return ProgressFn([&progress, s](double f) { return progress(s, f); });
  };
  ThicknessRun run;
  const double t0 = nowSeconds();
  // dense: hot spots and local thickness step through the box by strides
  auto distance = computeDistance(grid, stage(ThicknessStage::kDistance), DistanceLayout::kDense);
  if (!distance) return distance.error();
  const double t1 = nowSeconds();
  auto hot = findHotSpots(*distance, options.hot_spots, stage(ThicknessStage::kHotSpots));
  if (!hot) return hot.error();
  const double t2 = nowSeconds();
  if (options.walls) {
    auto ridge = findWallRidge(*distance, *options.walls, stage(ThicknessStage::kWalls));
    if (!ridge) return ridge.error();
    run.ridge = std::move(ridge).value();
  }
  const double t3 = nowSeconds();
  run.distance_max = distance->maxModel();
  auto thickness =
      options.keep_distance
          ? computeThickness(*distance, options.thickness, stage(ThicknessStage::kThickness))
          : computeThickness(std::move(distance).value(), options.thickness, stage(ThicknessStage::kThickness));
  if (!thickness) return thickness.error();
  run.thickness = std::move(thickness).value();
  run.hot_spots = std::move(hot).value();
  if (options.keep_distance) run.distance = std::move(distance).value();
  run.distance_s = t1 - t0;
  run.hot_spots_s = t2 - t1;
  run.walls_s = t3 - t2;
  const double t4 = nowSeconds();
  run.thickness_s = t4 - t3;
  if (options.ray_mesh) {
    auto ray = runRayThickness(*options.ray_mesh, grid, run.distance_max, options.ray, stage(ThicknessStage::kRays));
    if (!ray) return ray.error();
    run.ray = std::move(ray).value();
    run.ray_s = nowSeconds() - t4;
  }
  return run;
}

Result<RayThicknessResult> runRayThickness(const TriangleMesh& mesh, const VoxelGrid& grid, double distance_max,
                                           RayThicknessParams params, const ProgressFn& progress) {
  if (params.paint_limit <= 0.0) params.paint_limit = 2.0 * distance_max + 2.0 * grid.voxelSize();
  return computeRayThickness(mesh, grid, params, progress);
}

}  // namespace vox::workflow
