#pragma once
// Word operations on whole layers (thesis 5.1, 5.2.2): a voxel is interior when it and its six face neighbours are
// filled, interior = filled & xm & xp & ym & yp & zm & zp, and on the surface when filled & ~interior.
//
// Why a layer can be treated as one long bit string: a row holds nx + 2 padded bits in wordsPerRow() words, and
// both the first bit of a row (padded x = 0) and the last bit of its last word (padded x >= nx + 1) are always
// zero. Shifting a word by one therefore pulls in a zero from the neighbouring row's word, never a real voxel,
// so the x +- 1 masks need no per-row special case and the loop runs over a flat range of words.
#include <bit>
#include <cstdint>

#include "vox/core/bits.h"
#include "vox/core/voxel_grid.h"

namespace vox::analysis_detail {

// Interior word at flat index w of a layer: `cur` is the layer, `below` / `above` layers z -+ 1, wpr the words per
// row. w must lie in a real row (wpr <= w < wpr * (ny + 1)) so that w - 1, w + 1 and w +- wpr are inside the layer.
inline uint64_t interiorWord(const uint64_t* below, const uint64_t* cur, const uint64_t* above, int64_t wpr,
                             int64_t w) {
  const uint64_t c = cur[w];
  const uint64_t xm = (c << 1) | (cur[w - 1] >> 63);  // bit b holds voxel b - 1
  const uint64_t xp = (c >> 1) | (cur[w + 1] << 63);  // bit b holds voxel b + 1
  return c & xm & xp & cur[w - wpr] & cur[w + wpr] & below[w] & above[w];
}

// Flat word range of the real rows of a layer (rows y = 0 .. ny - 1).
inline int64_t firstRowWord(const VoxelGrid& g) { return g.wordsPerRow(); }
inline int64_t endRowWord(const VoxelGrid& g) { return g.wordsPerRow() * (int64_t(g.ny()) + 1); }

using vox::popcount64;
using vox::popcountWords;

}  // namespace vox::analysis_detail
