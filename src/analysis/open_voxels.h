#pragma once
// The voxels local thickness has not painted yet, as a three-level bit pyramid, so that a ball finds the open voxels
// it covers without walking the voxels (or rows) it covers: a brick is 4 x 4 x 4 voxels in one word (bit x + 4y +
// 16z), a node a word with a bit per open brick of its 4 x 4 x 4 bricks (16^3 voxels), and a block a word with a bit
// per open node of its 4 x 4 x 4 nodes (64^3 voxels). A ball descends only into blocks, nodes and bricks that hold
// open voxels and meet it, so a ball inside material already painted costs a few words.
//
// Threads own layers of blocks (64 voxel slices, round robin) across Z, or across Y when the box has more blocks
// along Y (a part thinner than a block layer along Z is still shared), and each has its own block words, so every
// word is written by one thread: paint(t, ...) touches only thread t's voxels, and a block is walked by one thread
// only (a ball that meets no open block of thread t costs that thread one look at the block words of its box). Whole
// layers keep each thread's words and voxels in runs of memory of their own: owning blocks in a checkerboard instead
// took 30% more time at R = 1000, the threads writing the same cache lines where blocks meet.
#include <algorithm>
#include <array>
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
  // The thread that owns block (kx, ky, kz) and every node, brick and voxel in it.
  int owner(int64_t, int64_t ky, int64_t kz) const { return int((layers_in_y_ ? ky : kz) % threads_); }

 private:
  static int64_t sq(int64_t v) { return v * v; }
  size_t brickIndex(int64_t bx, int64_t by, int64_t bz) const { return size_t(bx + b_.nx * (by + b_.ny * bz)); }
  size_t nodeIndex(int64_t nx, int64_t ny, int64_t nz) const { return size_t(nx + n_.nx * (ny + n_.ny * nz)); }
  size_t blockIndex(int64_t kx, int64_t ky, int64_t kz) const { return size_t(kx + k_.nx * (ky + k_.ny * kz)); }
  static int bit(int64_t x, int64_t y, int64_t z) { return int((x & 3) + 4 * (y & 3) + 16 * (z & 3)); }

  // One axis of a ball: for the blocks its box meets, the squared distance from the centre's coordinate c to each
  // block, node and brick along the axis (nearest voxel; farthest too for bricks), filled once per ball so that the
  // walk reads the four values of a cell as one vector. (A brick's voxels are worked out when it is tested: a table
  // of them cost more than the bricks a ball tests.)
  struct Reach {
    int64_t k0 = 0, k1 = -1;  // blocks k0..k1
    std::vector<int32_t> blocks, node_near, brick_near, brick_far;
    void set(int64_t c, int64_t r, int64_t n) {
      k0 = std::max<int64_t>(0, c - r) >> 6;
      k1 = std::min<int64_t>(n - 1, c + r) >> 6;
      const auto count = size_t(k1 - k0 + 1);
      blocks.resize(count);
      node_near.resize(count * 4);
      brick_near.resize(count * 16);
      brick_far.resize(count * 16);
      // Only what the walk can read is filled: every block and node of the box's blocks and the bricks of the nodes
      // within r of c. 32-bit: coordinates are below 2^15.
      const auto c32 = int32_t(c), base = int32_t(k0 * 64);
      auto near = [c32](int32_t a, int32_t b) {
        const int32_t d = std::max({a - c32, c32 - b, 0});
        return d * d;
      };
      for (int32_t i = 0; i < int32_t(count); ++i) blocks[size_t(i)] = near(base + 64 * i, base + 64 * i + 63);
      for (int32_t i = 0; i < int32_t(count) * 4; ++i) node_near[size_t(i)] = near(base + 16 * i, base + 16 * i + 15);
      const int64_t b0 = (std::max<int64_t>(0, c - r) >> 4) * 4, b1 = (std::min<int64_t>(n - 1, c + r) >> 4) * 4 + 3;
      for (auto i = int32_t(b0 - k0 * 16); i <= int32_t(b1 - k0 * 16); ++i) {
        const int32_t a = base + 4 * i, b = a + 3;
        brick_near[size_t(i)] = near(a, b);
        const int32_t f = std::max(c32 - a, b - c32);
        brick_far[size_t(i)] = f * f;
      }
    }
    int64_t block(int64_t k) const { return blocks[size_t(k - k0)]; }
    const int32_t* nodeNear(int64_t node) const { return node_near.data() + (node - k0 * 4); }
    const int32_t* brickNear(int64_t brick) const { return brick_near.data() + (brick - k0 * 16); }
    const int32_t* brickFar(int64_t brick) const { return brick_far.data() + (brick - k0 * 16); }
  };

  Dims box_, b_, n_, k_;  // voxels, bricks, nodes, blocks
  int threads_;
  bool layers_in_y_;
  std::vector<uint64_t> bricks_, nodes_;
  std::vector<std::vector<uint64_t>> blocks_;  // per thread
  std::vector<int64_t> open_;                  // open bricks per thread
  struct alignas(64) ThreadReach {
    std::array<Reach, 3> axis;
  };
  std::vector<ThreadReach> reach_;  // per thread, each on its own cache lines
};

