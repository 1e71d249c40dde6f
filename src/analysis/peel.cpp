// Skin removal (thesis 5.2.2, 6.4): every filled voxel with at least one empty face neighbour (6-connectivity) is
// reset at once, decided on the configuration before the layer. The thesis keeps the surface indices of two
// successive Z layers in a temporary array so that resetting never disturbs a neighbour still to be examined; here
// the same guarantee comes from writing the peeled layer into a second grid: next = grid & ~surface(grid), one word
// operation per 64 voxels (thesis 5.1 neighbour masks, see layer_ops.h).
//
// Repeated peeling is an erosion by the 6-neighbourhood cross, so the depth of a voxel (the layer that removes it)
// is its L1 distance to the nearest empty voxel. Layer after layer the model only shrinks, so the engine keeps,
// per row, the span of words that may still hold voxels and works only there: a full peel of a solid costs about
// the sum of the remaining volumes / 64 words, not layers x grid size. Two grids are reused alternately, so a peel
// of hundreds of layers allocates no more than two grids (plus the depth bit planes).
//
// The depth map stores the binary digits of the depth as bit-plane grids (plane b holds bit b of every voxel's
// depth), ceil(log2(layers + 1)) grids instead of a number per voxel. "Still present after k layers" is depth > k,
// which a bit-sliced comparator evaluates with a handful of word operations per plane, so any layer can be shown
// at once without peeling again, and stepping back (undo) is free.
#include <algorithm>
#include <bit>
#include <climits>
#include <string>
#include <utility>

#include "analysis/layer_ops.h"
#include "vox/core/parallel.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

using analysis_detail::interiorWord;

struct RowSpan {  // words [w0, w1) of a row that may hold filled voxels; zero everywhere else
  uint16_t w0 = 0, w1 = 0;
};
struct LayerSpan {  // rows [y0, y1) of a layer that may hold filled voxels
  int32_t y0 = 0, y1 = 0;
  bool empty() const { return y0 >= y1; }
};

// Where a grid may hold voxels. Invariant: every word outside the spans is zero.
struct Extent {
  std::vector<RowSpan> rows;  // index z * ny + y
  std::vector<LayerSpan> layers;
};

Extent fullExtent(const VoxelGrid& g) {  // every row of every allocated layer
  Extent e;
  e.rows.assign(size_t(g.nz()) * size_t(g.ny()), RowSpan{});
  e.layers.assign(size_t(g.nz()), LayerSpan{});
  for (int32_t z = 0; z < g.nz(); ++z) {
    if (!g.layerAllocated(z)) continue;
    e.layers[size_t(z)] = LayerSpan{0, g.ny()};
    std::fill_n(e.rows.begin() + ptrdiff_t(z) * g.ny(), g.ny(), RowSpan{0, uint16_t(g.wordsPerRow())});
  }
  return e;
}

Extent emptyExtent(const VoxelGrid& g) {
  Extent e;
  e.rows.assign(size_t(g.nz()) * size_t(g.ny()), RowSpan{});
  e.layers.assign(size_t(g.nz()), LayerSpan{});
  return e;
}

// Peels layer after layer, alternating between two grids.
class Peeler {
 public:
  explicit Peeler(const VoxelGrid& grid)
      : cur_(grid), next_(grid.dims(), grid.frame()), cur_ext_(fullExtent(grid)), next_ext_(emptyExtent(grid)) {}

