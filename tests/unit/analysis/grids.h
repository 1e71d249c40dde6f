#pragma once
// Grids built in code for the analysis tests, and brute-force versions of the analyses (voxel by voxel with
// VoxelGrid::get) that the word-parallel implementations are checked against.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/vec3.hpp>

#include "support/grids.h"
#include "vox/core/voxel_grid.h"

namespace vox::test {

// Filled box [lo, hi) in voxel indices.
inline void fillBox(VoxelGrid& g, glm::ivec3 lo, glm::ivec3 hi) {
  for (int z = lo.z; z < hi.z; ++z)
    for (int y = lo.y; y < hi.y; ++y) g.fillRun(y, z, lo.x, hi.x);
}

inline VoxelGrid boxGrid(Dims d, glm::ivec3 lo, glm::ivec3 hi, GridFrame frame = {}) {
  VoxelGrid g(d, std::move(frame));
  fillBox(g, lo, hi);
  return g;
}

// Ball of radius r (in voxels) centred at c (voxel coordinates of a centre may be fractional), by centre sampling:
// voxel (i, j, k) is filled when its centre (i + 0.5, ...) lies strictly inside. Filled row by row.
inline VoxelGrid ballGrid(Dims d, glm::dvec3 c, double r, GridFrame frame = {}) {
  VoxelGrid g(d, std::move(frame));
  for (int z = 0; z < d.nz; ++z) {
    for (int y = 0; y < d.ny; ++y) {
      const double dy = y + 0.5 - c.y, dz = z + 0.5 - c.z;
      const double q = r * r - dy * dy - dz * dz;
      if (q <= 0) continue;
      const double half = std::sqrt(q);
      // x + 0.5 in (c.x - half, c.x + half)
      const int64_t x0 = int64_t(std::floor(c.x - half - 0.5)) + 1;
      const int64_t x1 = int64_t(std::ceil(c.x + half - 0.5));
      int64_t lo = x0, hi = x1;
      while (lo < hi && (lo + 0.5 - c.x) * (lo + 0.5 - c.x) >= q) ++lo;
      while (hi > lo && (hi - 0.5 - c.x) * (hi - 0.5 - c.x) >= q) --hi;
      g.fillRun(y, z, lo, hi);
    }
  }
  return g;
}

// Random union of boxes: blobs with thick and thin parts, so peeling takes several layers.
inline VoxelGrid randomBoxes(Dims d, int count, uint32_t seed) {
  VoxelGrid g(d);
  std::mt19937 rng(seed);
  for (int i = 0; i < count; ++i) {
    glm::ivec3 lo(0), hi(0);
    for (int a = 0; a < 3; ++a) {
      const int n = a == 0 ? d.nx : (a == 1 ? d.ny : d.nz);
      std::uniform_int_distribution<int> pos(0, n - 1);
      int u = pos(rng), v = pos(rng);
      if (u > v) std::swap(u, v);
      lo[a] = u;
      hi[a] = v + 1;
    }
    fillBox(g, lo, hi);
  }
  return g;
}

// ---- Brute force ----

inline bool bruteSurface(const VoxelGrid& g, int x, int y, int z) {
  return g.get(x, y, z) && (!g.get(x - 1, y, z) || !g.get(x + 1, y, z) || !g.get(x, y - 1, z) || !g.get(x, y + 1, z) ||
                            !g.get(x, y, z - 1) || !g.get(x, y, z + 1));
}

inline VoxelGrid brutePeel(const VoxelGrid& g, int64_t* removed) {
  VoxelGrid out(g.dims(), g.frame());
  int64_t r = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        if (!g.get(x, y, z)) continue;
        if (bruteSurface(g, x, y, z)) {
          ++r;
        } else {
          out.set(x, y, z);
        }
      }
  if (removed) *removed = r;
  return out;
}

inline bool sameVoxels(const VoxelGrid& a, const VoxelGrid& b) {
  if (a.dims() != b.dims()) return false;
  for (int z = 0; z < a.nz(); ++z)
    for (int y = 0; y < a.ny(); ++y)
      for (int x = 0; x < a.nx(); ++x)
        if (a.get(x, y, z) != b.get(x, y, z)) return false;
  return true;
}

// Lengths of the maximal filled runs along a ray: start voxel s, direction unit axis a, n steps.
inline std::vector<int> bruteRuns(const VoxelGrid& g, glm::ivec3 s, int axis) {
  const int n = axis == 0 ? g.nx() : (axis == 1 ? g.ny() : g.nz());
  std::vector<int> runs;
  int len = 0;
  for (int i = 0; i <= n; ++i) {
    glm::ivec3 p = s;
    p[axis] = i;
    const bool f = i < n && g.get(p.x, p.y, p.z);
    if (f) {
      ++len;
    } else if (len > 0) {
      runs.push_back(len);
      len = 0;
    }
  }
  return runs;
}

}  // namespace vox::test
