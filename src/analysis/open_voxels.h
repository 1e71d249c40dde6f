#pragma once
// The voxels local thickness has not painted yet, as a three-level bit pyramid, so that a ball finds the open voxels
// it covers without walking the voxels (or rows) it covers: a brick is 4 x 4 x 4 voxels in one word (bit x + 4y +
// 16z), a node a word with a bit per open brick of its 4 x 4 x 4 bricks (16^3 voxels), and a block a word with a bit
// per open node of its 4 x 4 x 4 nodes (64^3 voxels). A ball descends only into blocks, nodes and bricks that hold
// open voxels and meet it, so a ball inside material already painted costs a few words.
//
// Each thread keeps the words of its open bricks packed in an array of its own, node by node in the order of the
// pyramid, and packs it again whenever half of them have closed: a ball's walk reads the bricks about its sphere,
// and after the largest balls have painted the bulk of a part the open bricks are a thin shell at its surface (at
// R = 1000, a quarter of them after the first million of 15.5 million balls, 1% before the last), which packed stays in
// the processor's caches where the box's whole array of brick words (87 MB) does not.
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
// The AVX2 and AVX-512 walks are built with GCC or Clang for x86-64 and taken only where the processor has them.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define VOX_OPEN_VOXELS_X86 1
#include <immintrin.h>
#else
#define VOX_OPEN_VOXELS_X86 0
#endif

#include "analysis/huge_array.h"
#include "vox/core/voxel_grid.h"
#include "vox/core/parallel.h"

namespace vox::analysis_detail {

using HugeWords = HugeArray<uint64_t>;

class OpenVoxels;
// The ball's walk for each kind of processor (analysis/open_voxels_walk.inc); OpenVoxels::paintBall picks one.
#if VOX_OPEN_VOXELS_X86
#define VOX_WALK_AVX512_ATTRIBUTE __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,popcnt,bmi,bmi2")))
#define VOX_WALK_AVX2_ATTRIBUTE __attribute__((target("avx2,popcnt,bmi,bmi2")))
#else
#define VOX_WALK_AVX512_ATTRIBUTE
#define VOX_WALK_AVX2_ATTRIBUTE
#endif
namespace open_voxels_sse2 {
template <class Window, class Paint>
void paintBall(OpenVoxels& o, int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, const Window& w, Paint&& paint);
}
namespace open_voxels_avx2 {
template <class Window, class Paint>
VOX_WALK_AVX2_ATTRIBUTE void paintBall(OpenVoxels& o, int t, int64_t cx, int64_t cy, int64_t cz, int64_t s,
                                       const Window& w, Paint&& paint);
}
namespace open_voxels_avx512 {
template <class Window, class Paint>
VOX_WALK_AVX512_ATTRIBUTE void paintBall(OpenVoxels& o, int t, int64_t cx, int64_t cy, int64_t cz, int64_t s,
                                         const Window& w, Paint&& paint);
}

class OpenVoxels {
 public:
  // Which walk paintBall takes: the widest the processor has (kAuto: AVX-512, else AVX2, else SSE2), or the one
  // named, where the processor has it.
  enum class Simd { kAuto, kSse2, kAvx2, kAvx512 };
  static bool avx512Available() {
#if VOX_OPEN_VOXELS_X86
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("bmi") &&
           __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("popcnt");
#else
    return false;
#endif
  }
  static bool avx2Available() {
#if VOX_OPEN_VOXELS_X86
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
           __builtin_cpu_supports("popcnt");
#else
    return false;
#endif
  }

  // Opens every voxel of the box (nx, ny, nz) for which filled(x, y, z) is true; `threads` owners. A walk named
  // that the processor lacks gives the next narrower one it has (SSE2, or plain code, at the least).
  template <class Filled>
  OpenVoxels(Dims box, int threads, Filled&& filled, Simd simd = Simd::kAuto);

