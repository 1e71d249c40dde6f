// Measuring on the voxel model: the voxel a ray meets first (a click in the 3D view). Voxel (i, j, k) occupies
// [i, i + 1) x [j, j + 1) x [k, k + 1) in voxel-index space, the space the renderer and its camera work in. The walk is
// Amanatides and Woo, "A fast voxel traversal algorithm for ray tracing" (Eurographics 1987): one voxel per step, in
// the order the ray enters them, so the first filled one is the one seen.
#include <algorithm>
#include <cmath>
#include <limits>

#include "vox/analysis/analysis.h"

namespace vox {

std::optional<glm::ivec3> pickVoxel(const VoxelGrid& grid, const glm::dvec3& from, const glm::dvec3& to) {
  if (grid.empty()) return std::nullopt;
  const glm::dvec3 dir = to - from;
  const glm::dvec3 size(grid.nx(), grid.ny(), grid.nz());
  // Clip the segment to the grid's box (slab method).
  double t0 = 0.0, t1 = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (dir[a] == 0.0) {
      if (from[a] < 0.0 || from[a] >= size[a]) return std::nullopt;
      continue;
    }
    double ta = (0.0 - from[a]) / dir[a], tb = (size[a] - from[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 <= t1)) return std::nullopt;
  const glm::dvec3 start = from + dir * t0;
  glm::ivec3 v, step;
  glm::dvec3 t_max, t_delta;
  for (int a = 0; a < 3; ++a) {
    v[a] = std::clamp(int(std::floor(start[a])), 0, int(size[a]) - 1);
    step[a] = dir[a] > 0 ? 1 : (dir[a] < 0 ? -1 : 0);
    const double next = dir[a] > 0 ? double(v[a] + 1) : double(v[a]);
    t_max[a] = dir[a] != 0 ? t0 + (next - start[a]) / dir[a] : std::numeric_limits<double>::infinity();
    t_delta[a] = dir[a] != 0 ? 1.0 / std::fabs(dir[a]) : std::numeric_limits<double>::infinity();
  }
  for (;;) {
    if (grid.get(v.x, v.y, v.z)) return v;
    const int a = t_max.x < t_max.y ? (t_max.x < t_max.z ? 0 : 2) : (t_max.y < t_max.z ? 1 : 2);
    if (t_max[a] > t1) return std::nullopt;
    v[a] += step[a];
    if (v[a] < 0 || v[a] >= int(size[a])) return std::nullopt;
    t_max[a] += t_delta[a];
  }
}

}  // namespace vox
