// The union of many parts on one lattice, and its update after some of them moved. Each part's rows are read at the
// union's word boundaries (shiftedRowWords) and ORed into the union's rows, over the part's own box only: the cost
// is the parts' words, not the number of parts times the whole extent, as a chain of booleanParts would be. After a
// move only the moved part's old and new boxes are made again, from the parts that reach into them; every other
// layer of the union stays shared with the grid it was copied from (copy-on-write layers, VoxelGrid).
#include <algorithm>
#include <span>
#include <vector>

#include "vox/analysis/assembly.h"
#include "vox/core/parallel.h"

namespace vox {
namespace {

// The bits of word w that lie in padded bit positions [b0, b1).
uint64_t wordMask(int64_t w, int64_t b0, int64_t b1) {
  const int64_t lo = std::max<int64_t>(b0 - 64 * w, 0), hi = std::min<int64_t>(b1 - 64 * w, 64);
  if (hi <= lo) return 0;
  const uint64_t below_hi = hi == 64 ? ~uint64_t(0) : (uint64_t(1) << hi) - 1;
  return below_hi & ~((uint64_t(1) << lo) - 1);
}

// Lattice layer Z of `acc` inside `region` (which acc's box holds) made the union of `parts` there: cleared first
// when `clear`, then each part's rows ORed in, word by word, masked to the region's columns.
void unionLayer(LatticeGrid& acc, std::span<const LatticeGrid> parts, const Box3i& region, int32_t Z, bool clear,
                std::vector<uint64_t>& bits) {
  const int32_t z = Z - acc.first.z;
  const int64_t wpr = acc.grid.wordsPerRow();
  const auto columns = [&](const Box3i& b) {  // padded bit range [b0, b1) of acc's rows
    return std::pair<int64_t, int64_t>{int64_t(b.min.x) - acc.first.x + 1, int64_t(b.max.x) - acc.first.x + 1};
  };
  if (clear && acc.grid.layerAllocated(z)) {
    const auto [b0, b1] = columns(region);
    for (int32_t Y = region.min.y; Y < region.max.y; ++Y) {
      uint64_t* row = acc.grid.mutableRowWords(Y - acc.first.y, z);
      const int64_t w0 = b0 >> 6, w1 = (b1 - 1) >> 6;
      row[w0] &= ~wordMask(w0, b0, b1);
      if (w1 > w0) std::fill(row + w0 + 1, row + w1, uint64_t(0));
      if (w1 > w0) row[w1] &= ~wordMask(w1, b0, b1);
    }
  }
  bits.resize(size_t(wpr));
  for (const LatticeGrid& p : parts) {
    const Box3i meet = intersect(p.box(), region);
    if (meet.empty() || Z < meet.min.z || Z >= meet.max.z || !p.grid.layerAllocated(Z - p.first.z)) continue;
    const auto [b0, b1] = columns(meet);
    const int64_t w0 = b0 >> 6, w1 = (b1 - 1) >> 6, n = w1 - w0 + 1;
    // acc's word w0 starts at lattice column acc.first.x - 1 + 64 w0: the part's padded bit there.
    const int64_t shift = int64_t(acc.first.x) - p.first.x + 64 * w0;
    for (int32_t Y = meet.min.y; Y < meet.max.y; ++Y) {
      shiftedRowWords(latticeRow(p, Y, Z), p.grid.wordsPerRow(), shift, n, bits.data());
      uint64_t any = 0;
      for (int64_t k = 0; k < n; ++k) any |= bits[size_t(k)];
      if (!any) continue;
      uint64_t* row = acc.grid.mutableRowWords(Y - acc.first.y, z);
      // Only the first and last words can reach outside the columns: the words between are ORed whole.
      row[w0] |= bits[0] & wordMask(w0, b0, b1);
      for (int64_t k = 1; k + 1 < n; ++k) row[w0 + k] |= bits[size_t(k)];
      if (n > 1) row[w1] |= bits[size_t(n - 1)] & wordMask(w1, b0, b1);
    }
  }
}

void unionLayers(LatticeGrid& acc, std::span<const LatticeGrid> parts, const Box3i& region, bool clear) {
  int64_t work = 0;
  for (const LatticeGrid& p : parts) {
    const Box3i meet = intersect(p.box(), region);
    if (!meet.empty()) work += int64_t(meet.size().y) * meet.size().z * (meet.size().x / 64 + 1);
  }
  const int threads = threadsFor(work);
  parallelChunks(region.min.z, region.max.z, 4, threads, [&](int, int64_t z0, int64_t z1) {
    std::vector<uint64_t> bits;
    for (int64_t Z = z0; Z < z1; ++Z) unionLayer(acc, parts, region, int32_t(Z), clear, bits);
  });
}

}  // namespace

LatticeGrid unionOfParts(std::span<const LatticeGrid> parts, const Box3i& box, const Lattice& lattice) {
  LatticeGrid acc;
  acc.first = box.min;
  if (box.empty()) return acc;
  const glm::ivec3 s = box.size();
  acc.grid = VoxelGrid(Dims{s.x, s.y, s.z}, lattice.frameAt(box.min));
  unionLayers(acc, parts, box, false);
  return acc;
}

void redoUnionIn(LatticeGrid& acc, std::span<const LatticeGrid> parts, const Box3i& region) {
  const Box3i r = intersect(region, acc.box());
  if (r.empty()) return;
  unionLayers(acc, parts, r, true);
}

}  // namespace vox