  // A box about a ball's centre: offsets lo..hi from it on each axis, inclusive.
  struct Window {
    int64_t lo[3], hi[3];
  };
  // Calls paint(x, y, z) once for every open voxel of thread t with |p - c|^2 < s and closes it.
  template <class Paint>
  void paintBall(int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, Paint&& paint) {
    constexpr int64_t kAll = int64_t(1) << 20;  // beyond any box (coordinates are below 2^15)
    paintBall(t, cx, cy, cz, s, Window{{-kAll, -kAll, -kAll}, {kAll, kAll, kAll}}, paint);
  }
  // The same for the open voxels of the bricks that meet `window`: the walk leaves the blocks, nodes and bricks
  // outside it, so a ball whose open voxels the caller knows to lie in a window costs only the window's part of its
  // sphere.
  template <class Paint>
  void paintBall(int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, const Window& window, Paint&& paint) {
    if (walk_ == Simd::kAvx512) {
      open_voxels_avx512::paintBall(*this, t, cx, cy, cz, s, window, paint);
    } else if (walk_ == Simd::kAvx2) {
      open_voxels_avx2::paintBall(*this, t, cx, cy, cz, s, window, paint);
    } else {
      open_voxels_sse2::paintBall(*this, t, cx, cy, cz, s, window, paint);
    }
    if (2 * size_t(open_[size_t(t)]) < packed_[size_t(t)].size()) {
      repack(t, [&](size_t node_index, int j) { return packed_[size_t(t)][brickSlot(node_index, j)]; });
    }
  }
  // The walk paintBall takes: kSse2, kAvx2 or kAvx512.
  Simd walk() const { return walk_; }
  // How many times thread t's brick words have been packed (once when opened, then again each time half of them
  // have closed).
  int64_t packings(int t) const { return packings_[size_t(t)]; }

  bool anyOpen(int t) const { return open_[size_t(t)] > 0; }
  // The thread that owns block (kx, ky, kz) and every node, brick and voxel in it.
  int owner(int64_t, int64_t ky, int64_t kz) const { return layer_owner_[size_t(layers_in_y_ ? ky : kz)]; }

 private:
  template <class Window, class Paint>
  friend void open_voxels_sse2::paintBall(OpenVoxels&, int, int64_t, int64_t, int64_t, int64_t, const Window&, Paint&&);
  template <class Window, class Paint>
  friend VOX_WALK_AVX2_ATTRIBUTE void open_voxels_avx2::paintBall(OpenVoxels&, int, int64_t, int64_t, int64_t, int64_t,
                                                                  const Window&, Paint&&);
  template <class Window, class Paint>
  friend VOX_WALK_AVX512_ATTRIBUTE void open_voxels_avx512::paintBall(OpenVoxels&, int, int64_t, int64_t, int64_t,
                                                                      int64_t, const Window&, Paint&&);

  // Words are stored block by block: a block's 64 node words together, and a node's 64 brick words together (the
  // bricks of one node are what a ball's walk reads after testing the node, 512 bytes in a row).
  size_t blockIndex(int64_t kx, int64_t ky, int64_t kz) const { return size_t(kx + k_.nx * (ky + k_.ny * kz)); }
  size_t nodeIndex(int64_t nx, int64_t ny, int64_t nz) const {
    return blockIndex(nx >> 2, ny >> 2, nz >> 2) * 64 + size_t(bit(nx, ny, nz));
  }
  size_t brickIndex(int64_t bx, int64_t by, int64_t bz) const {
    return nodeIndex(bx >> 2, by >> 2, bz >> 2) * 64 + size_t(bit(bx, by, bz));
  }
  static int bit(int64_t x, int64_t y, int64_t z) { return int((x & 3) + 4 * (y & 3) + 16 * (z & 3)); }

