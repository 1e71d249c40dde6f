#include "vox/core/lattice.h"

#include <bit>
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

namespace vox {

Box3i intersect(const Box3i& a, const Box3i& b) {
  Box3i r{glm::max(a.min, b.min), glm::min(a.max, b.max)};
  return r.empty() ? Box3i{} : r;
}

Box3i unite(const Box3i& a, const Box3i& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return Box3i{glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

GridFrame Lattice::frameAt(const glm::ivec3& first, const std::string& source) const {
  GridFrame f;
  f.origin = corner(first);
  f.voxel_size = voxel_size;
  f.units = units;
  f.source = source;
  return f;
}

Lattice latticeOf(const GridFrame& frame) { return Lattice{frame.origin, frame.voxel_size, frame.units}; }

namespace {

std::string numberText(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

Status checkSharedLattice(const GridFrame& a, const GridFrame& b, glm::ivec3* offset) {
  const double h = a.voxel_size;
  if (!(h > 0.0) || std::abs(h - b.voxel_size) > 1e-9 * h) {
    return makeError(ErrorCode::kInvalidArgument,
                     "voxel sizes differ: " + numberText(h) + " vs " + numberText(b.voxel_size));
  }
  if (a.units != b.units) {
    return makeError(ErrorCode::kInvalidArgument, "units differ: '" + a.units + "' vs '" + b.units + "'");
  }
  const glm::dvec3 d = (b.origin - a.origin) / h;
  const glm::dvec3 r = glm::dvec3(std::round(d.x), std::round(d.y), std::round(d.z));
  const glm::dvec3 off = glm::abs(d - r);
  if (off.x > 1e-6 || off.y > 1e-6 || off.z > 1e-6 || glm::any(glm::greaterThan(glm::abs(r), glm::dvec3(1e9)))) {
    const glm::dvec3 md = b.origin - a.origin;
    return makeError(ErrorCode::kInvalidArgument, "origins differ by (" + numberText(md.x) + ", " + numberText(md.y) +
                                                      ", " + numberText(md.z) + "), not a whole number of voxels of " +
                                                      numberText(h));
  }
  if (offset) *offset = glm::ivec3(r);
  return Ok{};
}

Box3i filledBox(const LatticeGrid& g) {
  const VoxelGrid& grid = g.grid;
  const int64_t wpr = grid.wordsPerRow();
  glm::ivec3 lo(INT32_MAX), hi(INT32_MIN);
  for (int32_t z = 0; z < grid.nz(); ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < grid.ny(); ++y) {
      const uint64_t* row = grid.rowWords(y, z);
      int64_t first_w = -1, last_w = -1;
      for (int64_t w = 0; w < wpr; ++w) {
        if (row[w] == 0) continue;
        if (first_w < 0) first_w = w;
        last_w = w;
      }
      if (first_w < 0) continue;
      const int32_t x0 = int32_t(first_w * 64 + std::countr_zero(row[first_w]) - 1);
      const int32_t x1 = int32_t(last_w * 64 + 63 - std::countl_zero(row[last_w]) - 1);
      lo = glm::min(lo, glm::ivec3(x0, y, z));
      hi = glm::max(hi, glm::ivec3(x1, y, z));
    }
  }
  if (lo.x > hi.x) return Box3i{};
  return Box3i{g.first + lo, g.first + hi + glm::ivec3(1)};
}

LatticeGrid reframe(const LatticeGrid& g, const Box3i& box, const Lattice& lattice) {
  LatticeGrid out;
  out.first = box.min;
  const glm::ivec3 s = glm::max(box.size(), glm::ivec3(1));
  GridFrame frame = lattice.frameAt(box.min, g.grid.frame().source);
  out.grid = VoxelGrid(Dims{s.x, s.y, s.z}, frame);
  const int64_t wpr = out.grid.wordsPerRow(), in_wpr = g.grid.wordsPerRow();
  const int64_t shift = int64_t(box.min.x) - g.first.x;
  const int64_t nx = s.x;
  const uint64_t last_mask = (uint64_t(1) << ((nx + 1) & 63)) - 1;  // bits below padding bit nx + 1
  for (int32_t z = 0; z < s.z; ++z) {
    for (int32_t y = 0; y < s.y; ++y) {
      const uint64_t* in = latticeRow(g, box.min.y + y, box.min.z + z);
      if (!in) continue;
      uint64_t any = 0;
      for (int64_t w = 0; w < wpr; ++w) any |= rowBitsAt(in, in_wpr, shift + 64 * w);
      if (any == 0) continue;
      uint64_t* row = out.grid.mutableRowWords(y, z);
      for (int64_t w = 0; w < wpr; ++w) row[w] = rowBitsAt(in, in_wpr, shift + 64 * w);
      row[0] &= ~uint64_t(1);
      row[(nx + 1) >> 6] &= last_mask;
      for (int64_t w = ((nx + 1) >> 6) + 1; w < wpr; ++w) row[w] = 0;
    }
  }
  out.grid.releaseEmptyLayers();
  return out;
}

}  // namespace vox
