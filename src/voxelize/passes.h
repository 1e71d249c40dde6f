#pragma once
// What the parts of the solid voxelizer share (internal to the voxelize module): the progress gate and the parallel
// row runners of every pass, the word operations that turn toggles into parities, and the steps that voxelizeSolid
// (voxelize.cpp, which also explains how they fit together) strings together:
//  - plan.cpp: the mode, the memory estimate and limit (planVoxelization, resolveAutoMode, fill mode names);
//  - fill.cpp: parity and nonzero mode, one pass of rays along X;
//  - vote.cpp: vote mode, the parity along X, Y and Z and the per-voxel majority;
//  - strays.cpp: the optional stray-voxel clean-up (thesis 4.3.3).
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "vox/core/grid_placement.h"
#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/voxelize/stream.h"
#include "vox/voxelize/voxelize.h"
#include "voxelize/ray_caster.h"

namespace vox::voxelize_detail {

// --- Planning (plan.cpp)

// "1 boundary edge", "3 boundary edges".
std::string plural(int64_t n, const char* word);

// Bytes of the results alive at the peak: the grid, and in vote mode the disputed voxels, at most a grid's words and a
// word per row (the parities along X and Y only ever exist one layer at a time, along Z as toggle lists).
uint64_t estimateResultBytes(const Dims& dims, FillMode m);

// Sets result.mode_used and result.mode_reason for the requested mode (kAuto: resolveAutoMode on `topology`, which
// must then be given), and warns in result.warnings when a mode other than vote is requested for a mesh `topology`
// says is not watertight. `name` names the mesh in the warning.
void chooseMode(FillMode requested, const MeshTopology* topology, const std::string& name, VoxelizeResult& result);

// Fails with kLimit, saying what the grid of `plan` would take in `mode` and what to do instead, when that is more
// than the plan's memory limit.
Status checkMemoryLimit(const VoxelizePlan& plan, const VoxelizeParams& params, FillMode mode);

// --- Checks before voxelizing (voxelize.cpp)

// Fails for a mesh that cannot be voxelized: no triangles, or more than the ray casters can index.
Status checkMesh(const TriangleMesh& mesh, const std::string& name);
// Warns about the degenerate triangles of `mesh` (counted by `topology` when given).
void warnAboutDegenerate(const TriangleMesh& mesh, const MeshTopology* topology, std::vector<std::string>& warnings);

// --- Progress and parallel rows (shared by the passes)

// Serialises progress callbacks from the workers and rate-limits them to about kSteps calls in total.
class ProgressGate {
 public:
  ProgressGate(const ProgressFn& fn, int64_t total) : fn_(fn), total_(std::max<int64_t>(total, 1)) {}

  // Records `n` more units done; calls the callback when another 1/kSteps is complete. Thread-safe.
  void advance(int64_t n) {
    const int64_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
    if (!fn_) return;
    const int64_t step = done * kSteps / total_;
    int64_t last = last_step_.load(std::memory_order_relaxed);
    while (step > last) {
      if (last_step_.compare_exchange_weak(last, step, std::memory_order_relaxed)) {
        report(double(done) / double(total_));
        return;
      }
    }
  }
  void finish() {
    if (fn_ && !cancelled()) report(1.0);
  }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

 private:
  static constexpr int64_t kSteps = 200;

  void report(double fraction) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (cancelled()) return;
    fraction = std::clamp(std::max(fraction, last_fraction_), 0.0, 1.0);  // monotone even when reports race
    last_fraction_ = fraction;
    if (!fn_(fraction)) cancelled_.store(true, std::memory_order_relaxed);
  }

  const ProgressFn& fn_;
  const int64_t total_;
  std::atomic<int64_t> done_{0};
  std::atomic<int64_t> last_step_{0};
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;
  double last_fraction_ = 0.0;
};

// Rows per slab of runSlabs: slabs start at multiples of it.
inline int32_t slabRows(int32_t rows, int threads) {
  threads = std::clamp(threads, 1, std::max(1, int(rows)));
  return std::max<int32_t>(1, rows / (threads * 8));
}

