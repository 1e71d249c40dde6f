#pragma once
// One lattice for many parts (docs/conventions.md, "Assemblies"). A lattice is a voxel size and an
// origin: lattice voxel (I, J, K) has its centre at origin + ((I + 0.5) h, (J + 0.5) h, (K + 0.5) h), computed in
// double exactly so (docs/conventions.md, "Grid placement", with I counted from the lattice origin). Every part of an
// assembly is a VoxelGrid covering a box of lattice voxels: its voxel (x, y, z) is lattice voxel first + (x, y, z).
// Parts with different boxes on one lattice combine by word operations (shifted rows), never by resampling.
#include <algorithm>
#include <cstdint>
#include <string>

#include <glm/vec3.hpp>

#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

// A box of lattice voxels, half-open: min <= (I, J, K) < max. Empty when any max <= min.
struct Box3i {
  glm::ivec3 min{0};
  glm::ivec3 max{0};
  bool empty() const { return max.x <= min.x || max.y <= min.y || max.z <= min.z; }
  glm::ivec3 size() const { return empty() ? glm::ivec3(0) : max - min; }
  int64_t count() const {
    const glm::ivec3 s = size();
    return int64_t(s.x) * s.y * s.z;
  }
  bool operator==(const Box3i&) const = default;
};
// The voxels in both boxes (empty when they do not meet); the smallest box holding both (an empty box adds nothing).
Box3i intersect(const Box3i& a, const Box3i& b);
Box3i unite(const Box3i& a, const Box3i& b);
// True when the boxes share at least one voxel.
inline bool boxesMeet(const Box3i& a, const Box3i& b) { return !intersect(a, b).empty(); }

// The lattice itself: origin (the corner of lattice voxel (0, 0, 0)), voxel size and units.
struct Lattice {
  glm::dvec3 origin{0.0};
  double voxel_size = 1.0;
  std::string units = "model";
  bool operator==(const Lattice&) const = default;
  // Centre of lattice voxel (i, j, k), docs/conventions.md, "Grid placement".
  glm::dvec3 voxelCentre(int64_t i, int64_t j, int64_t k) const {
    return origin +
           glm::dvec3((double(i) + 0.5) * voxel_size, (double(j) + 0.5) * voxel_size, (double(k) + 0.5) * voxel_size);
  }
  // Corner of lattice voxel (i, j, k) (its smallest coordinates): origin + (i, j, k) h.
  glm::dvec3 corner(const glm::ivec3& v) const { return origin + glm::dvec3(v) * voxel_size; }
  // The frame of a grid whose voxel (0, 0, 0) is lattice voxel `first`: origin = corner(first).
  GridFrame frameAt(const glm::ivec3& first, const std::string& source = {}) const;
};

// The lattice a grid lies on, taking its voxel (0, 0, 0) as lattice voxel (0, 0, 0).
Lattice latticeOf(const GridFrame& frame);

// A part's voxels on a lattice: `grid` covers lattice voxels [first, first + dims). The grid's frame origin is the
// lattice's corner(first) (for display and files); `first` is what operations between parts use.
struct LatticeGrid {
  VoxelGrid grid;
  glm::ivec3 first{0};
  Box3i box() const { return Box3i{first, first + glm::ivec3(grid.nx(), grid.ny(), grid.nz())}; }
};

// How two grids' frames relate as lattices. Ok with `offset` set when both have the same voxel size and units and
// b's origin lies a whole number of voxels from a's (to a relative 1e-6 of the voxel size, so grids written to files
// and read back still match): b's voxel (0, 0, 0) is a's voxel `offset`. Otherwise an error saying how they differ
// ("voxel sizes differ: 0.01 vs 0.02", "origins differ by (0.005, 0, 0), not a whole number of voxels of 0.01").
Status checkSharedLattice(const GridFrame& a, const GridFrame& b, glm::ivec3* offset);

// The 64 voxels of a padded row starting at padded bit `bit` (any value: bits outside the row's wpr words read as
// zero), least significant bit first. Rows are VoxelGrid rows (bit xp = x + 1). A grid starting at lattice X0 reads
// another starting at X1 with bit = (X0 - X1) + 64 w for its word w: the same lattice voxels, bit for bit.
inline uint64_t rowBitsAt(const uint64_t* row, int64_t wpr, int64_t bit) {
  const int64_t w = bit >> 6;  // floor, also for negative bits
  const int s = int(bit & 63);
  const uint64_t lo = (w >= 0 && w < wpr) ? row[w] : 0;
  if (s == 0) return lo;
  const uint64_t hi = (w + 1 >= 0 && w + 1 < wpr) ? row[w + 1] : 0;
  return (lo >> s) | (hi << (64 - s));
}

// out[w] = rowBitsAt(row, wpr, shift + 64 w) for w in [0, n): a whole row read at another grid's word boundaries,
// with two loads and two shifts per word where the row has both words.
inline void shiftedRowWords(const uint64_t* row, int64_t wpr, int64_t shift, int64_t n, uint64_t* out) {
  const int64_t q = shift >> 6;
  const int r = int(shift & 63);
  const int64_t lo = std::clamp<int64_t>(-q, 0, n), hi = std::clamp<int64_t>(wpr - 1 - q, lo, n);
  for (int64_t w = 0; w < lo; ++w) out[w] = rowBitsAt(row, wpr, shift + 64 * w);
  if (r == 0) {
    for (int64_t w = lo; w < hi; ++w) out[w] = row[q + w];
  } else {
    for (int64_t w = lo; w < hi; ++w) out[w] = (row[q + w] >> r) | (row[q + w + 1] << (64 - r));
  }
  for (int64_t w = hi; w < n; ++w) out[w] = rowBitsAt(row, wpr, shift + 64 * w);
}

// Row (Y, Z) of a lattice grid in lattice coordinates, or nullptr when the grid does not cover that row.
inline const uint64_t* latticeRow(const LatticeGrid& g, int32_t Y, int32_t Z) {
  const int32_t y = Y - g.first.y, z = Z - g.first.z;
  if (y < 0 || z < 0 || y >= g.grid.ny() || z >= g.grid.nz() || !g.grid.layerAllocated(z)) return nullptr;
  return g.grid.rowWords(y, z);
}

// The smallest box of lattice voxels holding every filled voxel of `g` (empty when none). O(allocated words).
Box3i filledBox(const LatticeGrid& g);

// `g` cut or grown to cover exactly `box` (voxels outside it are dropped). Word operations per row.
LatticeGrid reframe(const LatticeGrid& g, const Box3i& box, const Lattice& lattice);

}  // namespace vox