  // Peels one layer and returns the number of voxels removed. With `planes`, the removed voxels are ORed into the
  // planes of the set bits of `depth` (the caller provides bit_width(depth) planes).
  int64_t step(std::vector<VoxelGrid>* planes = nullptr, int32_t depth = 0) {
    const VoxelGrid& src = cur_;
    const int32_t nz = src.nz(), ny = src.ny();
    int32_t z_lo = nz, z_hi = 0;  // layers where either grid may hold voxels
    int64_t work = 0;
    for (int32_t z = 0; z < nz; ++z) {
      const LayerSpan& a = cur_ext_.layers[size_t(z)];
      const LayerSpan& b = next_ext_.layers[size_t(z)];
      if (a.empty() && b.empty()) continue;
      z_lo = std::min(z_lo, z);
      z_hi = z + 1;
      work += int64_t(std::max(a.y1, b.y1) - std::min(a.y0, b.y0)) * src.wordsPerRow();
    }
    if (z_lo >= z_hi) return 0;

    const int threads = threadsFor(work);
    std::vector<int64_t> removed(size_t(threads), 0);
    std::vector<int> plane_bits;
    for (int b = 0; b < 31; ++b) {
      if ((depth >> b) & 1) plane_bits.push_back(b);
    }
    parallelChunks(z_lo, z_hi, 1, threads, [&](int t, int64_t zb, int64_t ze) {
      for (int32_t z = int32_t(zb); z < int32_t(ze); ++z) removed[size_t(t)] += peelLayer(z, ny, planes, plane_bits);
    });
    std::swap(cur_, next_);
    std::swap(cur_ext_, next_ext_);
    int64_t total = 0;
    for (int64_t r : removed) total += r;
    return total;
  }

  // The grid after the layers peeled so far; all-zero layers go back to the shared zero layer.
  VoxelGrid result() const {
    VoxelGrid g = cur_;
    g.releaseEmptyLayers();
    return g;
  }

 private:
  // Writes layer z of next_ from cur_, clears what next_ held there before, and records next_'s new spans.
  int64_t peelLayer(int32_t z, int32_t ny, std::vector<VoxelGrid>* planes, const std::vector<int>& plane_bits) {
    const LayerSpan cl = cur_ext_.layers[size_t(z)];
    const LayerSpan nl = next_ext_.layers[size_t(z)];
    if (cl.empty() && nl.empty()) return 0;
    const int64_t wpr = cur_.wordsPerRow();
    const uint64_t* below = cur_.layerWords(z - 1);
    const uint64_t* cur = cur_.layerWords(z);
    const uint64_t* above = cur_.layerWords(z + 1);
    uint64_t* dst = next_.mutableLayerWords(z);
    std::vector<uint64_t*> plane_words;  // fetched on the first removal: allocating a plane layer costs a clear
    int64_t removed = 0;
    int32_t new_y0 = INT32_MAX, new_y1 = 0;
    const int32_t y_begin = cl.empty() ? nl.y0 : (nl.empty() ? cl.y0 : std::min(cl.y0, nl.y0));
    const int32_t y_end = cl.empty() ? nl.y1 : (nl.empty() ? cl.y1 : std::max(cl.y1, nl.y1));
    for (int32_t y = y_begin; y < y_end; ++y) {
      const RowSpan& cs = cur_ext_.rows[size_t(z) * size_t(ny) + size_t(y)];
      RowSpan& ns = next_ext_.rows[size_t(z) * size_t(ny) + size_t(y)];
      const RowSpan rc = (y >= cl.y0 && y < cl.y1) ? cs : RowSpan{};
      const int64_t base = (int64_t(y) + 1) * wpr;
      // Old content of next_ outside the new span: clear it.
      for (int64_t w = ns.w0; w < std::min<int64_t>(ns.w1, rc.w0); ++w) dst[base + w] = 0;
      for (int64_t w = std::max<int64_t>(ns.w0, rc.w1); w < ns.w1; ++w) dst[base + w] = 0;
      int64_t first = INT64_MAX, last = -1;
      for (int64_t w = rc.w0; w < rc.w1; ++w) {
        const int64_t i = base + w;
        const uint64_t c = cur[i];
        if (!c) {
          dst[i] = 0;
          continue;
        }
        const uint64_t inner = interiorWord(below, cur, above, wpr, i);
        dst[i] = inner;
        const uint64_t gone = c & ~inner;
        if (gone) removed += analysis_detail::popcount64(gone);
        if (inner) {
          first = std::min(first, w);
          last = w;
        }
        if (planes && gone) {
          if (plane_words.empty()) {
            for (int b : plane_bits) plane_words.push_back((*planes)[size_t(b)].mutableLayerWords(z));
          }
          for (uint64_t* p : plane_words) p[i] |= gone;
        }
      }
      if (last >= 0) {
        ns = RowSpan{uint16_t(first), uint16_t(last + 1)};
        new_y0 = std::min(new_y0, y);
        new_y1 = y + 1;
      } else {
        ns = RowSpan{};
      }
    }
    next_ext_.layers[size_t(z)] = new_y0 < new_y1 ? LayerSpan{new_y0, new_y1} : LayerSpan{};
    return removed;
  }