template <class Filled>
OpenVoxels::OpenVoxels(Dims box, int threads, Filled&& filled)
    : box_(box),
      b_{(box.nx + 3) / 4, (box.ny + 3) / 4, (box.nz + 3) / 4},
      n_{(b_.nx + 3) / 4, (b_.ny + 3) / 4, (b_.nz + 3) / 4},
      k_{(n_.nx + 3) / 4, (n_.ny + 3) / 4, (n_.nz + 3) / 4},
      threads_(threads),
      layers_in_y_(k_.ny > k_.nz),
      bricks_(size_t(b_.count()), 0),
      nodes_(size_t(n_.count()), 0),
      blocks_(size_t(threads), std::vector<uint64_t>(size_t(k_.count()), 0)),
      open_(size_t(threads), 0),
      reach_(size_t(threads)) {
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
        const int t = owner(bx >> 4, by >> 4, bz >> 4);
        ++open_[size_t(t)];
        nodes_[nodeIndex(bx >> 2, by >> 2, bz >> 2)] |= uint64_t(1) << bit(bx, by, bz);
        blocks_[size_t(t)][blockIndex(bx >> 4, by >> 4, bz >> 4)] |= uint64_t(1) << bit(bx >> 2, by >> 2, bz >> 2);
      }
}

// The bits (i + 4j + 16k) of a 4 x 4 x 4 cell for which ax[i] + ay[j] + az[k] < s, without branches. Every value
// is a squared distance within a box of at most kMaxDim voxels a side, so 32-bit lanes hold it.
inline uint64_t cellMask(const int32_t* ax, const int32_t* ay, const int32_t* az, int32_t s) {
  uint64_t m = 0;
#if defined(__SSE2__)
  const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(ax));
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      const __m128i rem = _mm_set1_epi32(s - ay[j] - az[k]);
      const auto row = uint64_t(uint32_t(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(rem, x)))));
      m |= row << (4 * j + 16 * k);
    }
#else
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      const int32_t rem = s - ay[j] - az[k];
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

