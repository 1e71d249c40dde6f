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

// Population count. The x86-64 baseline that Debian targets has no POPCNT instruction, so std::popcount becomes a
// call into libgcc; this inline bit-slice count is about twice as fast there and lets loops vectorize. Builds that
// enable POPCNT (-mpopcnt, -march=x86-64-v2 or later) and other architectures get the instruction.
inline int popcount64(uint64_t x) {
#if defined(__x86_64__) && !defined(__POPCNT__)
  x = x - ((x >> 1) & 0x5555555555555555ull);
  x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
  x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Full;
  return int((x * 0x0101010101010101ull) >> 56);
#else
  return std::popcount(x);
#endif
}

inline int64_t popcountWords(const uint64_t* w, int64_t n) {
  int64_t c = 0;
  for (int64_t i = 0; i < n; ++i) c += popcount64(w[i]);
  return c;
}

}  // namespace vox::analysis_detail