// Runs slab_fn(thread, row_begin, row_end) over slabs of consecutive rows on `threads` threads, handed out
// dynamically so uneven rows balance; about eight slabs per thread, enough to balance and few enough that setting up
// each slab's sweep stays cheap. slab_fn checks progress.cancelled() per row. Returns false when cancelled or out of
// memory (`out_of_memory` set).
template <class SlabFn>
bool runSlabs(int32_t rows, int threads, ProgressGate& progress, bool& out_of_memory, SlabFn&& slab_fn) {
  const int32_t slab = slabRows(rows, threads);
  threads = std::clamp(threads, 1, std::max(1, int(rows)));
  const int32_t slabs = (rows + slab - 1) / slab;
  std::atomic<int32_t> next{0};
  std::atomic<bool> failed{false};
  auto worker = [&](int t) {
    try {
      for (;;) {
        const int32_t s = next.fetch_add(1, std::memory_order_relaxed);
        if (s >= slabs || progress.cancelled() || failed.load(std::memory_order_relaxed)) return;
        slab_fn(t, s * slab, std::min(rows, s * slab + slab));
      }
    } catch (const std::bad_alloc&) {
      failed.store(true);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& th : pool) th.join();
  out_of_memory = failed.load();
  return !out_of_memory && !progress.cancelled();
}

// Runs row_fn(thread, row, crossings) for rows [row_begin, row_end) of the caster (all when row_end < 0), in
// parallel (runSlabs).
template <class RowFn>
bool castRows(const RayCaster& caster, int threads, ProgressGate& progress, bool& out_of_memory, RowFn&& row_fn,
              int32_t row_begin = 0, int32_t row_end = -1) {
  if (row_end < 0) row_end = caster.rows();
  return runSlabs(row_end - row_begin, threads, progress, out_of_memory, [&](int t, int32_t s0, int32_t s1) {
    const int32_t r0 = row_begin + s0, r1 = row_begin + s1;
    CrossingList crossings;
    RayCaster::RowSweep sweep(caster, r0, r1);
    for (int32_t r = r0; r < r1 && !progress.cancelled(); ++r) {
      crossings.clear();
      sweep.next(crossings);
      row_fn(t, r, crossings);
      progress.advance(1);
    }
  });
}

// --- Toggles to parities (shared by fill.cpp and vote.cpp)

// Bit i of the result is the XOR of bits 0..i of x.
inline uint64_t prefixXor(uint64_t x) {
  x ^= x << 1;
  x ^= x << 2;
  x ^= x << 4;
  x ^= x << 8;
  x ^= x << 16;
  x ^= x << 32;
  return x;
}

// One word of a parity along a row of toggles: bit i is the parity of the toggles up to bit i of this word, given
// `carry` (all ones where the parity before the word is odd), which it updates. Most words hold no toggle.
inline uint64_t parityWord(uint64_t toggles, uint64_t& carry) {
  if (toggles == 0) return carry;
  const uint64_t a = carry ^ prefixXor(toggles);
  carry = uint64_t(0) - (a >> 63);
  return a;
}

// Bits 0..nx - 1 of a padded row (bits 1..nx) in each of its wpr words.
inline std::vector<uint64_t> validRowBits(int64_t wpr, int64_t nx) {
  std::vector<uint64_t> valid(static_cast<size_t>(wpr), 0);
  for (int64_t w = 0; w < wpr; ++w) {
    for (int b = 0; b < 64; ++b) {
      const int64_t xp = w * 64 + b;
      if (xp >= 1 && xp <= nx) valid[size_t(w)] |= uint64_t(1) << b;
    }
  }
  return valid;
}

// --- The passes

// What every pass reads: the mesh, where its grid lies, the threads to use, and where to report progress and
// running out of memory (runSlabs).
struct PassInput {
  const TriangleMesh& mesh;
  const GridPlacement& placement;
  const GridFrame& frame;  // the result grid's frame
  int threads;
  ProgressGate& gate;
  bool& out_of_memory;
};

// Parity or nonzero mode (fill.cpp): rays along X, one row of rays per layer; sets result.grid and warns about rays
// with an odd number of crossings (and, nonzero, a nonzero total winding). Progress: one unit per layer. False when
// cancelled or out of memory.
bool fillAlongX(const PassInput& in, FillMode mode, VoxelizeResult& result);

// The pass of fillAlongX a range of Z layers at a time, so that a grid too large for memory can be made in slabs
// (stream.cpp): every layer gets exactly the voxels fillAlongX gives it, whatever the ranges. The ray caster is made
// once for the whole grid; the counts behind the warnings add up over the ranges filled.
// The warnings LayerFiller::warn gives for these counts (summed over fillers of the same grid), in `mode`
// (parity or nonzero).
void warnAboutRayCounts(const RayCounts& counts, FillMode mode, std::vector<std::string>& warnings);

class LayerFiller {
 public:
  LayerFiller(const PassInput& in, FillMode mode);
  ~LayerFiller();
  LayerFiller(const LayerFiller&) = delete;
  LayerFiller& operator=(const LayerFiller&) = delete;
  // Fills layers [z0, z1) of the grid into `target` (dims nx, ny and any nz), layer z into target layer
  // z - z_offset. False when cancelled or out of memory.
  bool fill(int32_t z0, int32_t z1, VoxelGrid& target, int32_t z_offset);
  // The warnings about the rays of every layer filled so far.
  void warn(std::vector<std::string>& warnings) const;
  // What warn() counts: the rays of the layers filled so far that warn, and the rays of the whole grid.
  RayCounts counts() const;

 private:
  struct State;
  const PassInput& in_;
  std::unique_ptr<State> state_;
};

// Vote mode (vote.cpp): the parity along X, Y and Z and the majority per voxel; sets result.grid, result.disputed
// and result.disputed_count, and warns about odd rays and disputed voxels. Progress: 2 nz + ny units. False when
// cancelled or out of memory.
bool fillByVote(const PassInput& in, VoxelizeResult& result);

// Thesis 4.3.3 (strays.cpp): one simultaneous pass removing every filled voxel with at most two filled face neighbours
// (four or more free faces: isolated voxels, voxel lines and their ends), decided on the grid as it was before the
// pass. Returns how many it removed.
int64_t removeStrayVoxels(VoxelGrid& grid, int threads);

}  // namespace vox::voxelize_detail
