#pragma once
// The printability pipeline both front ends run (vox/analysis/printability.h): the part's surface made
// ready for rays, the overhangs and support along the build direction, the trapped cavities and, when asked, the
// search over build directions. `voxmod printcheck` and the window's Print panel call this one function.
#include <functional>
#include <optional>
#include <vector>

#include "vox/analysis/printability.h"
#include "vox/core/mesh.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox::workflow {

enum class PrintStage { kSurface, kSupport, kCavities, kOrient };

// Progress within one stage (fraction in [0, 1]); returning false stops the run, which then fails with kCancelled.
using PrintProgress = std::function<bool(PrintStage stage, double fraction)>;

struct PrintCheckOptions {
  PrintParams params;         // the build direction, the overhang angle; params.fields: paint the fields
  int orient_directions = 0;  // > 0: also search the six axes and this many directions over the sphere
  // The mesh the grid was voxelized from (model units), whose own normals decide the overhangs; null: the voxels'
  // smooth surface.
  const TriangleMesh* mesh = nullptr;
};

struct PrintCheck {
  PrintSupport support;                    // along options.params.up
  std::vector<TrappedCavity> cavities;     // largest first
  double trapped_volume = 0.0;             // model units^3
  std::vector<PrintSupport> orientations;  // least support first, with options.orient_directions
  bool from_mesh = false;                  // the overhangs come from the mesh's normals
  double surface_s = 0.0, support_s = 0.0, cavities_s = 0.0, orient_s = 0.0;
};

Result<PrintCheck> runPrintCheck(const VoxelGrid& grid, const PrintCheckOptions& options,
                                 const PrintProgress& progress = {});

}  // namespace vox::workflow