template <class Paint>
void OpenVoxels::paintBall(int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, Paint&& paint) {
  std::vector<uint64_t>& blocks = blocks_[size_t(t)];
  int64_t r = int64_t(std::sqrt(double(s)));  // the ball reaches r < sqrt(s) voxels from its centre
  while (r > 0 && r * r >= s) --r;
  while ((r + 1) * (r + 1) < s) ++r;
  {  // nothing to do when the thread has no open voxel in the blocks of the ball's box
    const int64_t k0x = std::max<int64_t>(0, cx - r) >> 6, k1x = std::min<int64_t>(box_.nx - 1, cx + r) >> 6;
    const int64_t k0y = std::max<int64_t>(0, cy - r) >> 6, k1y = std::min<int64_t>(box_.ny - 1, cy + r) >> 6;
    const int64_t k0z = std::max<int64_t>(0, cz - r) >> 6, k1z = std::min<int64_t>(box_.nz - 1, cz + r) >> 6;
    uint64_t any = 0;
    for (int64_t kz = k0z; kz <= k1z; ++kz) {
      for (int64_t ky = k0y; ky <= k1y; ++ky)
        for (int64_t kx = k0x; kx <= k1x; ++kx) any |= blocks[blockIndex(kx, ky, kz)];
    }
    if (!any) return;
  }
  Reach& ax = reach_[size_t(t)].axis[0];
  Reach& ay = reach_[size_t(t)].axis[1];
  Reach& az = reach_[size_t(t)].axis[2];
  ax.set(cx, r, box_.nx);
  ay.set(cy, r, box_.ny);
  az.set(cz, r, box_.nz);
  const auto s32 = int32_t(s);
  for (int64_t kz = az.k0; kz <= az.k1; ++kz) {
    if (az.block(kz) >= s) continue;
    for (int64_t ky = ay.k0; ky <= ay.k1; ++ky) {
      const int64_t rest = s - az.block(kz) - ay.block(ky);  // the row of blocks meets the ball where dx^2 < rest
      if (rest <= 0 || owner(0, ky, kz) != t) continue;
      int64_t w = int64_t(std::sqrt(double(rest)));
      while (w > 0 && w * w >= rest) --w;
      while ((w + 1) * (w + 1) < rest) ++w;
      const int64_t kx0 = std::max(ax.k0, std::max<int64_t>(0, cx - w) >> 6);
      const int64_t kx1 = std::min(ax.k1, (cx + w) >> 6);
      for (int64_t kx = kx0; kx <= kx1; ++kx) {
        uint64_t& block = blocks[blockIndex(kx, ky, kz)];
        if (!block) continue;
        for (uint64_t nb = block & cellMask(ax.nodeNear(kx * 4), ay.nodeNear(ky * 4), az.nodeNear(kz * 4), s32); nb;
             nb &= nb - 1) {
          const int i = std::countr_zero(nb);
          const int64_t ix = kx * 4 + (i & 3), iy = ky * 4 + ((i >> 2) & 3), iz = kz * 4 + (i >> 4);
          uint64_t& node = nodes_[nodeIndex(ix, iy, iz)];
          const uint64_t met = node & cellMask(ax.brickNear(ix * 4), ay.brickNear(iy * 4), az.brickNear(iz * 4), s32);
          const uint64_t whole =  // bricks the ball holds entirely
              met ? cellMask(ax.brickFar(ix * 4), ay.brickFar(iy * 4), az.brickFar(iz * 4), s32) : 0;
          for (uint64_t bb = met; bb; bb &= bb - 1) {
            const int j = std::countr_zero(bb);
            const int64_t bx = ix * 4 + (j & 3), by = iy * 4 + ((j >> 2) & 3), bz = iz * 4 + (j >> 4);
            uint64_t& brick = bricks_[brickIndex(bx, by, bz)];
            uint64_t taken = brick;
            if (!(whole >> j & 1)) {
              if (nearestBitBox(brick, cx, cy, cz, bx * 4, by * 4, bz * 4) >= s) continue;
              int32_t vx[4], vy[4], vz[4];
              for (int q = 0; q < 4; ++q) {
                vx[q] = int32_t(sq(bx * 4 + q - cx));
                vy[q] = int32_t(sq(by * 4 + q - cy));
                vz[q] = int32_t(sq(bz * 4 + q - cz));
              }
              taken &= cellMask(vx, vy, vz, s32);
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
  }
}

}  // namespace vox::analysis_detail