  VoxelGrid cur_, next_;
  Extent cur_ext_, next_ext_;
};

Error cancelled(int32_t layers_done) {
  return makeError(ErrorCode::kCancelled, "skin removal cancelled after " + std::to_string(layers_done) + " layers");
}

// Fraction done for progress: the share of the voxels removed so far (the number of layers is not known ahead).
double removedFraction(int64_t removed, int64_t filled) { return filled > 0 ? double(removed) / double(filled) : 1.0; }

// Calls f(z, out) for every z where `like` has an allocated layer, writing whole layers of a new grid in parallel;
// then releases the layers that came out empty.
template <class F>
VoxelGrid buildByLayer(const VoxelGrid& like, F&& f) {
  VoxelGrid out(like.dims(), like.frame());
  const int threads = threadsFor(like.allocatedLayers() * like.wordsPerLayer());
  parallelChunks(0, like.nz(), 2, threads, [&](int, int64_t z0, int64_t z1) {
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      if (like.layerAllocated(z)) f(z, out.mutableLayerWords(z));
    }
  });
  out.releaseEmptyLayers();
  return out;
}

}  // namespace

VoxelGrid peelOneLayer(const VoxelGrid& grid, int64_t* removed) {
  if (grid.empty()) {
    if (removed) *removed = 0;
    return grid;
  }
  Peeler p(grid);
  const int64_t r = p.step();
  if (removed) *removed = r;
  return p.result();
}

Result<DepthMap> computeDepthMap(const VoxelGrid& grid, const PeelParams& params, const ProgressFn& progress) {
  if (!params.all && params.layers < 0) {
    return makeError(ErrorCode::kInvalidArgument,
                     "number of skin layers must be >= 0 (got " + std::to_string(params.layers) + ")");
  }
  DepthMap dm;
  dm.original_ = grid;
  if (grid.empty()) {
    dm.rest_ = grid;
    return dm;
  }
  const int64_t filled = grid.filledCount();
  dm.original_count_ = filled;
  int64_t left = filled;
  Peeler p(grid);
  for (int32_t k = 1; left > 0 && (params.all || k <= params.layers); ++k) {
    while (dm.depth_bits_.size() < size_t(std::bit_width(uint32_t(k)))) {
      dm.depth_bits_.emplace_back(grid.dims(), grid.frame());
    }
    const int64_t removed = p.step(&dm.depth_bits_, k);
    if (removed == 0) break;  // cannot happen while voxels are left: a finite solid always has a surface
    dm.removed_per_layer_.push_back(removed);
    left -= removed;
    const double fraction =
        params.all ? removedFraction(filled - left, filled) : double(k) / double(std::max(params.layers, 1));
    if (progress && !progress(std::min(fraction, 1.0))) return cancelled(k);
  }
  dm.rest_ = p.result();
  dm.rest_count_ = left;
  for (VoxelGrid& plane : dm.depth_bits_) plane.releaseEmptyLayers();
  return dm;
}

