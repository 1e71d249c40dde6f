#include "vox/workflow/print_check.h"

#include <utility>

#include "vox/core/text.h"

namespace vox::workflow {

Result<PrintCheck> runPrintCheck(const VoxelGrid& grid, const PrintCheckOptions& options,
                                 const PrintProgress& progress) {
  const auto stage = [&progress](PrintStage s) {
    if (!progress) return ProgressFn();
    return ProgressFn([&progress, s](double f) { return progress(s, f); });
  };
  PrintCheck check;
  check.from_mesh = options.mesh != nullptr;
  double t = nowSeconds();
  const auto lap = [&t] {
    const double now = nowSeconds(), s = now - t;
    t = now;
    return s;
  };
  auto surface = makePrintSurface(grid, options.mesh, stage(PrintStage::kSurface));
  if (!surface) return surface.error();
  check.surface_s = lap();
  auto support = computePrintSupport(*surface, grid, options.params, stage(PrintStage::kSupport));
  if (!support) return support.error();
  check.support = std::move(support).value();
  check.support_s = lap();
  auto cavities = findTrappedCavities(grid, stage(PrintStage::kCavities));
  if (!cavities) return cavities.error();
  check.cavities = std::move(cavities).value();
  for (const TrappedCavity& c : check.cavities) check.trapped_volume += c.volume;
  check.cavities_s = lap();
  if (options.orient_directions > 0) {
    auto found = searchPrintOrientations(*surface, grid, printDirections(options.orient_directions), options.params,
                                         stage(PrintStage::kOrient));
    if (!found) return found.error();
    check.orientations = std::move(found).value();
    check.orient_s = lap();
  }
  return check;
}

}  // namespace vox::workflow
