// Thin walls: filled voxels whose local thickness is below a minimum wall, in 26-connected regions (two thin voxels
// sharing a face, an edge or a corner belong to the same region). See vox/analysis/thickness.h.
#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include <glm/common.hpp>

#include "analysis/mask_regions.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/thickness.h"
#include "vox/core/parallel.h"

namespace vox {

Result<ThinWalls> findThinWalls(const Thickness& thickness, double min_wall, const ProgressFn& progress) {
  if (!(min_wall >= 0) || !std::isfinite(min_wall)) {
    return makeError(ErrorCode::kInvalidArgument, "thin walls: the minimum wall must be a number >= 0");
  }
  ThinWalls out;
  out.min_wall = min_wall;
  const DistanceField& f = thickness.radius;
  const Dims d = f.boxDims();
  const double h = f.voxelSize();
  if (d.count() == 0) return out;
  const int64_t nx = d.nx, ny = d.ny, nz = d.nz;
  const uint32_t* data = f.data();
  auto thin = [&](uint32_t v) { return v != 0 && 2.0 * std::sqrt(double(v)) * h < min_wall; };

  // Thin voxels as bits (one bit per box voxel); a bit is cleared when its voxel joins a region.
  std::vector<uint64_t> todo(size_t((d.count() + 63) / 64), 0);
  {
    const int threads = threadsFor(d.count() / 4);
    std::vector<int64_t> counts(size_t(threads), 0);
    // chunks of whole words, so no two threads write the same word
    parallelChunks(0, int64_t(todo.size()), 4096, threads, [&](int t, int64_t wb, int64_t we) {
      for (int64_t w = wb; w < we; ++w) {
        uint64_t bits = 0;
        const int64_t i0 = w * 64, i1 = std::min(d.count(), i0 + 64);
        for (int64_t i = i0; i < i1; ++i) {
          if (thin(data[i])) bits |= uint64_t(1) << (i - i0);
        }
        todo[size_t(w)] = bits;
        counts[size_t(t)] += std::popcount(bits);
      }
    });
    for (int64_t c : counts) out.voxels += c;
  }
  analysis_detail::ProgressGate gate(progress);
  const glm::ivec3 lo = f.boxMin();
  int64_t visited = 0, next_report = 0;
  bool cancelled = false;
  analysis_detail::forEachRegion(
      std::move(todo), nx, ny, nz, [&](int64_t i) { return data[i] != 0; },
      [&](const analysis_detail::MaskRegion& m) {
        ThinWallRegion r;
        uint32_t min_v = UINT32_MAX;
        for (int64_t i : *m.voxels) min_v = std::min(min_v, data[i]);
        r.voxels = int64_t(m.voxels->size());
        r.exposed_faces = m.exposed_faces;
        visited += r.voxels;
        r.area = double(r.exposed_faces) * h * h;
        r.bbox_min_ijk = m.min + lo;
        r.bbox_max_ijk = m.max + lo;
        const GridFrame& fr = f.frame();
        r.bbox.min = fr.origin + glm::dvec3(r.bbox_min_ijk) * h;
        r.bbox.max = fr.origin + glm::dvec3(r.bbox_max_ijk + 1) * h;
        r.min = 2.0 * std::sqrt(double(min_v)) * h;
        out.regions.push_back(r);
        if (visited >= next_report) {
          next_report = visited + out.voxels / 100 + 1;
          cancelled = !gate.report(double(visited) / double(out.voxels));
        }
        return !cancelled;
      });
  if (cancelled) return makeError(ErrorCode::kCancelled, "thin walls cancelled");
  std::stable_sort(out.regions.begin(), out.regions.end(),
                   [](const ThinWallRegion& a, const ThinWallRegion& b) { return a.voxels > b.voxels; });
  if (!gate.report(1.0)) return makeError(ErrorCode::kCancelled, "thin walls cancelled");
  return out;
}

}  // namespace vox