PeelResult DepthMap::peeled(int32_t k) const {
  PeelResult r;
  k = std::clamp(k, 0, layers());
  r.remaining = remainingAfter(k);
  r.removed_per_layer.assign(removed_per_layer_.begin(), removed_per_layer_.begin() + k);
  r.remaining_count = original_count_;
  for (int64_t n : r.removed_per_layer) r.remaining_count -= n;
  r.core_voxels = r.removed_per_layer.empty() ? 0 : r.removed_per_layer.back();
  return r;
}

uint64_t estimateDepthMapBytes(const VoxelGrid& grid) {
  if (grid.empty()) return 0;
  const int64_t deepest = (std::min({grid.nx(), grid.ny(), grid.nz()}) + 1) / 2;
  const uint64_t planes = uint64_t(std::bit_width(uint64_t(deepest)));
  return (planes + 2) * uint64_t(grid.memoryBytes());
}

VoxelGrid DepthMap::remainingAfter(int32_t k) const {
  if (k <= 0 || original_.empty()) return original_;
  if (k >= layers()) return rest_;
  const int planes = int(depth_bits_.size());
  const int64_t w_begin = analysis_detail::firstRowWord(original_);
  const int64_t w_end = analysis_detail::endRowWord(original_);
  return buildByLayer(original_, [&](int32_t z, uint64_t* out) {
    std::vector<const uint64_t*> p(static_cast<size_t>(planes));
    for (int b = 0; b < planes; ++b) p[size_t(b)] = depth_bits_[size_t(b)].layerWords(z);
    const uint64_t* rest = rest_.layerWords(z);
    for (int64_t w = w_begin; w < w_end; ++w) {
      // Bit-sliced depth > k, most significant plane first: `gt` is decided, `eq` still equal so far.
      uint64_t gt = 0, eq = ~uint64_t(0);
      for (int b = planes - 1; b >= 0; --b) {
        const uint64_t d = p[size_t(b)][w];
        if ((k >> b) & 1) {
          eq &= d;
        } else {
          gt |= eq & d;
          eq &= ~d;
        }
      }
      out[w] = gt | rest[w];  // voxels a partial depth map did not reach are still there
    }
  });
}

VoxelGrid DepthMap::removedBy(int32_t k) const {
  if (original_.empty()) return original_;
  if (k < 1 || k > layers()) return VoxelGrid(original_.dims(), original_.frame());
  const int planes = int(depth_bits_.size());
  const int64_t w_begin = analysis_detail::firstRowWord(original_);
  const int64_t w_end = analysis_detail::endRowWord(original_);
  return buildByLayer(original_, [&](int32_t z, uint64_t* out) {
    std::vector<const uint64_t*> p(static_cast<size_t>(planes));
    for (int b = 0; b < planes; ++b) p[size_t(b)] = depth_bits_[size_t(b)].layerWords(z);
    for (int64_t w = w_begin; w < w_end; ++w) {
      uint64_t eq = ~uint64_t(0);  // k >= 1 has a set bit, so padding (zero in every plane) never survives
      for (int b = 0; b < planes; ++b) eq &= ((k >> b) & 1) ? p[size_t(b)][w] : ~p[size_t(b)][w];
      out[w] = eq;
    }
  });
}

int32_t DepthMap::depthAt(int32_t x, int32_t y, int32_t z) const {
  if (!original_.inBounds(x, y, z)) return 0;
  int32_t d = 0;
  for (size_t b = 0; b < depth_bits_.size(); ++b) d |= int32_t(depth_bits_[b].get(x, y, z)) << b;
  return d;
}

size_t DepthMap::memoryBytes() const {
  size_t bytes = sizeof(*this) + removed_per_layer_.capacity() * sizeof(int64_t);
  for (const VoxelGrid& plane : depth_bits_) bytes += plane.memoryBytes();
  if (rest_count_ > 0) bytes += rest_.memoryBytes();
  return bytes;
}

}  // namespace vox
