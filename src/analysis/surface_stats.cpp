// Surface statistics and the face-neighbour code histogram (thesis 5.1, Table 5.1; docs/conventions.md,
// "Face-neighbour code"). Surface voxels are found with word operations on whole layers (surface = filled & ~(all six
// neighbours)); only surface voxels are visited one by one, to build their codes. Codes with four or five free faces
// are the one- and two-dimensional structures that thesis 4.3.3 attributes to voxelization errors.
#include <bit>

#include "analysis/layer_ops.h"
#include "vox/core/parallel.h"
#include "vox/analysis/analysis.h"
#include "vox/core/neighbour_code.h"

namespace vox {

using analysis_detail::interiorWord;

SurfaceStats computeSurfaceStats(const VoxelGrid& grid) {
  SurfaceStats stats;
  if (grid.empty()) return stats;
  const int64_t wpr = grid.wordsPerRow();
  const int64_t w_begin = analysis_detail::firstRowWord(grid);
  const int64_t w_end = analysis_detail::endRowWord(grid);
  const int threads = threadsFor(grid.allocatedLayers() * grid.wordsPerLayer());
  std::vector<SurfaceStats> partial(static_cast<size_t>(threads));

  parallelChunks(0, grid.nz(), 4, threads, [&](int t, int64_t z0, int64_t z1) {
    SurfaceStats& s = partial[size_t(t)];
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      if (!grid.layerAllocated(z)) continue;
      const uint64_t* below = grid.layerWords(z - 1);
      const uint64_t* cur = grid.layerWords(z);
      const uint64_t* above = grid.layerWords(z + 1);
      for (int64_t w = w_begin; w < w_end; ++w) {
        const uint64_t c = cur[w];
        if (!c) continue;
        const uint64_t interior = interiorWord(below, cur, above, wpr, w);
        s.filled += analysis_detail::popcount64(c);
        s.code_histogram[kCodeInterior] += analysis_detail::popcount64(interior);
        uint64_t surf = c & ~interior;
        if (!surf) continue;
        const uint64_t xm = (c << 1) | (cur[w - 1] >> 63);
        const uint64_t xp = (c >> 1) | (cur[w + 1] << 63);
        const uint64_t ym = cur[w - wpr], yp = cur[w + wpr], zm = below[w], zp = above[w];
        while (surf) {
          const int b = std::countr_zero(surf);
          surf &= surf - 1;
          const unsigned code = unsigned(((ym >> b) & 1) << 5 | ((xm >> b) & 1) << 4 | ((xp >> b) & 1) << 3 |
                                         ((yp >> b) & 1) << 2 | ((zm >> b) & 1) << 1 | ((zp >> b) & 1));
          ++s.code_histogram[code];
        }
      }
    }
  });

  for (const SurfaceStats& s : partial) {
    stats.filled += s.filled;
    for (size_t c = 0; c < 64; ++c) stats.code_histogram[c] += s.code_histogram[c];
  }
  stats.surface_voxels = stats.filled - stats.code_histogram[kCodeInterior];
  for (unsigned code = 0; code < 63; ++code) {
    const int free_faces = freeFaces(uint8_t(code));
    if (free_faces == 4 || free_faces == 5) stats.suspect_voxels += stats.code_histogram[code];
  }
  return stats;
}

}  // namespace vox
