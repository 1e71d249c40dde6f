#pragma once
// The voxels local thickness has not painted yet, as a three-level bit pyramid, so that a ball finds the open voxels
// it covers without walking the voxels (or rows) it covers: a brick is 4 x 4 x 4 voxels in one word (bit x + 4y +
// 16z), a node a word with a bit per open brick of its 4 x 4 x 4 bricks (16^3 voxels), and a block a word with a bit
// per open node of its 4 x 4 x 4 nodes (64^3 voxels). A ball descends only into blocks, nodes and bricks that hold
// open voxels and meet it, so a ball inside material already painted costs a few words.
//
// Threads own layers of nodes (16 voxel slices, round robin) and each has its own block words, so every word is
// written by one thread: paint(t, ...) touches only thread t's voxels.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "vox/core/voxel_grid.h"
#include "vox/core/parallel.h"

namespace vox::analysis_detail {

class OpenVoxels {
 public:
  // Opens every voxel of the box (nx, ny, nz) for which filled(x, y, z) is true; `threads` owners.
  template <class Filled>
  OpenVoxels(Dims box, int threads, Filled&& filled);

  // Calls paint(x, y, z) once for every open voxel of thread t with |p - c|^2 < s and closes it.
  template <class Paint>
  void paintBall(int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, Paint&& paint);

  bool anyOpen(int t) const { return open_[size_t(t)] > 0; }
  int owner(int64_t node_z) const { return int(node_z % threads_); }

 private:
  static int64_t sq(int64_t v) { return v * v; }
  size_t brickIndex(int64_t bx, int64_t by, int64_t bz) const { return size_t(bx + b_.nx * (by + b_.ny * bz)); }
  size_t nodeIndex(int64_t nx, int64_t ny, int64_t nz) const { return size_t(nx + n_.nx * (ny + n_.ny * nz)); }
  size_t blockIndex(int64_t kx, int64_t ky, int64_t kz) const { return size_t(kx + k_.nx * (ky + k_.ny * kz)); }
  static int bit(int64_t x, int64_t y, int64_t z) { return int((x & 3) + 4 * (y & 3) + 16 * (z & 3)); }

  Dims box_, b_, n_, k_;  // voxels, bricks, nodes, blocks
  int threads_;
  std::vector<uint64_t> bricks_, nodes_;
  std::vector<std::vector<uint64_t>> blocks_;  // per thread
  std::vector<int64_t> open_;                  // open bricks per thread
};

template <class Filled>
OpenVoxels::OpenVoxels(Dims box, int threads, Filled&& filled)
    : box_(box),
      b_{(box.nx + 3) / 4, (box.ny + 3) / 4, (box.nz + 3) / 4},
      n_{(b_.nx + 3) / 4, (b_.ny + 3) / 4, (b_.nz + 3) / 4},
      k_{(n_.nx + 3) / 4, (n_.ny + 3) / 4, (n_.nz + 3) / 4},
      threads_(threads),
      bricks_(size_t(b_.count()), 0),
      nodes_(size_t(n_.count()), 0),
      blocks_(size_t(threads), std::vector<uint64_t>(size_t(k_.count()), 0)),
      open_(size_t(threads), 0) {
  parallelChunks(0, b_.nz, 1, threadsFor(box.count() / 4), [&](int, int64_t bz0, int64_t bz1) {
    for (int64_t z = bz0 * 4; z < std::min<int64_t>(box.nz, bz1 * 4); ++z)
      for (int64_t y = 0; y < box.ny; ++y)
        for (int64_t x = 0; x < box.nx; ++x)
          if (filled(x, y, z)) bricks_[brickIndex(x >> 2, y >> 2, z >> 2)] |= uint64_t(1) << bit(x, y, z);
  });
  for (int64_t bz = 0; bz < b_.nz; ++bz)
    for (int64_t by = 0; by < b_.ny; ++by)
      for (int64_t bx = 0; bx < b_.nx; ++bx) {
        if (!bricks_[brickIndex(bx, by, bz)]) continue;
        const int t = owner(bz >> 2);
        ++open_[size_t(t)];
        nodes_[nodeIndex(bx >> 2, by >> 2, bz >> 2)] |= uint64_t(1) << bit(bx, by, bz);
        blocks_[size_t(t)][blockIndex(bx >> 4, by >> 4, bz >> 4)] |= uint64_t(1) << bit(bx >> 2, by >> 2, bz >> 2);
      }
}

// The bits (i + 4j + 16k) of a 4 x 4 x 4 cell for which ax[i] + ay[j] + az[k] < s, without branches. Every value
// is a squared distance within a box of at most kMaxDim voxels a side, so 32-bit lanes hold it.
inline uint64_t cellMask(const int64_t ax[4], const int64_t ay[4], const int64_t az[4], int64_t s) {
  uint64_t m = 0;
#if defined(__SSE2__)
  const __m128i x = _mm_set_epi32(int32_t(ax[3]), int32_t(ax[2]), int32_t(ax[1]), int32_t(ax[0]));
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      const __m128i rem = _mm_set1_epi32(int32_t(s - ay[j] - az[k]));
      const auto row = uint64_t(uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(rem, x)))));
      m |= row << (4 * j + 16 * k);
    }
#else
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      const int64_t rem = s - ay[j] - az[k];
      const uint64_t row =
          uint64_t(ax[0] < rem) | uint64_t(ax[1] < rem) << 1 | uint64_t(ax[2] < rem) << 2 | uint64_t(ax[3] < rem) << 3;
      m |= row << (4 * j + 16 * k);
    }
#endif
  return m;
}

