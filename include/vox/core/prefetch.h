#pragma once
// Machine tuning of the hot loops: asking the cache for memory a few items before it is read, so the misses overlap
// instead of being waited for one by one. Nothing computed depends on it: each loop gives the same without these
// calls, and the distances are set by measurement (docs/performance.md).
#include <cstddef>
#include <cstdint>

namespace vox {

inline constexpr uintptr_t kCacheLine = 64;

// Asks the cache for every line of [p, p + bytes).
inline void prefetchBytes(const void* p, size_t bytes) {
  if (bytes == 0) return;
  const auto first = reinterpret_cast<uintptr_t>(p) & ~(kCacheLine - 1);
  const uintptr_t last = reinterpret_cast<uintptr_t>(p) + bytes - 1;
  for (uintptr_t line = first; line <= last; line += kCacheLine)
    __builtin_prefetch(reinterpret_cast<const void*>(line));
}

// How many items ahead each loop asks.
namespace prefetch_distance {
inline constexpr size_t kWeldCorners = 16;    // core/mesh.cpp: the hash slots of the corners welded next
inline constexpr size_t kRowTriangles = 8;    // voxelize/ray_caster.cpp: the triangles a row of rays meets
inline constexpr int64_t kDistanceRows = 8;   // analysis/distance.cpp: the rows of a tile's line pass
inline constexpr int64_t kBallTableRows = 2;  // analysis/thickness.cpp: the ball table's rows of the voxels left
}  // namespace prefetch_distance

}  // namespace vox
