// The half of a model on one side of a section plane (vox/analysis/cut.h): whole layers dropped along Z, whole rows
// along Y, and bits masked within the rows along X; at any angle, each row's kept run masked.
#include "vox/analysis/cut.h"

#include <algorithm>
#include <utility>

namespace vox {
namespace {

// Whether coordinate c along the cut axis is kept.
bool kept(int64_t c, int32_t index, bool keep_above) { return keep_above ? c >= index : c <= index; }

// Row bits of the kept x range [lo, hi] (inclusive) in word w; the row's bit of voxel x is x + 1 (one padding bit).
uint64_t rowMask(int64_t w, int64_t lo, int64_t hi) {
  const int64_t b0 = std::max<int64_t>(lo + 1, 64 * w), b1 = std::min<int64_t>(hi + 1, 64 * w + 63);
  if (b0 > b1) return 0;
  const int64_t n = b1 - b0 + 1;
  const uint64_t ones = n >= 64 ? ~uint64_t(0) : (uint64_t(1) << n) - 1;
  return ones << (b0 - 64 * w);
}

// Row (y, z) of `out` (sharing `grid`'s layers) keeps only x in [lo, hi]; the row is copied only when that changes it.
void keepRun(const VoxelGrid& grid, VoxelGrid& out, int32_t y, int32_t z, int64_t lo, int64_t hi) {
  const uint64_t* row = grid.rowWords(y, z);
  uint64_t* dst = nullptr;
  for (int64_t w = 0; w < grid.wordsPerRow(); ++w) {
    const uint64_t keep = row[w] & rowMask(w, lo, hi);
    if (keep == row[w]) continue;
    if (!dst) dst = out.mutableRowWords(y, z);
    dst[w] = keep;
  }
}

}  // namespace

VoxelGrid cutAway(const VoxelGrid& grid, Axis axis, int32_t index, bool keep_above) {
  VoxelGrid out = grid;  // shares the layers; only changed ones are copied
  const int32_t nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
  const int64_t wpr = grid.wordsPerRow();
  const int64_t lo = keep_above ? std::max(index, 0) : 0, hi = keep_above ? nx - 1 : std::min(index, nx - 1);
  for (int32_t z = 0; z < nz; ++z) {
    if (!grid.layerAllocated(z)) continue;
    if (axis == Axis::kZ) {
      if (!kept(z, index, keep_above)) out.releaseLayer(z);
      continue;
    }
    for (int32_t y = 0; y < ny; ++y) {
      const uint64_t* row = grid.rowWords(y, z);
      if (std::all_of(row, row + wpr, [](uint64_t w) { return w == 0; })) continue;
      if (axis == Axis::kY) {
        if (!kept(y, index, keep_above)) std::fill_n(out.mutableRowWords(y, z), wpr, uint64_t(0));
        continue;
      }
      keepRun(grid, out, y, z, lo, hi);
    }
  }
  out.releaseEmptyLayers();
  return out;
}

namespace {

// The run [first, last] of x that the plane keeps in row (y, z), empty when first > last. The slab's value is monotone
// along the row (the row's x term of the plane's sum grows or falls with x, the rest is fixed), so what is kept is
// all, none, a prefix or a suffix: its end is found by bisection on sectionSlab itself.
std::pair<int32_t, int32_t> keptRun(const SectionPlane& plane, int32_t y, int32_t z, int32_t nx, int dropped) {
  const auto kept = [&](int32_t x) { return sectionSlab(plane, glm::ivec3(x, y, z)) != dropped; };
  const bool first = kept(0), last = kept(nx - 1);
  if (first == last) return first ? std::pair{0, nx - 1} : std::pair{0, -1};
  int32_t lo = 0, hi = nx - 1;  // kept(lo) == first, kept(hi) == last
  while (hi - lo > 1) {
    const int32_t mid = lo + (hi - lo) / 2;
    (kept(mid) == first ? lo : hi) = mid;
  }
  return first ? std::pair{0, lo} : std::pair{hi, nx - 1};
}

}  // namespace

VoxelGrid cutAway(const VoxelGrid& grid, const SectionPlane& plane, bool keep_above) {
  VoxelGrid out = grid;
  const int64_t wpr = grid.wordsPerRow();
  const int dropped = keep_above ? -1 : 1;  // the side of the slab that goes
  for (int32_t z = 0; z < grid.nz(); ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < grid.ny(); ++y) {
      const uint64_t* row = grid.rowWords(y, z);
      if (std::all_of(row, row + wpr, [](uint64_t w) { return w == 0; })) continue;
      const auto [first, last] = keptRun(plane, y, z, grid.nx(), dropped);
      keepRun(grid, out, y, z, first, last);
    }
  }
  out.releaseEmptyLayers();
  return out;
}

}  // namespace vox
