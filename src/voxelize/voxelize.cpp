// Solid voxelization: modes, parallel passes, memory limit, progress, warnings.
//
// Builds on:
//  - the thesis, section 4.3 (scan-line voxelization along X, layer by layer; 4.3.3: stray voxels with four or
//    more free faces are artefacts of thin sections and broken meshes);
//  - H. Edelsbrunner and E. P. Mücke, Simulation of Simplicity, ACM TOG 9(1), 1990 (ties; see ray_caster.cpp);
//  - F. S. Nooruddin and G. Turk, "Simplification and Repair of Polygonal Models Using Volumetric Techniques",
//    IEEE TVCG 9(2):191-205, 2003: parity counts along several directions and a per-voxel vote make a solid out of
//    a mesh with holes; voxmod uses the three axis directions and a majority of three.
//
// The crossings of each ray come from RayCaster as (first voxel past the crossing, sign) pairs, so filling is
// integer work, and it is done by toggles: a crossing toggles the bit of the first voxel past it, and a prefix XOR
// along the ray turns toggles into "inside", with word operations. Parity mode (rays along X) toggles at every
// crossing, in any order. Nonzero mode sorts each ray's crossings along it and toggles only where the winding
// number changes between zero and nonzero. Vote mode takes the parity along each axis: the prefix XOR runs within
// a row's words for rays along X, over the rows for rays along Y, over the layers for rays along Z (whose toggles
// are listed by layer and XORed into a running layer as the layer pass goes up). Rows of rays are independent, so
// the work is split over slabs of rows with std::thread; each thread writes only the Z layers of its own rows (rays
// along X and Y) or its own slab's toggle lists (rays along Z), so no two threads ever write the same word.
#include "vox/core/text.h"
#include "vox/voxelize/voxelize.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <new>
#include <thread>

#include "vox/core/bits.h"
#include "vox/core/surface.h"
#include "voxelize/ray_caster.h"

