// How thick the overlap of two parts is (vox/analysis/assembly.h, InterferencePair::thickness): from the exact
// distance transform of the shared voxels alone, so a voxel on the overlap's border is 1 voxel deep and the deepest one
// d voxels; a sheet k voxels thick has d = (k + 1) / 2 for k odd, k / 2 for k even, hence 2 d - 1.
#include "vox/analysis/assembly.h"
#include "vox/analysis/distance.h"

namespace vox {

Result<double> overlapThickness(const LatticeGrid& shared, const Lattice& lattice, const ProgressFn& progress) {
  if (shared.grid.filledCount() == 0) return 0.0;
  auto distance = computeDistance(shared.grid, progress);
  if (!distance) return distance.error();
  return std::max(0.0, 2.0 * distance->maxVoxels() - 1.0) * lattice.voxel_size;
}

}  // namespace vox