  // Where a node's owner's packed array holds the words of its bricks: those of the bricks in `slots` (the open ones
  // when it was last packed, a superset of the open ones now) from `base` on, in bit order.
  // (Kept apart from the nodes' open-brick words, nodes_, which every node a ball meets reads: 8 bytes a node stay
  // in the caches better than 24.)
  struct Packing {  // (zeroed by HugeArray)
    uint64_t slots, base;
  };
  // Where brick j of a node lies in its owner's packed array.
  size_t brickSlot(size_t node_index, int j) const {
    const Packing& p = packing_[node_index];
    return p.base + size_t(std::popcount(p.slots & ((uint64_t(1) << j) - 1)));
  }
  // Packs thread t's open bricks again (word(node_index, j) gives brick j's word of a node) into a new array.
  template <class Word>
  void repack(int t, Word&& word) {
    size_t count = 0;
    const std::vector<uint64_t>& blocks = blocks_[size_t(t)];
    for (size_t b = 0; b < blocks.size(); ++b)
      for (uint64_t nb = blocks[b]; nb; nb &= nb - 1)
        count += size_t(std::popcount(nodes_[b * 64 + size_t(std::countr_zero(nb))]));
    HugeWords packed(count);
    size_t next = 0;
    for (size_t b = 0; b < blocks.size(); ++b)
      for (uint64_t nb = blocks[b]; nb; nb &= nb - 1) {
        const size_t node_index = b * 64 + size_t(std::countr_zero(nb));
        Packing& p = packing_[node_index];
        const size_t base = next;
        for (uint64_t bb = nodes_[node_index]; bb; bb &= bb - 1)
          packed[next++] = word(node_index, std::countr_zero(bb));
        p.slots = nodes_[node_index];
        p.base = base;
      }
    packed_[size_t(t)] = std::move(packed);
    ++packings_[size_t(t)];
  }

 public:  // (the walk's view of one axis, filled by the walk too: analysis/open_voxels_walk.inc)
  // One axis of a ball: for the blocks its box meets, the squared distance from the centre's coordinate c to each
  // block, node and brick along the axis (nearest voxel; farthest too for bricks), filled once per ball so that the
  // walk reads the four values of a cell as one vector. (A brick's voxels are worked out when it is tested: a table
  // of them cost more than the bricks a ball tests.)
  struct Reach {
    int64_t k0 = 0, k1 = -1;  // blocks k0..k1
    std::vector<int32_t> blocks, node_near, brick_near, brick_far;
    int64_t c_ = -1;  // what the values are for (with lo_ and hi_): the balls of one size come in Morton order,
                      // and consecutive ones often share a coordinate
    // The bricks' values to fill, brick_near[i0 + i] and brick_far[i0 + i] for i < bricks, the first brick's first
    // voxel at `first` from c: left to the walk (fillBricks in analysis/open_voxels_walk.inc), which fills them with
    // its own instructions, sixteen at a time with AVX-512, eight with AVX2.
    int32_t i0 = 0, bricks = 0, first = 0;
    // Returns false when the values are those of the last ball already. lo..hi: the voxels along the axis that the
    // walk visits (the ball's reach, within the box and the ball's window); blocks, nodes and bricks outside them are
    // given kFar, which no ball reaches.
    static constexpr int32_t kFar = int32_t(1) << 29;  // three of them still fit 32 bits
    // beyond every ball: a squared distance in a box is below kMaxDim^2
    static_assert(int64_t(VoxelGrid::kMaxDim) * VoxelGrid::kMaxDim < kFar);
    int64_t lo_ = 0, hi_ = -1;
    int32_t lo_rel = 0, hi_rel = -1;  // lo and hi from c, for fillBricks
    bool set(int64_t c, int64_t lo, int64_t hi) {
      if (c == c_ && lo == lo_ && hi == hi_) return false;
      c_ = c;
      lo_ = lo;
      hi_ = hi;
      k0 = lo >> 6;
      k1 = hi >> 6;
      const auto count = size_t(k1 - k0 + 1);
      blocks.resize(count);
      node_near.resize(count * 4);
      brick_near.resize(count * 16 + 16);  // room for a last vector of sixteen
      brick_far.resize(count * 16 + 16);
      // Only what the walk can read is filled: every block and node of the blocks lo..hi meet and the bricks of the
      // nodes lo..hi meet. 32-bit: coordinates are below 2^15.
      const auto c32 = int32_t(c), base = int32_t(k0 * 64), lo32 = int32_t(lo), hi32 = int32_t(hi);
      auto near = [c32, lo32, hi32](int32_t a, int32_t b) {
        if (b < lo32 || a > hi32) return kFar;
        const int32_t d = std::max({a - c32, c32 - b, 0});
        return d * d;
      };
      for (int32_t i = 0; i < int32_t(count); ++i) blocks[size_t(i)] = near(base + 64 * i, base + 64 * i + 63);
      for (int32_t i = 0; i < int32_t(count) * 4; ++i) node_near[size_t(i)] = near(base + 16 * i, base + 16 * i + 15);
      const int64_t b0 = (lo >> 4) * 4, b1 = (hi >> 4) * 4 + 3;
      i0 = int32_t(b0 - k0 * 16);
      bricks = int32_t(b1 - b0 + 1);
      first = base + 4 * i0 - c32;
      lo_rel = lo32 - c32;
      hi_rel = hi32 - c32;
      return true;
    }
    int64_t block(int64_t k) const { return blocks[size_t(k - k0)]; }
    const int32_t* nodeNear(int64_t node) const { return node_near.data() + (node - k0 * 4); }
    const int32_t* brickNear(int64_t brick) const { return brick_near.data() + (brick - k0 * 16); }
    const int32_t* brickFar(int64_t brick) const { return brick_far.data() + (brick - k0 * 16); }
  };