namespace vox {

using voxelize_detail::Crossing;
using voxelize_detail::CrossingList;
using voxelize_detail::RayCaster;

const char* fillModeName(FillMode m) {
  switch (m) {
    case FillMode::kAuto:
      return "auto";
    case FillMode::kParity:
      return "parity";
    case FillMode::kNonzero:
      return "nonzero";
    case FillMode::kVote:
      return "vote";
  }
  return "auto";
}

std::optional<FillMode> parseFillMode(const std::string& s) {
  for (FillMode m : {FillMode::kAuto, FillMode::kParity, FillMode::kNonzero, FillMode::kVote}) {
    if (s == fillModeName(m)) return m;
  }
  return std::nullopt;
}

namespace {

// Bytes of the results alive at the peak: the grid, and in vote mode the disputed voxels, at most a grid's words and a
// word per row (the parities along X and Y only ever exist one layer at a time, along Z as toggle lists).
bool mayVote(FillMode m) { return m == FillMode::kVote || m == FillMode::kAuto; }
uint64_t estimateResultBytes(const Dims& dims, FillMode m) {
  return estimateGridBytes(dims) + (mayVote(m) ? SparseVoxels::maxBytes(dims) : 0);
}

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
int32_t slabRows(int32_t rows, int threads) {
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

// Runs row_fn(thread, row, crossings) for every row of the caster, in parallel (runSlabs).
template <class RowFn>
bool castRows(const RayCaster& caster, int threads, ProgressGate& progress, bool& out_of_memory, RowFn&& row_fn) {
  return runSlabs(caster.rows(), threads, progress, out_of_memory, [&](int t, int32_t r0, int32_t r1) {
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

// Calls f(thread, i) for every i in [0, n) (layers, or slabs of them) on `threads` threads.
template <class F>
void forLayers(int32_t n, int threads, F&& f) {
  threads = std::clamp(threads, 1, std::max(1, int(n)));
  std::atomic<int32_t> next{0};
  auto worker = [&](int t) {
    for (int32_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < n;) f(t, i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& th : pool) th.join();
}

enum class Rule { kParity, kNonzero };

// Per-thread scratch and counters of a pass.
struct PassScratch {
  std::vector<int32_t> by_first;  // counting sort of crossings by first voxel
  std::vector<Crossing> along;    // crossings sorted by first voxel
  std::vector<int32_t> winding;   // by ray: the winding number so far (zero between rows)
  std::vector<int32_t> seen;      // by ray: crossings so far (zero between rows)
  int64_t odd_rays = 0;           // rays with an odd number of crossings
  int64_t unbalanced_rays = 0;    // rays whose signed crossings do not sum to zero
};

struct PassStats {
  int64_t odd_rays = 0, unbalanced_rays = 0, rays = 0;
};

PassStats sumStats(const std::vector<PassScratch>& scratch, const RayCaster& caster) {
  PassStats s;
  for (const auto& p : scratch) {
    s.odd_rays += p.odd_rays;
    s.unbalanced_rays += p.unbalanced_rays;
  }
  s.rays = int64_t(caster.rows()) * caster.raysPerRow();
  return s;
}

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

// Rays along X, row = layer z (parity and nonzero mode): marks, for each ray y, the voxels x where being inside
// changes, as toggled bits in `layer` (the grid's layout: bit x + 1 of row y + 1, x = the first voxel past the
// crossing, 0..nx), and flags the row in `marked`; the voxels inside a ray are then those with an odd number of
// toggles up to them, a prefix XOR along the row (fillToggledRows). Parity toggles at every crossing, in any order.
// Nonzero needs each ray's crossings in order along it: the winding number from -infinity changes at each, and a
// toggle goes where it changes between zero and nonzero. Toggles at the same voxel cancel, so crossings with the
// same ray and first voxel may come in either order.
void markRowAlongX(int32_t ny, int32_t nx, const CrossingList& crossings, Rule rule, PassScratch& s, uint64_t* layer,
                   uint8_t* marked, int64_t wpr) {
  if (crossings.empty()) return;
  // Toggles bit x + 1 of padded row y + 1 when `on`.
  auto toggle = [layer, wpr](int32_t y, int32_t x, bool on) {
    const int64_t xp = int64_t(x) + 1;
    layer[(int64_t(y) + 1) * wpr + (xp >> 6)] ^= uint64_t(on) << (xp & 63);
  };
  if (rule == Rule::kParity) {
    for (const Crossing& c : crossings) {
      toggle(c.ray(), c.first(), true);
      marked[c.ray() + 1] = 1;
    }
    return;  // odd rays: the parity past the row's last voxel (fillToggledRows)
  }
  // All rays at once, in order along them: one counting sort by first voxel, O(nx + ny + crossings) without a
  // data-dependent branch, then each crossing updates its ray's winding number, kept per ray. The order across rays
  // does not matter, and within a ray it is the order along it. (An insertion sort per ray mispredicts on nearly
  // every step where rays cross many bodies; the state per ray saves the second counting sort, by ray, that
  // walking each ray in turn would need.)
  const size_t count = crossings.size();
  if (s.winding.size() != size_t(ny)) {
    s.winding.assign(size_t(ny), 0);
    s.seen.assign(size_t(ny), 0);
  }
  // Two halves counted and scattered side by side, each with its own counts: consecutive crossings often share a
  // first voxel, and one array of counts would make each increment wait for the one before.
  const size_t bins = size_t(nx) + 1, half = count / 2;
  s.by_first.assign(2 * bins, 0);
  int32_t* const h0 = s.by_first.data();
  int32_t* const h1 = h0 + bins;
  const Crossing* const c0 = crossings.begin();
  const Crossing* const c1 = c0 + half;
  for (size_t i = 0; i < half; ++i) {
    ++h0[c0[i].first()];
    ++h1[c1[i].first()];
  }
  if (count % 2 != 0) ++h1[c1[half].first()];
  // h0: where the first half's crossings of each voxel go, h1 the second half's (after the first half's).
  int32_t at = 0;
  for (size_t i = 0; i < bins; ++i) {
    const int32_t n0 = h0[i], n1 = h1[i];
    h0[i] = at;
    h1[i] = at + n0;
    at += n0 + n1;
  }
  s.along.resize(count);
  Crossing* const along = s.along.data();
  for (size_t i = 0; i < half; ++i) {
    along[h0[c0[i].first()]++] = c0[i];
    along[h1[c1[i].first()]++] = c1[i];
  }
  if (count % 2 != 0) along[h1[c1[half].first()]++] = c1[half];
  // Winding number from -infinity: entering a solid (normal pointing to -u, sign -1) adds one. Branch-free: where
  // rays cross many bodies, whether the winding is zero changes unpredictably.
  int32_t* const winding = s.winding.data();
  int32_t* const seen = s.seen.data();
  for (const Crossing& c : s.along) {
    const int32_t j = c.ray();
    const int32_t before = winding[j], after = before - c.sign();
    winding[j] = after;
    ++seen[j];
    toggle(j, c.first(), (before != 0) != (after != 0));
  }
  // Each ray's totals, and its state set back to zero for the next row (branch-free: a ray without crossings adds
  // nothing, and its row stays unmarked).
  int64_t unbalanced = 0, odd = 0;
  for (int32_t j = 0; j < ny; ++j) {
    marked[j + 1] |= seen[j] != 0 ? 1 : 0;
    unbalanced += winding[j] != 0 ? 1 : 0;
    odd += seen[j] & 1;
    winding[j] = 0;
    seen[j] = 0;
  }
  s.unbalanced_rays += unbalanced;
  s.odd_rays += odd;
}

// Bits 0..nx - 1 of a padded row (bits 1..nx) in each of its wpr words.
std::vector<uint64_t> validRowBits(int64_t wpr, int64_t nx) {
  std::vector<uint64_t> valid(static_cast<size_t>(wpr), 0);
  for (int64_t w = 0; w < wpr; ++w) {
    for (int b = 0; b < 64; ++b) {
      const int64_t xp = w * 64 + b;
      if (xp >= 1 && xp <= nx) valid[size_t(w)] |= uint64_t(1) << b;
    }
  }
  return valid;
}

// Turns the toggles of each marked row of `layer` (grid layout, rows 1..ny of wpr words), in place, into the voxels
// with an odd number of toggles up to them (a prefix XOR along the row, carried from word to word), masked to the
// row's voxels. Leaves `marked` zeroed.
struct FilledRows {
  int64_t odd = 0;   // marked rows with an odd number of toggles in all
  bool any = false;  // some voxel is inside
};
FilledRows fillToggledRows(uint64_t* layer, uint8_t* marked, int32_t ny, int64_t wpr,
                           const std::vector<uint64_t>& valid) {
  const uint64_t* const valid_bits = valid.data();
  FilledRows f;
  uint64_t any = 0;
  for (int64_t yp = 1; yp <= ny; ++yp) {
    if (marked[yp] == 0) continue;
    marked[yp] = 0;
    uint64_t* const row = layer + yp * wpr;
    uint64_t carry = 0;
    for (int64_t w = 0; w < wpr; ++w) {
      row[w] = parityWord(row[w], carry) & valid_bits[w];
      any |= row[w];
    }
    f.odd += int64_t(carry & 1);
  }
  f.any = any != 0;
  return f;
}

// Per-thread scratch of vote mode's layer pass.
struct VoteScratch {
  std::vector<uint64_t> tx, ty;         // toggles along X and along Y, one layer in the grid's layout
  std::vector<uint8_t> x_rows, y_rows;  // which rows of tx and ty hold a toggle (by padded row)
  std::vector<uint64_t> y_run;          // the running Y parity, one row
  std::vector<uint64_t> d_row;          // the disputed voxels of the current row
  VoteScratch(int64_t wpl, int64_t wpr, int32_t ny)
      : tx(size_t(wpl), 0),
        ty(size_t(wpl), 0),
        x_rows(size_t(ny) + 2, 0),
        y_rows(size_t(ny) + 2, 0),
        y_run(size_t(wpr), 0),
        d_row(size_t(wpr), 0) {}
};

// Rays along X and Y in vote mode, row = layer z: each crossing toggles the bit of the first voxel past it in a
// zeroed scratch layer (the grid's layout: ny + 2 rows of wpr words, one padding bit or row on either side). The
// parity of a voxel along the ray is then the XOR of the toggles up to it: a prefix XOR within each row for rays
// along X, over the rows for rays along Y, which voteLayer computes as it reads the layer. A crossing past every
// centre toggles the padding bit (X: bit nx + 1 < wpr * 64) or row (Y: row ny + 1) just past the end, so the parity
// at the end of each ray says whether its count was odd.
void toggleAlongX(VoteScratch& s, int64_t wpr, const CrossingList& crossings) {
  for (const Crossing& c : crossings) {
    const int64_t xp = int64_t(c.first()) + 1, yp = int64_t(c.ray()) + 1;
    s.tx[size_t(yp * wpr + (xp >> 6))] ^= uint64_t(1) << (xp & 63);
    s.x_rows[size_t(yp)] = 1;
  }
}

void toggleAlongY(VoteScratch& s, int64_t wpr, const CrossingList& crossings) {
  for (const Crossing& c : crossings) {
    const int64_t xp = int64_t(c.ray()) + 1, yp = int64_t(c.first()) + 1;
    s.ty[size_t(yp * wpr + (xp >> 6))] ^= uint64_t(1) << (xp & 63);
    s.y_rows[size_t(yp)] = 1;
  }
}

struct VoteCounts {
  int64_t odd_x = 0, odd_y = 0;
};

// One layer of vote mode, in one pass over its words: s.tx and s.ty hold the layer's toggles along X and Y
// (toggleAlongX/Y), bz the parity along Z. Row by row, the X parity is the prefix XOR of tx's row (carried from
// word to word), the Y parity a running row that each row of ty is XORed into; the majority of the three goes to
// layer z of `grid` (allocated at its first nonzero word), the voxels where they differ to `disputed`, a row at a
// time.
// Rows where all three parities are zero are skipped. `valid` masks each word of a row to the voxels 0..nx - 1.
// Leaves the scratch zeroed for the next layer.
void voteLayer(int32_t z, int32_t ny, int64_t wpr, const std::vector<uint64_t>& valid, VoteScratch& s,
               const uint64_t* bz, VoxelGrid& grid, SparseVoxels::Chunk& disputed_rows, VoteCounts& counts) {
  uint64_t* c = nullptr;
  uint64_t* const d_row = s.d_row.data();
  uint64_t* const y_run = s.y_run.data();
  const uint64_t* const valid_bits = valid.data();
  uint8_t* const x_rows = s.x_rows.data();
  uint8_t* const y_rows = s.y_rows.data();
  uint64_t* const tx = s.tx.data();
  uint64_t* const ty = s.ty.data();
  std::fill(s.y_run.begin(), s.y_run.end(), 0);
  bool y_any = false;  // some word of y_run is nonzero
  int64_t odd_x = 0;
  for (int64_t yp = 1; yp <= ny; ++yp) {
    uint64_t* const tx_row = tx + yp * wpr;
    const uint64_t* z_row = bz + yp * wpr;
    if (y_rows[yp] != 0) {
      y_rows[yp] = 0;
      uint64_t* const ty_row = ty + yp * wpr;
      uint64_t any = 0;
      for (int64_t w = 0; w < wpr; ++w) {
        y_run[w] ^= ty_row[w];
        ty_row[w] = 0;
        any |= y_run[w];
      }
      y_any = any != 0;
    }
    const bool x_any = x_rows[yp] != 0;
    if (!x_any && !y_any) {
      uint64_t z_any = 0;
      for (int64_t w = 0; w < wpr; ++w) z_any |= z_row[w];
      if (z_any == 0) continue;  // all three parities are zero on this row
    }
    x_rows[yp] = 0;
    uint64_t carry = 0;                  // the X parity
    int64_t d_first = wpr, d_last = -1;  // words of the row holding a disputed voxel
    for (int64_t w = 0; w < wpr; ++w) {
      const uint64_t t = tx_row[w];
      if (t != 0) tx_row[w] = 0;  // leave the scratch zeroed, storing only where there was a toggle
      const uint64_t a = parityWord(t, carry) & valid_bits[w];
      const uint64_t b = y_run[w], zz = z_row[w];
      const uint64_t r = (a & b) | (zz & (a | b));
      if (r != 0) {
        if (!c) c = grid.mutableLayerWords(z);
        c[yp * wpr + w] = r;
      }
      const uint64_t d = (a ^ b) | (a ^ zz);
      d_row[w] = d;
      if (d != 0) {
        d_first = std::min(d_first, w);
        d_last = w;
      }
    }
    if (d_last >= 0) disputed_rows.addRow(int32_t(yp - 1), z, d_first, d_last - d_first + 1, d_row + d_first);
    odd_x += int64_t(carry & 1);
  }
  // Row ny + 1: the crossings past every centre along Y. The running row is then each ray's total parity.
  const int64_t past_row = int64_t(ny) + 1;
  uint64_t* past = s.ty.data() + past_row * wpr;
  int64_t odd_y = 0;
  for (int64_t w = 0; w < wpr; ++w) {
    odd_y += popcount64(y_run[w] ^ past[w]);
    past[w] = 0;
  }
  s.y_rows[size_t(past_row)] = 0;
  counts.odd_x += odd_x;
  counts.odd_y += odd_y;
}

// Rays along Z, row = y, rays step along x: each crossing toggles bit (x, y) of the parity of every layer from
// `first` up. The toggles are kept, not applied: each slab of rows of the Z pass lists them by layer `first`, as the
// bit's position in a layer ((y + 1) * wpr * 64 + x + 1, below 2^32 for any grid voxmod accepts), and the layer pass
// XORs them into a running parity layer as it goes up in z. So the Z parity never needs a grid of its own.
// Crossings past every centre go to layer nz: no layer uses them, but with them the running layer ends as each
// ray's total parity.
struct ZToggles {
  std::vector<uint32_t> bits;  // by layer: layer z's are bits[start[z]] .. bits[start[z + 1] - 1]
  std::vector<size_t> start;   // nz + 2 entries
};

// Lists the crossings of rows r0.. of the Z pass (all of them in `crossings`, row r's from row_start[r - r0]) by
// layer: a counting sort on the layer.
void listTogglesAlongZ(int32_t r0, const CrossingList& crossings, const std::vector<size_t>& row_start, int32_t nz,
                       int64_t wpr, ZToggles& out) {
  out.start.assign(size_t(nz) + 2, 0);
  for (const Crossing& c : crossings) ++out.start[size_t(c.first()) + 1];
  for (int32_t z = 0; z <= nz; ++z) out.start[size_t(z) + 1] += out.start[size_t(z)];
  out.bits.resize(crossings.size());
  std::vector<size_t> pos(out.start.begin(), out.start.end() - 1);
  for (size_t r = 0; r + 1 < row_start.size(); ++r) {
    const int64_t row_bit = (int64_t(r0) + int64_t(r) + 1) * wpr * 64 + 1;
    for (size_t i = row_start[r]; i < row_start[r + 1]; ++i) {
      const Crossing c = crossings[i];
      out.bits[pos[size_t(c.first())]++] = uint32_t(row_bit + c.ray());
    }
  }
}

// XORs layer z's toggles of every slab into `layer`.
void applyTogglesAlongZ(const std::vector<ZToggles>& toggles, int32_t z, uint64_t* layer) {
  for (const ZToggles& t : toggles) {
    for (size_t i = t.start[size_t(z)]; i < t.start[size_t(z) + 1]; ++i) {
      const uint32_t bit = t.bits[i];
      layer[bit >> 6] ^= uint64_t(1) << (bit & 63);
    }
  }
}

// Thesis 4.3.3: one simultaneous pass removing every filled voxel with at most two filled face neighbours (four or
// more free faces: isolated voxels, voxel lines and their ends), decided on the grid as it was before the pass.
int64_t removeStrayVoxels(VoxelGrid& grid, int threads) {
  const VoxelGrid before = grid;  // copy-on-write snapshot: shares the layers until one is written
  std::vector<int64_t> removed(size_t(std::max(threads, 1)), 0);
  forLayers(grid.nz(), threads, [&](int t, int32_t z) {
    if (!before.layerAllocated(z)) return;
    RowNeighbours n;
    n.resize(size_t(before.wordsPerRow()));
    for (int32_t y = 0; y < before.ny(); ++y) {
      rowNeighbourMasks(before, y, z, n);
      uint64_t* row = nullptr;
      for (size_t w = 0; w < n.self.size(); ++w) {
        if (n.self[w] == 0) continue;
        // Bit-sliced count of filled neighbours (s2 s1 s0 in binary), then "count <= 2".
        uint64_t s0 = 0, s1 = 0, s2 = 0;
        for (uint64_t m : {n.xm[w], n.xp[w], n.ym[w], n.yp[w], n.zm[w], n.zp[w]}) {
          const uint64_t c0 = s0 & m;
          s0 ^= m;
          const uint64_t c1 = s1 & c0;
          s1 ^= c0;
          s2 |= c1;
        }
        const uint64_t stray = n.self[w] & ~s2 & ~(s1 & s0);
        if (stray == 0) continue;
        if (!row) row = grid.mutableRowWords(y, z);
        row[w] &= ~stray;
        removed[size_t(t)] += popcount64(stray);
      }
    }
  });
  grid.releaseEmptyLayers();
  int64_t total = 0;
  for (int64_t r : removed) total += r;
  return total;
}

std::string plural(int64_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

}  // namespace

Result<VoxelizePlan> planVoxelization(const Box3d& bounds, const VoxelizeParams& params) {
  if (!(params.voxel_size >= 0.0) || !std::isfinite(params.voxel_size)) {
    return makeError(ErrorCode::kInvalidArgument, "voxel size must be a positive number (or 0 to use the resolution)");
  }
  if (params.threads < 0) {
    return makeError(ErrorCode::kInvalidArgument,
                     "threads must be 0 (all hardware threads) or positive, not " + std::to_string(params.threads));
  }
  auto placement = params.voxel_size > 0.0 ? placeGridByVoxelSize(bounds, params.voxel_size)
                                           : placeGridByResolution(bounds, params.resolution);
  if (!placement) return placement.error();
  VoxelizePlan plan;
  plan.placement = std::move(placement).value();
  plan.bytes = estimateResultBytes(plan.placement.dims, params.mode);
  if (params.memory_limit_bytes > 0) {
    plan.limit_bytes = params.memory_limit_bytes;
  } else {
    const uint64_t physical = physicalMemoryBytes();
    plan.limit_bytes = physical > 0 ? physical / 5 * 4 : UINT64_MAX;
  }
  return plan;
}

ModeChoice resolveAutoMode(const MeshTopology& topology) {
  const std::string edges_text =
      plural(topology.boundary_edges, "boundary edge") + ", " + plural(topology.nonmanifold_edges, "non-manifold edge");
  if (topology.watertight()) return {FillMode::kNonzero, "mesh is closed (" + edges_text + "): using nonzero"};
  if (topology.closedOriented()) {
    // Closed bodies that touch or overlap (an assembly): every edge is used as often in each direction, so the
    // winding number is exact everywhere and nonzero gives the union, where vote would equal parity and leave the
    // overlaps empty.
    return {FillMode::kNonzero, "mesh is not manifold (" + edges_text +
                                    ") but closed: every edge is used equally often in both directions (touching or "
                                    "overlapping bodies): using nonzero, which fills their union"};
  }
  if (topology.closes_when_noise_welded) {
    // Open only by exporter noise (corners that should coincide differ by ~1e-17): closed once vertices within 1e-9
    // of the bounding-box diagonal are welded. A ray slips through such a seam only if it passes within that
    // distance of it, so nonzero gives the closed solid (on featuretype it matches the reference exactly), where
    // vote would cost three ray passes for nothing.
    return {FillMode::kNonzero, "mesh is not watertight by exact vertex equality (" + edges_text +
                                    ") but closes when vertices within 1e-9 of its size are welded: using nonzero"};
  }
  return {FillMode::kVote, "mesh is not watertight (" + edges_text + "): using vote"};
}

Result<VoxelizeResult> voxelizeSolid(const TriangleMesh& mesh, const VoxelizeParams& params, const ProgressFn& progress,
                                     const MeshTopology* topology) {
  const std::string name = mesh.name.empty() ? std::string("the mesh") : mesh.name;
  if (mesh.triangles.empty()) return makeError(ErrorCode::kParse, name + " has no triangles");
  if (mesh.triangles.size() > UINT32_MAX) {  // the ray casters index triangles with 32 bits
    return makeError(ErrorCode::kLimit, name + " has " + std::to_string(mesh.triangles.size()) +
                                            " triangles; at most 4294967295 can be voxelized");
  }
  auto plan_or = planVoxelization(mesh.bounds(), params);
  if (!plan_or) return plan_or.error();
  VoxelizePlan plan = std::move(plan_or).value();
  const Dims dims = plan.placement.dims;

  VoxelizeResult result;
  // Resolve the mode. Topology is only needed for auto (or given anyway, for the warning).
  MeshTopology computed;
  if (!topology && params.mode == FillMode::kAuto) {
    computed = analyzeTopology(mesh);
    topology = &computed;
  }
  const std::string edges_text = topology ? plural(topology->boundary_edges, "boundary edge") + ", " +
                                                plural(topology->nonmanifold_edges, "non-manifold edge")
                                          : std::string();
  switch (params.mode) {
    case FillMode::kAuto: {
      ModeChoice choice = resolveAutoMode(*topology);
      result.mode_used = choice.mode;
      result.mode_reason = std::move(choice.reason);
      break;
    }
    case FillMode::kParity:
    case FillMode::kNonzero:
    case FillMode::kVote:
      result.mode_used = params.mode;
      result.mode_reason = std::string("requested: ") + fillModeName(params.mode);
      if (topology && !topology->watertight() && params.mode != FillMode::kVote) {
        // Say what can go wrong with this kind of defect: holes break single-axis rays, while touching or
        // overlapping bodies (non-manifold edges only) make the rules differ.
        std::string consequence;
        if (topology->boundary_edges > 0) {
          consequence =
              " mode fills or drops whole runs of a row where a ray passes through a hole (vote mode is "
              "meant for open meshes)";
        } else {
          consequence =
              " mode: touching or overlapping bodies (parity leaves overlaps empty, nonzero fills the "
              "union)";
        }
        result.warnings.push_back(name + " is not watertight (" + edges_text + "); " + fillModeName(params.mode) +
                                  consequence);
      }
      break;
  }
  const bool vote = result.mode_used == FillMode::kVote;

  // Refuse before allocating anything large.
  const uint64_t need = estimateResultBytes(dims, result.mode_used);
  if (need > plan.limit_bytes) {
    std::string msg = "a " + dimsText(dims) + " grid (resolution " + std::to_string(plan.placement.resolution) +
                      ") needs about " + formatBytes(need);
    if (vote) {
      msg += " in vote mode (" + formatBytes(estimateGridBytes(dims)) + " for the voxels, up to " +
             formatBytes(SparseVoxels::maxBytes(dims)) + " for the disputed voxels)";
    }
    msg += ", more than the memory limit of " + formatBytes(plan.limit_bytes);
    msg += params.memory_limit_bytes > 0 ? " (as set)" : " (80% of physical memory)";
    msg += "; use a lower resolution";
    if (vote) msg += " or parity/nonzero mode on a closed mesh";
    return makeError(ErrorCode::kLimit, msg);
  }

  int64_t degenerate = 0;
  if (topology) {
    degenerate = topology->degenerate_triangles;
  } else {
    for (const Triangle& t : mesh.triangles) degenerate += isDegenerate(t) ? 1 : 0;
  }
  if (degenerate > 0) {
    result.warnings.push_back(plural(degenerate, "degenerate triangle") + " (zero area) ignored: they cross no ray");
  }

  const int threads = params.threads > 0 ? params.threads : std::max(1, int(std::thread::hardware_concurrency()));
  GridFrame frame = plan.placement.frame;
  frame.units = params.units;
  frame.source = mesh.name;

  const int64_t total_rows = vote ? int64_t(dims.nz) * 2 + dims.ny : int64_t(dims.nz);
  ProgressGate gate(progress, total_rows);
  bool out_of_memory = false;
  auto failure = [&]() -> Error {
    if (out_of_memory) {
      return makeError(ErrorCode::kLimit,
                       "ran out of memory while voxelizing " + name + " on a " + dimsText(dims) + " grid");
    }
    return makeError(ErrorCode::kCancelled, "voxelization cancelled");
  };

  try {
    if (!vote) {
      const Rule rule = result.mode_used == FillMode::kParity ? Rule::kParity : Rule::kNonzero;
      VoxelGrid grid(dims, frame);
      const RayCaster caster(mesh, plan.placement, voxelize_detail::kRaysAlongX, threads);
      std::vector<PassScratch> scratch(static_cast<size_t>(threads));
      const int64_t wpr = grid.wordsPerRow();
      // Each ray's toggles go straight into the grid's layer (allocated for a row of rays with any crossing, given
      // back if no voxel ends up inside); then each marked row becomes its inside voxels by a prefix XOR in place. Only
      // rows with a toggle are touched, so a page no such row lies in is never faulted in (VoxelGrid's layers start as
      // untouched zero memory), and nothing is copied. (A toggle is a read-modify-write of the word: on
      // cycloidal_assembly at R = 1000 it takes as many page faults as storing finished rows did, so a fresh page is
      // not faulted twice.)
      std::vector<std::vector<uint8_t>> marked(static_cast<size_t>(threads));  // rows holding a toggle (by padded row)
      const std::vector<uint64_t> valid = validRowBits(wpr, dims.nx);
      const bool ok = castRows(caster, threads, gate, out_of_memory, [&](int t, int32_t z, const auto& crossings) {
        if (crossings.empty()) return;
        std::vector<uint8_t>& m = marked[size_t(t)];
        if (m.empty()) m.assign(size_t(dims.ny) + 2, 0);
        uint64_t* const layer = grid.mutableLayerWords(z);  // only this thread writes layer z
        PassScratch& ps = scratch[size_t(t)];
        markRowAlongX(dims.ny, dims.nx, crossings, rule, ps, layer, m.data(), wpr);
        const FilledRows filled = fillToggledRows(layer, m.data(), dims.ny, wpr, valid);
        // Crossings that leave no voxel inside (all past every centre, or a wall between two centres): the layer goes
        // back to the shared zero layer, as if never allocated.
        if (!filled.any) grid.releaseLayer(z);
        if (rule == Rule::kParity) ps.odd_rays += filled.odd;
      });
      if (!ok) return failure();
      const PassStats stats = sumStats(scratch, caster);
      if (stats.odd_rays > 0) {
        result.warnings.push_back("odd number of crossings on " + std::to_string(stats.odd_rays) + " of " +
                                  std::to_string(stats.rays) +
                                  " rays along X: the mesh is not closed along them (a closed mesh gives 0)");
      }
      if (rule == Rule::kNonzero && stats.unbalanced_rays > 0) {
        result.warnings.push_back("nonzero total winding on " + std::to_string(stats.unbalanced_rays) + " of " +
                                  std::to_string(stats.rays) +
                                  " rays along X: the mesh is open or inconsistently oriented along them");
      }
      result.grid = std::move(grid);
    } else {
      // Rays along Z first: their crossings become per-layer toggle lists (listTogglesAlongZ). Then, layer by
      // layer going up, the toggles along X and along Y into two cache-sized scratch layers and the parity along Z in
      // a running layer (the toggles of this layer XORed in); one pass over the layer's words (voteLayer) turns the
      // toggles into parities and writes the per-word majority of the three into the grid (layers allocated where a
      // word is filled), and the rows of voxels where the axes disagree into the slab's chunk of the disputed set (a
      // SparseVoxels: they are usually few words of many rows, which as a grid would fault in a page every few words).
      // Each slab of layers starts from a snapshot of the running Z parity at its first layer. Peak: the grid, the
      // disputed rows, 4 bytes per crossing along Z (8 while a slab's are being listed), and a layer per slab.
      VoxelGrid grid(dims, frame);
      std::vector<int64_t> odd(3, 0);
      const int64_t wpr = grid.wordsPerRow(), wpl = grid.wordsPerLayer();
      std::vector<ZToggles> toggles;  // per slab of rows of the Z pass
      {
        const RayCaster caster(mesh, plan.placement, voxelize_detail::kRaysAlongZ, threads);
        const int32_t rows = caster.rows(), row_slab = slabRows(rows, threads);
        toggles.resize(size_t((rows + row_slab - 1) / row_slab));
        const bool ok = runSlabs(rows, threads, gate, out_of_memory, [&](int, int32_t r0, int32_t r1) {
          CrossingList crossings;
          std::vector<size_t> row_start{0};
          RayCaster::RowSweep sweep(caster, r0, r1);
          for (int32_t r = r0; r < r1 && !gate.cancelled(); ++r) {
            sweep.next(crossings);  // appends
            row_start.push_back(crossings.size());
            gate.advance(1);
          }
          listTogglesAlongZ(r0, crossings, row_start, dims.nz, wpr, toggles[size_t(r0 / row_slab)]);
        });
        if (!ok) return failure();
      }
      // The running Z parity at the first layer of every slab of the layer pass: each slab's toggles XORed
      // together (in parallel), then accumulated over the slabs.
      const int32_t slab = slabRows(dims.nz, threads);
      const int32_t slabs = (dims.nz + slab - 1) / slab;
      std::vector<std::vector<uint64_t>> snapshots(static_cast<size_t>(slabs));
      {
        std::vector<uint64_t> last(static_cast<size_t>(wpl), 0);  // the last slab's toggles and those past it
        forLayers(slabs, threads, [&](int, int32_t k) {
          std::vector<uint64_t>& sum = k + 1 < slabs ? snapshots[size_t(k) + 1] : last;
          sum.assign(size_t(wpl), 0);
          for (int32_t z = k * slab; z < std::min(dims.nz, (k + 1) * slab); ++z) {
            applyTogglesAlongZ(toggles, z, sum.data());
          }
          if (k + 1 == slabs) applyTogglesAlongZ(toggles, dims.nz, sum.data());
        });
        snapshots[0].assign(size_t(wpl), 0);
        for (int32_t k = 2; k < slabs; ++k) {
          for (int64_t w = 0; w < wpl; ++w) snapshots[size_t(k)][size_t(w)] ^= snapshots[size_t(k) - 1][size_t(w)];
        }
        // The running layer past the last crossings holds each ray's total parity.
        for (int64_t w = 0; w < wpl; ++w)
          odd[2] += popcount64(snapshots[size_t(slabs) - 1][size_t(w)] ^ last[size_t(w)]);
      }
      std::vector<VoteCounts> counts(static_cast<size_t>(threads));
      std::vector<SparseVoxels::Chunk> disputed(static_cast<size_t>(slabs));  // per slab of the layer pass
      {
        const RayCaster along_x(mesh, plan.placement, voxelize_detail::kRaysAlongX, threads);
        const RayCaster along_y(mesh, plan.placement, voxelize_detail::kRaysAlongY, threads);
        const std::vector<uint64_t> valid = validRowBits(wpr, dims.nx);
        const bool ok = runSlabs(dims.nz, threads, gate, out_of_memory, [&](int t, int32_t z0, int32_t z1) {
          CrossingList cx, cy;
          VoteScratch scratch(wpl, wpr, dims.ny);
          std::vector<uint64_t> bz = std::move(snapshots[size_t(z0 / slab)]);
          RayCaster::RowSweep sweep_x(along_x, z0, z1), sweep_y(along_y, z0, z1);
          for (int32_t z = z0; z < z1 && !gate.cancelled(); ++z) {
            cx.clear();
            cy.clear();
            sweep_x.next(cx);
            sweep_y.next(cy);
            toggleAlongX(scratch, wpr, cx);
            toggleAlongY(scratch, wpr, cy);
            applyTogglesAlongZ(toggles, z, bz.data());
            voteLayer(z, dims.ny, wpr, valid, scratch, bz.data(), grid, disputed[size_t(z0 / slab)], counts[size_t(t)]);
            gate.advance(2);  // two rows of rays (X and Y) per layer
          }
        });
        if (!ok) return failure();
      }
      result.disputed = SparseVoxels(dims, frame, std::move(disputed));
      result.disputed_count = result.disputed->count();
      for (const VoteCounts& c : counts) {
        odd[0] += c.odd_x;
        odd[1] += c.odd_y;
      }
      const char* axes[3] = {"X", "Y", "Z"};
      std::string odd_text;
      for (int a = 0; a < 3; ++a) {
        if (odd[size_t(a)] == 0) continue;
        if (!odd_text.empty()) odd_text += ", ";
        odd_text += std::to_string(odd[size_t(a)]) + " along " + axes[a];
      }
      if (!odd_text.empty()) {
        result.warnings.push_back("rays with an odd number of crossings (the mesh is open along them): " + odd_text);
      }
      if (result.disputed_count > 0) {
        result.warnings.push_back("vote: the X, Y and Z parity grids disagree on " +
                                  plural(result.disputed_count, "voxel") +
                                  " (filled by majority; see the disputed mask)");
      }
      result.grid = std::move(grid);
    }
    if (params.remove_strays) result.strays_removed = removeStrayVoxels(result.grid, threads);
  } catch (const std::bad_alloc&) {
    out_of_memory = true;
    return failure();
  }
  gate.finish();
  if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "voxelization cancelled");
  return result;
}

}  // namespace vox
