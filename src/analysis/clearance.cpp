// Clearance between two parts on one lattice: the exact Euclidean distance transform (distance.cpp)
// of the empty voxels to part a, over a box holding both parts, read at part b's voxels; the smallest value is the
// closest pair's centre distance, and the voxel of a realising it is found by a search of the ball of that radius
// about b's voxel.
#include <bit>
#include <cmath>

#include <glm/common.hpp>

#include "vox/analysis/assembly.h"
#include "vox/analysis/distance.h"

namespace vox {
namespace {

// The box b's voxels are searched in: b's filled box, cut to a's grown by the bound when there is one.
Box3i searchBox(const Box3i& box_a, const Box3i& box_b, double bound_voxels) {
  if (bound_voxels <= 0.0) return box_b;
  const int32_t grow = int32_t(std::min(std::ceil(bound_voxels) + 1.0, 1e8));
  return intersect(box_b, Box3i{box_a.min - glm::ivec3(grow), box_a.max + glm::ivec3(grow)});
}

// The filled voxel of `g` nearest-first in (z, y, x) order at squared distance exactly d2 from voxel v.
glm::ivec3 voxelAtDistance(const VoxelGrid& g, const glm::ivec3& v, uint32_t d2) {
  const int32_t r = int32_t(std::ceil(std::sqrt(double(d2)))) + 1;
  for (int32_t dz = -r; dz <= r; ++dz)
    for (int32_t dy = -r; dy <= r; ++dy)
      for (int32_t dx = -r; dx <= r; ++dx) {
        if (uint32_t(dx * dx + dy * dy + dz * dz) != d2) continue;
        const glm::ivec3 p = v + glm::ivec3(dx, dy, dz);
        if (g.inBounds(p.x, p.y, p.z) && g.get(p.x, p.y, p.z)) return p;
      }
  return v;
}

}  // namespace

Result<Clearance> findClearance(const LatticeGrid& a, const LatticeGrid& b, const Lattice& lattice,
                                const ClearanceParams& params, const ProgressFn& progress) {
  Clearance out;
  const Box3i box_a = filledBox(a), box_b_all = filledBox(b);
  if (box_a.empty() || box_b_all.empty()) return out;
  const Box3i box_b = searchBox(box_a, box_b_all, params.max_distance / lattice.voxel_size);
  if (box_b.empty()) return out;
  const Box3i box = unite(box_a, box_b);
  const LatticeGrid grid_a = reframe(a, box, lattice);
  const LatticeGrid grid_b = reframe(b, box, lattice);
  auto field = computeClearance(grid_a.grid, progress);
  if (!field) return field.error();
  // The smallest value at b's voxels (first in z, y, x order among equals).
  uint32_t best = DistanceField::kInfinite;
  glm::ivec3 best_b(0);
  const VoxelGrid& gb = grid_b.grid;
  for (int32_t z = 0; z < gb.nz() && best > 0; ++z) {
    if (!gb.layerAllocated(z)) continue;
    for (int32_t y = 0; y < gb.ny(); ++y) {
      const uint64_t* row = gb.rowWords(y, z);
      for (int64_t w = 0; w < gb.wordsPerRow(); ++w) {
        for (uint64_t v = row[w]; v != 0; v &= v - 1) {
          const int32_t x = int32_t(w * 64 + std::countr_zero(v) - 1);
          const uint32_t d2 = field->squared(x, y, z);
          if (d2 < best) {
            best = d2;
            best_b = glm::ivec3(x, y, z);
          }
        }
      }
    }
  }
  if (best == DistanceField::kInfinite) return out;
  const double h = lattice.voxel_size;
  if (params.max_distance > 0.0 && std::sqrt(double(best)) * h > params.max_distance) return out;
  out.found = true;
  const glm::ivec3 local_a = best == 0 ? best_b : voxelAtDistance(grid_a.grid, best_b, best);
  out.voxel_a = box.min + local_a;
  out.voxel_b = box.min + best_b;
  out.centre_a = lattice.voxelCentre(out.voxel_a.x, out.voxel_a.y, out.voxel_a.z);
  out.centre_b = lattice.voxelCentre(out.voxel_b.x, out.voxel_b.y, out.voxel_b.z);
  out.centre_distance_voxels = std::sqrt(double(best));
  out.centre_distance = out.centre_distance_voxels * h;
  out.touching = best <= 1;  // a shared voxel, or two voxels sharing a face
  out.gap = std::max(0.0, out.centre_distance - h);
  return out;
}

}  // namespace vox
