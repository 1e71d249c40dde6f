#pragma once
// The 26-connected regions of a set of voxels of a box given as bits (x fastest, then y, then z), for the thin-wall
// analyses: each region's voxels, its exposed faces (faces whose neighbour is empty, the box's outside counting as
// empty) and its box.
#include <bit>
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "analysis/neighbours.h"

namespace vox::analysis_detail {

struct MaskRegion {
  const std::vector<int64_t>* voxels = nullptr;  // box indices, the seed first
  int64_t exposed_faces = 0;
  glm::ivec3 min{0}, max{0};  // inclusive, box coordinates
};

// Calls visit(region) for each region, in the order of their first voxel; `filled(i)` tells a box voxel's material.
// visit returns false to stop.
template <class Filled, class Visit>
void forEachRegion(std::vector<uint64_t> todo, int64_t nx, int64_t ny, int64_t nz, Filled&& filled, Visit&& visit) {
  const int64_t plane = nx * ny;
  auto take = [&](int64_t i) {
    uint64_t& w = todo[size_t(i >> 6)];
    const uint64_t bit = uint64_t(1) << (i & 63);
    if (!(w & bit)) return false;
    w &= ~bit;
    return true;
  };
  std::vector<int64_t> queue;
  for (int64_t wi = 0; wi < int64_t(todo.size()); ++wi) {
    while (todo[size_t(wi)]) {
      const int64_t seed = wi * 64 + std::countr_zero(todo[size_t(wi)]);
      take(seed);
      MaskRegion r;
      r.voxels = &queue;
      r.min = glm::ivec3(INT32_MAX);
      r.max = glm::ivec3(INT32_MIN);
      queue.assign(1, seed);
      for (size_t qi = 0; qi < queue.size(); ++qi) {
        const int64_t i = queue[qi];
        const int64_t x = i % nx, y = (i / nx) % ny, z = i / plane;
        const glm::ivec3 v{int32_t(x), int32_t(y), int32_t(z)};
        r.min = glm::min(r.min, v);
        r.max = glm::max(r.max, v);
        r.exposed_faces += (x == 0 || !filled(i - 1)) + (x == nx - 1 || !filled(i + 1)) + (y == 0 || !filled(i - nx)) +
                           (y == ny - 1 || !filled(i + nx)) + (z == 0 || !filled(i - plane)) +
                           (z == nz - 1 || !filled(i + plane));
        forEach26(x, y, z, nx, ny, nz, [&](int64_t j) {
          if (take(j)) queue.push_back(j);
        });
      }
      if (!visit(r)) return;
    }
  }
}

}  // namespace vox::analysis_detail
