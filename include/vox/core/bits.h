#pragma once
// Bit counting and searching shared by the modules that walk bit planes.
#include <algorithm>
#include <bit>
#include <cstdint>

namespace vox {

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

// First position in [from, end) whose bit equals `value` (end when none), in padded x.
inline int64_t nextBit(const uint64_t* row, int64_t from, int64_t end, bool value) {
  if (from >= end) return end;
  int64_t w = from >> 6;
  uint64_t bits = (value ? row[w] : ~row[w]) & (~uint64_t(0) << (from & 63));
  while (!bits) {
    ++w;
    if (w * 64 >= end) return end;
    bits = value ? row[w] : ~row[w];
  }
  return std::min(end, w * 64 + std::countr_zero(bits));
}

}  // namespace vox
