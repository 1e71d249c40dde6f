// Trapped cavities: empty regions no empty path joins to the outside, and the shortest straight drain from each. See
// vox/analysis/printability.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "vox/analysis/assembly.h"
#include "vox/analysis/printability.h"

namespace vox {
namespace {

// The empty voxels of the grid's box as a grid of their own (padding stays empty).
VoxelGrid emptyVoxels(const VoxelGrid& grid) {
  VoxelGrid empty(grid.dims(), grid.frame());
  const int64_t wpr = grid.wordsPerRow();
  std::vector<uint64_t> valid(size_t(wpr), 0);  // bits 1..nx of a padded row
  for (int64_t xp = 1; xp <= grid.nx(); ++xp) valid[size_t(xp >> 6)] |= uint64_t(1) << (xp & 63);
  for (int32_t z = 0; z < grid.nz(); ++z) {
    uint64_t* layer = empty.freshLayerWords(z);
    for (int32_t y = 0; y < grid.ny(); ++y) {
      const uint64_t* in = grid.rowWords(y, z);
      uint64_t* out = layer + (int64_t(y) + 1) * wpr;
      for (int64_t w = 0; w < wpr; ++w) out[w] = ~in[w] & valid[size_t(w)];
    }
  }
  return empty;
}

bool touchesBorder(const Component& c, const Dims& dims) {
  return c.box_min.x == 0 || c.box_min.y == 0 || c.box_min.z == 0 || c.box_max.x == dims.nx - 1 ||
         c.box_max.y == dims.ny - 1 || c.box_max.z == dims.nz - 1;
}

// The 26 lattice directions.
std::vector<glm::ivec3> latticeSteps() {
  std::vector<glm::ivec3> steps;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x)
        if (x != 0 || y != 0 || z != 0) steps.emplace_back(x, y, z);
  return steps;
}

// From cavity voxel p along `step` through the material: the number of filled voxels crossed before an outside
// voxel (empty, in no cavity, or beyond the grid), or -1 when the line meets another cavity first or passes `limit`.
int64_t drillFrom(const VoxelGrid& grid, const VoxelGrid& cavities, glm::ivec3 p, glm::ivec3 step, int64_t limit) {
  int64_t crossed = 0;
  for (glm::ivec3 q = p + step;; q += step) {
    if (!grid.inBounds(q.x, q.y, q.z)) return crossed;
    if (grid.get(q.x, q.y, q.z)) {
      if (++crossed >= limit) return -1;
      continue;
    }
    return cavities.get(q.x, q.y, q.z) ? -1 : crossed;
  }
}

// The shortest straight drain from any wall voxel of the cavity (its runs, indices into parts.runs) along a lattice
// direction.
std::optional<DrainHole> shortestDrain(const VoxelGrid& grid, const VoxelGrid& cavities, const Components& parts,
                                       const std::vector<size_t>& runs) {
  static const std::vector<glm::ivec3> steps = latticeSteps();
  double best = 1e300;
  std::optional<DrainHole> drain;
  const double h = grid.voxelSize();
  for (const size_t r : runs) {
    const Components::Run& run = parts.runs[r];
    for (int32_t x = run.x0; x < run.x1; ++x) {
      const glm::ivec3 p(x, run.y, run.z);
      for (const glm::ivec3& step : steps) {
        const glm::ivec3 next = p + step;
        if (!grid.inBounds(next.x, next.y, next.z) || !grid.get(next.x, next.y, next.z)) continue;  // not a wall
        const double unit = std::sqrt(double(step.x * step.x + step.y * step.y + step.z * step.z)) * h;
        const int64_t limit = best > 1e15 ? INT64_MAX : int64_t(std::ceil(best / unit));
        const int64_t crossed = drillFrom(grid, cavities, p, step, limit);
        if (crossed < 0 || double(crossed) * unit >= best) continue;
        best = double(crossed) * unit;
        const glm::ivec3 to = p + step * int(crossed + 1);
        drain =
            DrainHole{grid.frame().voxelCentre(p.x, p.y, p.z), grid.frame().voxelCentre(to.x, to.y, to.z), step, best};
      }
    }
  }
  return drain;
}

}  // namespace

Result<std::vector<TrappedCavity>> findTrappedCavities(const VoxelGrid& grid, const ProgressFn& progress) {
  std::vector<TrappedCavity> out;
  if (grid.empty()) return out;
  if (progress && !progress(0.0)) return makeError(ErrorCode::kCancelled, "trapped cavities cancelled");
  const VoxelGrid empty = emptyVoxels(grid);
  const Components parts = findComponents(empty, Connectivity::kFace);
  if (progress && !progress(0.5)) return makeError(ErrorCode::kCancelled, "trapped cavities cancelled");
  std::vector<uint32_t> trapped;  // component indices, largest first
  for (size_t c = 0; c < parts.components.size(); ++c) {
    if (!touchesBorder(parts.components[c], grid.dims())) trapped.push_back(uint32_t(c));
  }
  if (trapped.empty()) return out;
  // every cavity's voxels, and each one's sums of voxel centres
  VoxelGrid cavities(grid.dims(), grid.frame());
  std::vector<int32_t> slot(parts.components.size(), -1);
  for (size_t i = 0; i < trapped.size(); ++i) slot[trapped[i]] = int32_t(i);
  std::vector<glm::dvec3> sum(trapped.size(), glm::dvec3(0.0));
  std::vector<std::vector<size_t>> runs_of(trapped.size());  // each cavity's runs, listed once for its drain
  for (size_t r = 0; r < parts.runs.size(); ++r) {
    const int32_t i = slot[parts.run_component[r]];
    if (i < 0) continue;
    runs_of[size_t(i)].push_back(r);
    const Components::Run& run = parts.runs[r];
    cavities.fillRun(run.y, run.z, run.x0, run.x1);
    const double n = double(run.x1 - run.x0);
    sum[size_t(i)] += glm::dvec3(n * (double(run.x0 + run.x1) * 0.5), n * (run.y + 0.5), n * (run.z + 0.5));
  }
  const double h = grid.voxelSize();
  const glm::dvec3 origin = grid.frame().origin;
  for (size_t i = 0; i < trapped.size(); ++i) {
    const Component& c = parts.components[trapped[i]];
    TrappedCavity cav;
    cav.voxels = c.voxels;
    cav.volume = double(c.voxels) * h * h * h;
    cav.centre = origin + sum[i] / double(c.voxels) * h;
    cav.box_min = c.box_min;
    cav.box_max = c.box_max;
    cav.bbox.min = origin + glm::dvec3(c.box_min) * h;
    cav.bbox.max = origin + glm::dvec3(c.box_max + glm::ivec3(1)) * h;
    cav.drain = shortestDrain(grid, cavities, parts, runs_of[i]);
    out.push_back(cav);
    if (progress && !progress(0.5 + 0.5 * double(i + 1) / double(trapped.size()))) {
      return makeError(ErrorCode::kCancelled, "trapped cavities cancelled");
    }
  }
  return out;
}

VoxelGrid trappedCavityGrid(const VoxelGrid& grid) {
  VoxelGrid cavities(grid.dims(), grid.frame());
  if (grid.empty()) return cavities;
  const VoxelGrid empty = emptyVoxels(grid);
  const Components parts = findComponents(empty, Connectivity::kFace);
  for (size_t r = 0; r < parts.runs.size(); ++r) {
    if (touchesBorder(parts.components[parts.run_component[r]], grid.dims())) continue;
    const Components::Run& run = parts.runs[r];
    cavities.fillRun(run.y, run.z, run.x0, run.x1);
  }
  return cavities;
}

}  // namespace vox