 private:
  Dims box_, b_, n_, k_;  // voxels, bricks, nodes, blocks
  bool layers_in_y_;
  Simd walk_;
  std::vector<int> layer_owner_;  // by layer of blocks: its index modulo the threads (no division in the walk)
  HugeWords nodes_;               // a node's open bricks: bit j for brick j
  HugeArray<Packing> packing_;
  std::vector<HugeWords> packed_;              // per thread: the words of its open bricks (and of some closed ones)
  std::vector<std::vector<uint64_t>> blocks_;  // per thread
  std::vector<int64_t> open_;                  // open bricks per thread
  std::vector<int64_t> packings_;              // per thread
  struct alignas(64) ThreadReach {
    std::array<Reach, 3> axis;
  };
  std::vector<ThreadReach> reach_;  // per thread, each on its own cache lines

  static Simd pickWalk(Simd asked) {
    if ((asked == Simd::kAuto || asked == Simd::kAvx512) && avx512Available()) return Simd::kAvx512;
    if (asked != Simd::kSse2 && avx2Available()) return Simd::kAvx2;
    return Simd::kSse2;
  }
};

template <class Filled>
OpenVoxels::OpenVoxels(Dims box, int threads, Filled&& filled, Simd simd)
    : box_(box),
      b_{(box.nx + 3) / 4, (box.ny + 3) / 4, (box.nz + 3) / 4},
      n_{(b_.nx + 3) / 4, (b_.ny + 3) / 4, (b_.nz + 3) / 4},
      k_{(n_.nx + 3) / 4, (n_.ny + 3) / 4, (n_.nz + 3) / 4},
      layers_in_y_(k_.ny > k_.nz),
      walk_(pickWalk(simd)),
      layer_owner_(size_t(layers_in_y_ ? k_.ny : k_.nz)),
      nodes_(size_t(k_.count()) * 64),
      packing_(size_t(k_.count()) * 64),
      blocks_(size_t(threads), std::vector<uint64_t>(size_t(k_.count()), 0)),
      open_(size_t(threads), 0),
      packings_(size_t(threads), 0),
      reach_(size_t(threads)) {
  for (size_t k = 0; k < layer_owner_.size(); ++k) layer_owner_[k] = int(k % size_t(threads));
  for (int t = 0; t < threads; ++t) packed_.emplace_back(0);
  HugeWords bricks(size_t(k_.count()) * 64 * 64);  // every brick's word, by brickIndex, until packed
  parallelChunks(0, b_.nz, 1, threadsFor(box.count() / 4), [&](int, int64_t bz0, int64_t bz1) {
    for (int64_t z = bz0 * 4; z < std::min<int64_t>(box.nz, bz1 * 4); ++z)
      for (int64_t y = 0; y < box.ny; ++y)
        for (int64_t x = 0; x < box.nx; ++x)
          if (filled(x, y, z)) bricks[brickIndex(x >> 2, y >> 2, z >> 2)] |= uint64_t(1) << bit(x, y, z);
  });
  for (int64_t bz = 0; bz < b_.nz; ++bz)
    for (int64_t by = 0; by < b_.ny; ++by)
      for (int64_t bx = 0; bx < b_.nx; ++bx) {
        if (!bricks[brickIndex(bx, by, bz)]) continue;
        const int t = owner(bx >> 4, by >> 4, bz >> 4);
        ++open_[size_t(t)];
        nodes_[nodeIndex(bx >> 2, by >> 2, bz >> 2)] |= uint64_t(1) << bit(bx, by, bz);
        blocks_[size_t(t)][blockIndex(bx >> 4, by >> 4, bz >> 4)] |= uint64_t(1) << bit(bx >> 2, by >> 2, bz >> 2);
      }
  parallelChunks(0, threads, 1, threadsFor(box.count() / 4), [&](int, int64_t t0, int64_t t1) {
    for (int64_t t = t0; t < t1; ++t)
      repack(int(t), [&](size_t node_index, int j) { return bricks[node_index * 64 + size_t(j)]; });
  });
}

namespace open_voxels_sse2 {
#define VOX_WALK_AVX512 0
#define VOX_WALK_AVX2 0
#define VOX_WALK_TARGET
#include "analysis/open_voxels_walk.inc"  // IWYU pragma: keep
#undef VOX_WALK_TARGET
#undef VOX_WALK_AVX2
#undef VOX_WALK_AVX512
}  // namespace open_voxels_sse2

#if VOX_OPEN_VOXELS_X86
namespace open_voxels_avx2 {
#define VOX_WALK_AVX512 0
#define VOX_WALK_AVX2 1
#define VOX_WALK_TARGET VOX_WALK_AVX2_ATTRIBUTE
#include "analysis/open_voxels_walk.inc"  // IWYU pragma: keep
#undef VOX_WALK_TARGET
#undef VOX_WALK_AVX2
#undef VOX_WALK_AVX512
}  // namespace open_voxels_avx2

namespace open_voxels_avx512 {
#define VOX_WALK_AVX512 1
#define VOX_WALK_AVX2 0
#define VOX_WALK_TARGET VOX_WALK_AVX512_ATTRIBUTE
#include "analysis/open_voxels_walk.inc"  // IWYU pragma: keep
#undef VOX_WALK_TARGET
#undef VOX_WALK_AVX2
#undef VOX_WALK_AVX512
}  // namespace open_voxels_avx512
#else
// never taken: avx2Available() and avx512Available() are false
namespace open_voxels_avx2 {
template <class Window, class Paint>
void paintBall(OpenVoxels& o, int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, const Window& w, Paint&& paint) {
  open_voxels_sse2::paintBall(o, t, cx, cy, cz, s, w, paint);
}
}  // namespace open_voxels_avx2
namespace open_voxels_avx512 {
template <class Window, class Paint>
void paintBall(OpenVoxels& o, int t, int64_t cx, int64_t cy, int64_t cz, int64_t s, const Window& w, Paint&& paint) {
  open_voxels_sse2::paintBall(o, t, cx, cy, cz, s, w, paint);
}
}  // namespace open_voxels_avx512
#endif

}  // namespace vox::analysis_detail
