#pragma once
// What `voxmod peel` and the window do to peel: the depth map for the layers asked for, then what those layers leave.
#include "vox/analysis/analysis.h"

namespace vox::test {

inline Result<PeelResult> peelLayers(const VoxelGrid& g, const PeelParams& p, const ProgressFn& progress = {}) {
  auto d = computeDepthMap(g, p, progress);
  if (!d) return d.error();
  return d->peeled(p.all ? d->layers() : p.layers);
}

}  // namespace vox::test