// Squared distance from c to the nearest set bit's voxel of a brick at (x0, y0, z0), along each axis summed: the
// brick's open voxels lie in the box their bits span, so a ball that does not reach that box takes none of them.
inline int64_t nearestBitBox(uint64_t bits, int64_t cx, int64_t cy, int64_t cz, int64_t x0, int64_t y0, int64_t z0) {
  uint64_t v = bits | bits >> 32;
  v |= v >> 16;  // 16 bits: row y = j of any z in bits 4j..4j+3
  const auto ym = uint32_t(((v & 0xF) != 0) | ((v >> 4 & 0xF) != 0) << 1 | ((v >> 8 & 0xF) != 0) << 2 |
                           ((v >> 12 & 0xF) != 0) << 3);
  const auto xm = uint32_t((v | v >> 4 | v >> 8 | v >> 12) & 0xF);
  const auto zm = uint32_t((bits & 0xFFFF) != 0) | uint32_t((bits >> 16 & 0xFFFF) != 0) << 1 |
                  uint32_t((bits >> 32 & 0xFFFF) != 0) << 2 | uint32_t((bits >> 48) != 0) << 3;
  auto axis = [](uint32_t m, int64_t c, int64_t lo) {
    const int64_t a = lo + std::countr_zero(m), b = lo + 31 - std::countl_zero(m);
    const int64_t d = c < a ? a - c : c > b ? c - b : 0;
    return d * d;
  };
  return axis(xm, cx, x0) + axis(ym, cy, y0) + axis(zm, cz, z0);
}

// For the four cells of `size` voxels from `lo` on one axis: the squared distance from c to their nearest voxel
// centre (near) and to their farthest (far).
inline void axisReach(int64_t c, int64_t lo, int64_t size, int64_t near[4], int64_t far[4]) {
  for (int i = 0; i < 4; ++i) {
    const int64_t a = lo + i * size, b = a + size - 1;
    const int64_t dn = c < a ? a - c : c > b ? c - b : 0;
    near[i] = dn * dn;
    far[i] = std::max((c - a) * (c - a), (b - c) * (b - c));
  }
}

template <class Paint>
void OpenVoxels::paintBall(int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, Paint&& paint) {
  std::vector<uint64_t>& blocks = blocks_[size_t(t)];
  int64_t r = int64_t(std::sqrt(double(s)));  // the ball reaches r < sqrt(s) voxels from its centre
  while (r > 0 && r * r >= s) --r;
  while ((r + 1) * (r + 1) < s) ++r;
  const int64_t k0x = std::max<int64_t>(0, cx - r) >> 6, k1x = std::min<int64_t>(box_.nx - 1, cx + r) >> 6;
  const int64_t k0y = std::max<int64_t>(0, cy - r) >> 6, k1y = std::min<int64_t>(box_.ny - 1, cy + r) >> 6;
  const int64_t k0z = std::max<int64_t>(0, cz - r) >> 6, k1z = std::min<int64_t>(box_.nz - 1, cz + r) >> 6;
  int64_t nx[4], ny[4], nz[4], fx[4], fy[4], fz[4];
  for (int64_t kz = k0z; kz <= k1z; ++kz)
    for (int64_t ky = k0y; ky <= k1y; ++ky)
      for (int64_t kx = k0x; kx <= k1x; ++kx) {
        uint64_t& block = blocks[blockIndex(kx, ky, kz)];
        if (!block) continue;
        axisReach(cx, kx * 64, 16, nx, fx);
        axisReach(cy, ky * 64, 16, ny, fy);
        axisReach(cz, kz * 64, 16, nz, fz);
        for (uint64_t nb = block & cellMask(nx, ny, nz, s); nb; nb &= nb - 1) {
          const int i = std::countr_zero(nb);
          const int64_t ix = kx * 4 + (i & 3), iy = ky * 4 + ((i >> 2) & 3), iz = kz * 4 + (i >> 4);
          uint64_t& node = nodes_[nodeIndex(ix, iy, iz)];
          int64_t bnx[4], bny[4], bnz[4], bfx[4], bfy[4], bfz[4];
          axisReach(cx, ix * 16, 4, bnx, bfx);
          axisReach(cy, iy * 16, 4, bny, bfy);
          axisReach(cz, iz * 16, 4, bnz, bfz);
          const uint64_t met = node & cellMask(bnx, bny, bnz, s);
          const uint64_t whole = met ? cellMask(bfx, bfy, bfz, s) : 0;  // bricks the ball holds entirely
          for (uint64_t bb = met; bb; bb &= bb - 1) {
            const int j = std::countr_zero(bb);
            const int64_t bx = ix * 4 + (j & 3), by = iy * 4 + ((j >> 2) & 3), bz = iz * 4 + (j >> 4);
            uint64_t& brick = bricks_[brickIndex(bx, by, bz)];
            uint64_t taken = brick;
            if (!(whole >> j & 1)) {
              if (nearestBitBox(brick, cx, cy, cz, bx * 4, by * 4, bz * 4) >= s) continue;
              int64_t vx[4], vy[4], vz[4];
              for (int q = 0; q < 4; ++q) {
                vx[q] = sq(bx * 4 + q - cx);
                vy[q] = sq(by * 4 + q - cy);
                vz[q] = sq(bz * 4 + q - cz);
              }
              taken &= cellMask(vx, vy, vz, s);
            }
            if (!taken) continue;
            for (uint64_t v = taken; v; v &= v - 1) {
              const int q = std::countr_zero(v);
              paint(bx * 4 + (q & 3), by * 4 + ((q >> 2) & 3), bz * 4 + (q >> 4));
            }
            brick &= ~taken;
            if (brick) continue;
            --open_[size_t(t)];
            node &= ~(uint64_t(1) << j);
          }
          if (!node) block &= ~(uint64_t(1) << i);
        }
      }
}

}  // namespace vox::analysis_detail
