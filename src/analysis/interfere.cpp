// Interference between the parts of an assembly on one lattice. Pairs: the parts' filled boxes are swept along X
// (sorted by where they start; a box leaves the active set once the sweep passes its end), so only pairs whose boxes
// meet are compared, word by word over the rows of their common box. Overlap counts: a bit-sliced counter (ones,
// twos, threes) over the union of the boxes, a layer at a time, gives the voxels in two or more and in three or more
// parts, reading each part only over its own box.
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <numeric>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "analysis/progress_gate.h"
#include "vox/analysis/assembly.h"
#include "vox/core/bits.h"
#include "vox/core/parallel.h"

namespace vox {
namespace {

using analysis_detail::ProgressGate;

// The shares of the work: comparing the pairs, then their overlaps' thickness (the rest: counting the voxels in two
// or more parts, layer by layer).
constexpr double kPairShare = 0.5;
constexpr double kThicknessShare = 0.3;
// A pair's box up to this many voxels has its distance transform on one thread beside the others'; larger ones are
// taken one at a time with the transform's own threads (their memory is not needed at once).
constexpr int64_t kSmallOverlapBox = int64_t(1) << 22;

// Bit j of a bit's index within a word: sum over j of 2^j popcount(m & kIndexBit[j]) is the sum of m's bit indices.
constexpr std::array<uint64_t, 6> kIndexBit = {0xAAAAAAAAAAAAAAAAull, 0xCCCCCCCCCCCCCCCCull, 0xF0F0F0F0F0F0F0F0ull,
                                               0xFF00FF00FF00FF00ull, 0xFFFF0000FFFF0000ull, 0xFFFFFFFF00000000ull};

// Low `n` bits set (n in 1..64).
inline uint64_t lowBits(int64_t n) { return n >= 64 ? ~uint64_t(0) : (uint64_t(1) << n) - 1; }

// Shared voxels of parts a and b over `box` (their boxes' intersection): count, index sums, bounding box.
struct PairTally {
  int64_t voxels = 0;
  int64_t sum[3] = {0, 0, 0};
  glm::ivec3 lo{INT32_MAX}, hi{INT32_MIN};
};

PairTally tallyPair(const LatticeGrid& a, const LatticeGrid& b, const Box3i& box) {
  PairTally t;
  const int64_t nx = box.size().x, words = (nx + 63) / 64;
  const int64_t wa = a.grid.wordsPerRow(), wb = b.grid.wordsPerRow();
  const int64_t shift_a = int64_t(box.min.x) - a.first.x + 1, shift_b = int64_t(box.min.x) - b.first.x + 1;
  for (int32_t Z = box.min.z; Z < box.max.z; ++Z) {
    for (int32_t Y = box.min.y; Y < box.max.y; ++Y) {
      const uint64_t* ra = latticeRow(a, Y, Z);
      const uint64_t* rb = ra ? latticeRow(b, Y, Z) : nullptr;
      if (!rb) continue;
      int64_t row_count = 0;
      for (int64_t w = 0; w < words; ++w) {
        uint64_t m = rowBitsAt(ra, wa, shift_a + 64 * w) & rowBitsAt(rb, wb, shift_b + 64 * w);
        if (w == words - 1) m &= lowBits(nx - 64 * w);
        if (m == 0) continue;
        const int64_t pc = popcount64(m);
        const int64_t base = int64_t(box.min.x) + 64 * w;
        int64_t index_sum = 0;
        for (int j = 0; j < 6; ++j) index_sum += int64_t(popcount64(m & kIndexBit[size_t(j)])) << j;
        t.sum[0] += base * pc + index_sum;
        row_count += pc;
        t.lo.x = std::min(t.lo.x, int32_t(base + std::countr_zero(m)));
        t.hi.x = std::max(t.hi.x, int32_t(base + 63 - std::countl_zero(m)));
      }
      if (row_count == 0) continue;
      t.voxels += row_count;
      t.sum[1] += row_count * Y;
      t.sum[2] += row_count * Z;
      t.lo.y = std::min(t.lo.y, Y);
      t.hi.y = std::max(t.hi.y, Y);
      t.lo.z = std::min(t.lo.z, Z);
      t.hi.z = std::max(t.hi.z, Z);
    }
  }
  return t;
}

// Pairs (i < j) of non-empty boxes that meet: a sweep along X over the boxes sorted by start.
std::vector<std::pair<int32_t, int32_t>> candidatePairs(const std::vector<Box3i>& boxes) {
  std::vector<int32_t> order;
  for (int32_t i = 0; i < int32_t(boxes.size()); ++i) {
    if (!boxes[size_t(i)].empty()) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int32_t a, int32_t b) { return boxes[size_t(a)].min.x < boxes[size_t(b)].min.x; });
  std::vector<std::pair<int32_t, int32_t>> pairs;
  std::vector<int32_t> active;
  for (int32_t i : order) {
    const Box3i& bi = boxes[size_t(i)];
    std::erase_if(active, [&](int32_t j) { return boxes[size_t(j)].max.x <= bi.min.x; });
    for (int32_t j : active) {
      if (boxesMeet(bi, boxes[size_t(j)])) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
    active.push_back(i);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// Voxels in two or more and in three or more parts, over the union of the boxes, one layer at a time.
struct OverlapTally {
  int64_t twos = 0, threes = 0;
  glm::ivec3 lo{INT32_MAX}, hi{INT32_MIN};
};

OverlapTally tallyOverlaps(std::span<const LatticeGrid> parts, const std::vector<Box3i>& boxes, const Box3i& all,
                           ProgressGate& gate) {
  const int64_t words = (int64_t(all.size().x) + 63) / 64;
  const int threads = threadsFor(all.count() / 64);
  std::vector<OverlapTally> per_thread(size_t(std::max(1, threads)));
  std::atomic<int64_t> layers_done{0};
  const double layers = double(std::max(1, all.size().z));
  parallelChunks(all.min.z, all.max.z, 1, threads, [&](int t, int64_t z0, int64_t z1) {
    const size_t n = static_cast<size_t>(words);
    std::vector<uint64_t> ones(n), twos(n), threes(n);
    std::vector<size_t> in_layer;
    OverlapTally& tally = per_thread[size_t(t)];
    for (int32_t Z = int32_t(z0); Z < int32_t(z1); ++Z) {
      const double share = kPairShare + kThicknessShare;
      if (!gate.report(share + (1.0 - share) * double(layers_done.fetch_add(1)) / layers)) return;
      in_layer.clear();
      for (size_t p = 0; p < parts.size(); ++p) {
        if (!boxes[p].empty() && boxes[p].min.z <= Z && Z < boxes[p].max.z) in_layer.push_back(p);
      }
      if (in_layer.size() < 2) continue;
      for (int32_t Y = all.min.y; Y < all.max.y; ++Y) {
        int64_t w_lo = words, w_hi = 0;  // the words any part wrote this row
        for (size_t p : in_layer) {
          const Box3i& b = boxes[p];
          if (Y < b.min.y || Y >= b.max.y) continue;
          const uint64_t* row = latticeRow(parts[p], Y, Z);
          if (!row) continue;
          // The accumulators are zero outside [w_lo, w_hi), the words touched in this row so far.
          const int64_t first = (int64_t(b.min.x) - all.min.x) / 64, last = (int64_t(b.max.x) - 1 - all.min.x) / 64;
          w_lo = std::min(w_lo, first);
          w_hi = std::max(w_hi, last + 1);
          const int64_t wpr = parts[p].grid.wordsPerRow();
          const int64_t shift = int64_t(all.min.x) - parts[p].first.x + 1;
          for (int64_t w = first; w <= last; ++w) {
            const uint64_t x = rowBitsAt(row, wpr, shift + 64 * w);
            threes[size_t(w)] |= twos[size_t(w)] & x;
            twos[size_t(w)] |= ones[size_t(w)] & x;
            ones[size_t(w)] |= x;
          }
        }
        for (int64_t w = w_lo; w < w_hi; ++w) {
          tally.twos += popcount64(twos[size_t(w)]);
          const uint64_t m = threes[size_t(w)];
          ones[size_t(w)] = twos[size_t(w)] = threes[size_t(w)] = 0;
          if (m == 0) continue;
          tally.threes += popcount64(m);
          const int32_t base = int32_t(all.min.x + 64 * w);
          tally.lo = glm::min(tally.lo, glm::ivec3(base + std::countr_zero(m), Y, Z));
          tally.hi = glm::max(tally.hi, glm::ivec3(base + 63 - std::countl_zero(m), Y, Z));
        }
      }
    }
  });
  OverlapTally sum;
  for (const OverlapTally& t : per_thread) {
    sum.twos += t.twos;
    sum.threes += t.threes;
    sum.lo = glm::min(sum.lo, t.lo);
    sum.hi = glm::max(sum.hi, t.hi);
  }
  return sum;
}

// InterferencePair::thickness from the voxels the pair shares over their own box; without memory for the distance,
// the box's least side, which no overlap inside it exceeds.
void pairThickness(InterferencePair& p, std::span<const LatticeGrid> parts, const Lattice& lattice,
                   ProgressGate& gate) {
  const LatticeGrid both = booleanParts(reframe(parts[size_t(p.a)], p.box, lattice),
                                        reframe(parts[size_t(p.b)], p.box, lattice), PartOp::kIntersection, lattice);
  auto thickness = overlapThickness(both, lattice, [&gate](double) { return !gate.cancelled(); });
  if (gate.cancelled()) return;
  const glm::ivec3 side = p.box.size();
  p.thickness = thickness ? *thickness : double(std::min({side.x, side.y, side.z})) * lattice.voxel_size;
}

// InterferencePair::thickness of every pair: the small boxes a pair per thread, the large ones one at a time.
void overlapThicknesses(std::vector<InterferencePair>& pairs, std::span<const LatticeGrid> parts,
                        const Lattice& lattice, ProgressGate& gate) {
  std::vector<size_t> small, large;
  for (size_t k = 0; k < pairs.size(); ++k) (pairs[k].box.count() <= kSmallOverlapBox ? small : large).push_back(k);
  std::atomic<int64_t> done{0};
  const auto report = [&] {
    return gate.report(kPairShare + kThicknessShare * double(done.fetch_add(1) + 1) / double(pairs.size()));
  };
  parallelChunks(0, int64_t(small.size()), 1, threadsFor(int64_t(small.size()) << 16),
                 [&](int, int64_t k0, int64_t k1) {
                   for (int64_t k = k0; k < k1 && !gate.cancelled(); ++k) {
                     pairThickness(pairs[small[size_t(k)]], parts, lattice, gate);
                     report();
                   }
                 });
  for (size_t k = 0; k < large.size() && !gate.cancelled(); ++k) {
    pairThickness(pairs[large[k]], parts, lattice, gate);
    report();
  }
}

}  // namespace

Interference findInterference(std::span<const LatticeGrid> parts, const Lattice& lattice) {
  return std::move(findInterference(parts, lattice, ProgressFn{})).value();  // no callback: never cancelled
}

Result<Interference> findInterference(std::span<const LatticeGrid> parts, const Lattice& lattice,
                                      const ProgressFn& progress) {
  ProgressGate gate(progress);
  Interference out;
  std::vector<Box3i> boxes(parts.size());
  parallelChunks(0, int64_t(parts.size()), 1, threadsFor(int64_t(parts.size()) << 16),
                 [&](int, int64_t i0, int64_t i1) {
                   for (int64_t i = i0; i < i1; ++i) boxes[size_t(i)] = filledBox(parts[size_t(i)]);
                 });
  const auto candidates = candidatePairs(boxes);
  out.candidate_pairs = int64_t(candidates.size());
  std::vector<PairTally> tallies(candidates.size());
  int64_t work = 0;
  for (const auto& [i, j] : candidates) work += intersect(boxes[size_t(i)], boxes[size_t(j)]).count() / 64;
  std::atomic<int64_t> work_done{0};
  parallelChunks(0, int64_t(candidates.size()), 1, threadsFor(work), [&](int, int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1; ++k) {
      const auto [i, j] = candidates[size_t(k)];
      const Box3i common = intersect(boxes[size_t(i)], boxes[size_t(j)]);
      if (!gate.report(kPairShare * double(work_done.load()) / double(std::max<int64_t>(work, 1)))) return;
      tallies[size_t(k)] = tallyPair(parts[size_t(i)], parts[size_t(j)], common);
      work_done.fetch_add(common.count() / 64);
    }
  });
  if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "finding interference: cancelled");
  for (size_t k = 0; k < candidates.size(); ++k) {
    const PairTally& t = tallies[k];
    if (t.voxels == 0) continue;
    InterferencePair p;
    p.a = candidates[k].first;
    p.b = candidates[k].second;
    p.voxels = t.voxels;
    p.box = Box3i{t.lo, t.hi + glm::ivec3(1)};
    const glm::dvec3 mean = glm::dvec3(double(t.sum[0]), double(t.sum[1]), double(t.sum[2])) / double(t.voxels);
    p.centre = lattice.origin + (mean + glm::dvec3(0.5)) * lattice.voxel_size;
    out.pairs.push_back(p);
  }
  std::stable_sort(out.pairs.begin(), out.pairs.end(),
                   [](const InterferencePair& x, const InterferencePair& y) { return x.voxels > y.voxels; });
  overlapThicknesses(out.pairs, parts, lattice, gate);  // how thick each overlap is: contact or interference
  if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "finding interference: cancelled");
  Box3i all;
  for (const Box3i& b : boxes) all = unite(all, b);
  if (!all.empty() && !out.pairs.empty()) {
    const OverlapTally o = tallyOverlaps(parts, boxes, all, gate);
    if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "finding interference: cancelled");
    out.overlap_voxels = o.twos;
    out.multiple_overlap_voxels = o.threes;
    if (o.threes > 0) out.multiple_overlap_box = Box3i{o.lo, o.hi + glm::ivec3(1)};
  }
  gate.report(1.0);
  return out;
}

LatticeGrid sharedVoxels(const LatticeGrid& a, const LatticeGrid& b, const Lattice& lattice) {
  const Box3i common = intersect(a.box(), b.box());
  if (common.empty()) {
    LatticeGrid none;
    none.first = a.first;
    none.grid = VoxelGrid(Dims{1, 1, 1}, lattice.frameAt(a.first));
    return none;
  }
  return reframe(booleanParts(a, b, PartOp::kIntersection, lattice), common, lattice);
}

}  // namespace vox
