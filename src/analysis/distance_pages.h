#pragma once
// Memory tuning of the distance transform: which blocks of a field's memory go on 2 MiB pages. The values computed do
// not depend on it; a field advised nothing holds the same.
#include "vox/analysis/distance.h"
#include "vox/core/voxel_grid.h"

namespace vox::analysis_detail {

// Asks the kernel for 2 MiB pages over the blocks of f's memory that the passes will write most of, before anything
// is written; the sites are the empty voxels of g when to_empty, else its filled ones. Nothing where the kernel has
// no such advice.
void adviseHugePages(const VoxelGrid& g, DistanceField& f, bool to_empty);

}  // namespace vox::analysis_detail
