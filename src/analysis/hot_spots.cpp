// Hot spots: regional maxima of the distance field and their dynamics (see vox/analysis/thickness.h and
// docs/accuracy.md), from the field's basins rather than from a watershed over the voxels in order of distance.
//
// Order the filled voxels by (squared distance, then lower index first). Every voxel that is not the greatest of its
// 26-neighbourhood points to its greatest neighbour; following the pointers climbs, never below the voxel's own
// distance, to a voxel greater than all its neighbours: a summit, whose basin the voxel is in. Every regional maximum
// holds one summit or more (a plateau's first voxel is one), and the lowest level that a path from one summit to
// another must go down to is the same over the voxels as over the basins, where two basins are joined at the highest
// min(s(u), s(v)) over their 26-adjacent voxel pairs u, v: inside a basin a path can always climb to its summit and
// back. So the maxima's dynamics come from the basin graph, a few edges per summit, by Kruskal's merge from the
// highest edge down: where two sets meet, the one with the lower summit (the later one among equals) dies at that
// level, its saddle; summits of equal distance that meet at that distance are one plateau. Each step is a sweep over
// the box's layers, in parallel, reading the field and the labels about each voxel where they lie in memory.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "analysis/neighbours.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/thickness.h"
#include "vox/core/parallel.h"

namespace vox {
namespace {

// A summit's set in the basin graph's merge.
struct Component {
  uint32_t peak = 0;    // squared distance at the summit
  uint32_t saddle = 0;  // squared distance where it died (met a higher summit)
  bool dead = false;
  uint32_t absorbed_by = UINT32_MAX;  // the set it died into, or whose plateau it joined
};

// The geometric (Chvorinov) modulus V/A, in voxels, of the region a hot spot feeds: R its inscribed radius and mean
// the mean depth of the region's voxels (their distance less the half voxel by which the distance to the nearest
// empty centre exceeds the depth below the surface). Where the inner offsets' areas shrink as (1 - depth / R)^(n - 1),
// as for a plate (n = 1), a bar or cylinder (2), a cube or sphere (3), V/A = R / n and the mean depth is R / (n + 1):
// so V/A = R mean / (R - mean), between R / 3 and R.
double regionModulus(double radius, double depth_sum, int64_t voxels) {
  if (voxels <= 0 || radius <= 0.0) return radius / 3.0;
  const double mean = std::max(depth_sum / double(voxels) - 0.5, 0.0);
  if (mean >= radius * 0.5) return radius;
  return std::clamp(radius * mean / (radius - mean), radius / 3.0, radius);
}

// The root of i's set in a union-find forest (link[k] == k at a root), compressing the path.
uint32_t findRoot(std::vector<uint32_t>& link, uint32_t i) {
  uint32_t r = i;
  while (link[r] != r) r = link[r];
  while (link[i] != r) {
    const uint32_t next = link[i];
    link[i] = r;
    i = next;
  }
  return r;
}

// The highest joining level of each pair of basins a thread met: open addressing on the pair, growing at half full.
class EdgeTable {
 public:
  struct Edge {
    uint64_t pair = kEmpty;  // lower summit << 32 | higher summit
    uint32_t level = 0;
  };
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  EdgeTable() : slots_(1024) {}
  void raise(uint32_t a, uint32_t b, uint32_t level) {
    const uint64_t pair = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
    if (slots_[last_].pair != pair) {  // not the same pair again, as along a boundary between two basins
      if (2 * (used_ + 1) > slots_.size()) grow();
      last_ = find(pair);
      if (slots_[last_].pair == kEmpty) {
        slots_[last_].pair = pair;
        ++used_;
      }
    }
    slots_[last_].level = std::max(slots_[last_].level, level);
  }
  const std::vector<Edge>& slots() const { return slots_; }

 private:
  size_t find(uint64_t pair) const {
    size_t i = size_t((pair * 0x9E3779B97F4A7C15ull) >> 20) & (slots_.size() - 1);
    while (slots_[i].pair != kEmpty && slots_[i].pair != pair) i = (i + 1) & (slots_.size() - 1);
    return i;
  }
  void grow() {
    std::vector<Edge> old(slots_.size() * 2);
    old.swap(slots_);
    for (const Edge& e : old) {
      if (e.pair != kEmpty) slots_[find(e.pair)] = e;
    }
    last_ = 0;
  }
  std::vector<Edge> slots_;
  size_t used_ = 0;
  size_t last_ = 0;  // the slot raised last (or any slot)
};

// The greatest values over the 3 x 3 voxels about each voxel in its layer, for the layers about [zb, ze) of a box,
// along x and then y: three values at each step instead of 9; the caller takes the greatest of three layers, the
// last step of the 3 x 3 x 3 maximum. key(i, k) is voxel i's value as the k-th of three along x (i = -1: outside
// the box); up(v, k, step) the same for a greatest value of a row as the k-th of three rows (step 3), and the caller
// uses it for layers (step 9); `more` is the greater (componentwise where T holds several). The box is taken in
// bands of kBand rows, each through the layers, so that what is kept of three layers stays in the caches: for each
// band and layer z, out(z, y0, y1, below, at, above) gets the 3 x 3 greatest of rows [y0, y1) in layers z - 1, z and
// z + 1 (x fastest, row y at (y - y0) * nx; below and above null outside the box), and returns false to stop.
constexpr int64_t kBand = 16;
template <class T, class Key, class Up, class More, class Out>
void greatestAbout(const Dims& d, int64_t zb, int64_t ze, Key&& key, Up&& up, More&& more, Out&& out) {
  const int64_t nx = d.nx, ny = d.ny, nz = d.nz, layer = nx * ny;
  std::vector<T> rows(static_cast<size_t>((kBand + 2) * nx)), planes(static_cast<size_t>(3 * kBand * nx));
  const T outside = up(key(-1, 0), 0, 3);
  for (int64_t y0 = 0; y0 < ny; y0 += kBand) {
    const int64_t y1 = std::min(ny, y0 + kBand), ya = std::max<int64_t>(y0 - 1, 0), yb = std::min(ny, y1 + 1);
    auto plane = [&](int64_t z) { return planes.data() + (z % 3) * kBand * nx; };
    auto fill = [&](int64_t z) {
      for (int64_t y = ya; y < yb; ++y) {
        const int64_t i = layer * z + nx * y;
        T* r = rows.data() + nx * (y - ya);
        for (int64_t x = 0; x < nx; ++x) {
          const T left = x > 0 ? key(i + x - 1, 0) : key(-1, 0);
          const T right = x + 1 < nx ? key(i + x + 1, 2) : key(-1, 2);
          r[x] = more(more(left, key(i + x, 1)), right);
        }
      }
      T* p = plane(z);
      for (int64_t y = y0; y < y1; ++y) {
        const T* r = rows.data() + nx * (y - ya);
        T* o = p + nx * (y - y0);
        for (int64_t x = 0; x < nx; ++x) {
          const T lo = y > 0 ? up(r[x - nx], 0, 3) : outside, hi = y + 1 < ny ? up(r[x + nx], 2, 3) : outside;
          o[x] = more(more(lo, up(r[x], 1, 3)), hi);
        }
      }
    };
    if (zb > 0) fill(zb - 1);
    fill(zb);
    for (int64_t z = zb; z < ze; ++z) {
      if (z + 1 < nz) fill(z + 1);
      if (!out(z, y0, y1, z > 0 ? plane(z - 1) : nullptr, plane(z), z + 1 < nz ? plane(z + 1) : nullptr)) return;
    }
  }
}

// The search over one dense field, step by step (the file's header says why these steps): the shared geometry, the
// progress and the results each step hands to the next.
class HotSpotSearch {
 public:
  HotSpotSearch(const DistanceField& distance, const HotSpotParams& params, const ProgressFn& progress,
                bool keep_labels = false)
      : keep_labels_(keep_labels),
        distance_(distance),
        params_(params),
        d_(distance.boxDims()),
        nx_(d_.nx),
        ny_(d_.ny),
        nz_(d_.nz),
        layer_(nx_ * ny_),
        data_(distance.data()),
        gate_(progress),
        threads_(threadsFor(d_.count() / 4)),
        bands_((ny_ + kBand - 1) / kBand),
        grain_(std::max<int64_t>(8, nz_ / (8 * threads_))) {  // a slab reads two more layers about it
    int k = 0;  // the 26 neighbours in increasing index order: code k leads to the voxel offset_[k] on
    for (int64_t dz = -1; dz <= 1; ++dz)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dx = -1; dx <= 1; ++dx)
          if (dx || dy || dz) offset_[k++] = dx + nx_ * (dy + ny_ * dz);
  }

  Result<std::vector<HotSpot>> run() {
    if (Status s = climbCodes(); !s) return s.error();
    if (Status s = basinGraph(); !s) return s.error();
    mergeBasins();
    if (!gate_.report(0.95)) return cancelled();
    std::vector<HotSpot> out = spots();
    if (!gate_.report(1.0)) return cancelled();
    return out;
  }

 private:
  using Labels16 = uint16_t;
  static constexpr uint16_t kClimb16 = 0x8000;

  static Error cancelled() { return makeError(ErrorCode::kCancelled, "hot spots cancelled"); }
  static Error noMemory(int64_t bytes) {
    return makeError(ErrorCode::kLimit,
                     "hot spots: cannot allocate " + std::to_string(bytes >> 20) + " MiB for labels");
  }

  // Reports the share [from, to) of the progress for one more of the nz layers of a sweep (or of a band of them),
  // every 16th; false once cancelled.
  bool layerDone(double from, double to, int64_t bands = 1) {
    const int64_t n = done_.fetch_add(1) + 1;
    if (n % 16 && n != nz_ * bands) return !gate_.cancelled();
    return gate_.report(from + (to - from) * double(n) / double(nz_ * bands));
  }

  // 1. Each filled voxel's code: which of its 26 neighbours is its greatest (kClimb | k), or none, a summit. As keys,
  // distance << 5 | 31 - rank, where rank orders the 27 voxels about one by index (9 (dz + 1) + 3 (dy + 1) + dx + 1,
  // 13 the voxel itself): the greatest key names the greatest voxel, and its rank what was added to the key's low
  // bits along the way. Codes fit 16 bits, and so do the summits' numbers on most parts: the labels are 16 bits
  // wide until there are more summits. They start zeroed (fresh pages; only the climbing voxels' are written here,
  // the summits' in step 2).
  Status climbCodes() {
    code_.reset(static_cast<uint16_t*>(std::calloc(size_t(d_.count()), sizeof(uint16_t))));
    if (!code_) return noMemory(d_.count() * 2);
    std::vector<std::vector<uint32_t>> summits(static_cast<size_t>(nz_));  // per layer, in index order
    auto key = [&](int64_t i, int k) { return (i < 0 ? uint64_t(0) : uint64_t(data_[i]) << 5) | uint64_t(31 - k); };
    auto up = [](uint64_t v, int k, int step) { return v - uint64_t(k * step); };
    auto more = [](uint64_t a, uint64_t b) { return std::max(a, b); };
    parallelChunks(0, nz_, grain_, threads_, [&](int, int64_t zb, int64_t ze) {
      greatestAbout<uint64_t>(
          d_, zb, ze, key, up, more,
          [&](int64_t z, int64_t y0, int64_t y1, const uint64_t* below, const uint64_t* at, const uint64_t* above) {
            const uint64_t outside = up(key(-1, 0), 0, 9);
            for (int64_t j = 0; j < (y1 - y0) * nx_; ++j) {
              const int64_t i = layer_ * z + nx_ * y0 + j;
              if (!data_[i]) continue;
              const uint64_t m =
                  more(more(below ? below[j] : outside, up(at[j], 1, 9)), above ? up(above[j], 2, 9) : outside);
              const auto rank = int(31 - (m & 31));
              if (rank != 13) {
                code_[size_t(i)] = uint16_t(kClimb16 | (rank < 13 ? rank : rank - 1));
              } else {
                summits[size_t(z)].push_back(uint32_t(i));
              }
            }
            return layerDone(0.0, 0.35, bands_);
          });
    });
    if (gate_.cancelled()) return cancelled();
    for (const auto& v : summits) summit_voxel_.insert(summit_voxel_.end(), v.begin(), v.end());
    if (summit_voxel_.size() >= 0x80000000u) return makeError(ErrorCode::kLimit, "hot spots: more than 2^31 maxima");
    comps_.resize(summit_voxel_.size());
    for (size_t k = 0; k < comps_.size(); ++k) comps_[k].peak = data_[summit_voxel_[k]];
    return Ok{};
  }

  // Steps 2 and 3 over labels of 16 bits (the codes themselves), or 32-bit copies when more summits than 16 bits
  // number.
  Status basinGraph() {
    tables_.resize(static_cast<size_t>(threads_));
    plateau_voxels_.resize(static_cast<size_t>(nz_));
    basin_depth_.assign(static_cast<size_t>(threads_), std::vector<double>(summit_voxel_.size(), 0.0));
    basin_voxels_.assign(static_cast<size_t>(threads_), std::vector<int64_t>(summit_voxel_.size(), 0));
    if (summit_voxel_.size() < 0x8000u) {
      basins(code_.get());
    } else {
      std::unique_ptr<uint32_t[], decltype(&std::free)> wide(
          static_cast<uint32_t*>(std::calloc(size_t(d_.count()), sizeof(uint32_t))), &std::free);
      if (!wide) return noMemory(d_.count() * 4);
      parallelChunks(0, nz_, grain_, threads_, [&](int, int64_t zb, int64_t ze) {
        if (gate_.cancelled()) return;
        for (int64_t i = layer_ * zb; i < layer_ * ze; ++i) {
          if (code_[size_t(i)] & kClimb16) wide[size_t(i)] = 0x80000000u | (code_[size_t(i)] & 31u);
        }
      });
      if (gate_.cancelled()) return cancelled();
      code_.reset();
      basins(wide.get());
      if (keep_labels_) wide_ = std::move(wide);
    }
    if (!keep_labels_) code_.reset();
    if (gate_.cancelled()) return cancelled();
    return Ok{};
  }

  template <class L>
  void basins(L* label) {
    labelBasins(label);
    if (!gate_.cancelled()) joinBasins(label);
  }

  // 2. Summits numbered in index order (so that among equal distances the lower number is the earlier voxel), then
  // every voxel's summit, by following the codes up to a label that is a number and writing that number back along
  // the way. Followed in the order of the layers, a path that climbs to the next layers would run through voxels far
  // apart in memory, one miss each, and the paths beside it would do the same: so the layers are swept upwards
  // following only paths that stay in the layers below, the voxels of a path that leaves them marked kWait, then
  // downwards for the marked ones, whose paths then mostly reach numbers in the layers above at once. A thread may
  // follow and write labels in another's layers: a voxel's label is always its code, its code marked, or its number,
  // all of which lead to its summit (a mark goes only on the code, by a compare and exchange, never on a number
  // written meanwhile), by relaxed atomic loads and stores.
  template <class L>
  void labelBasins(L* label) {
    constexpr L kClimb = L(1) << (8 * sizeof(L) - 1);
    constexpr L kWait = kClimb >> 1, kCode = kWait - 1;
    for (size_t k = 0; k < summit_voxel_.size(); ++k) label[summit_voxel_[k]] = L(k);
    auto load = [&](int64_t q) { return std::atomic_ref<L>(label[q]).load(std::memory_order_relaxed); };
    auto store = [&](int64_t q, L l) { std::atomic_ref<L>(label[q]).store(l, std::memory_order_relaxed); };
    for (const bool upwards : {true, false}) {
      done_ = 0;
      parallelChunks(0, nz_, grain_, threads_, [&](int, int64_t zb, int64_t ze) {
        std::vector<std::pair<int64_t, L>> path;  // the voxels followed, with the codes read there
        for (int64_t n = zb; n < ze && !gate_.cancelled(); ++n) {
          const int64_t z = upwards ? n : nz_ - 1 - n;
          const int64_t top = layer_ * (z + 1);  // upwards, paths stop where they reach the layers above z
          for (int64_t i = layer_ * z; i < top; ++i) {
            if (!data_[i]) continue;
            L l = load(i);
            if (!(l & kClimb) || (upwards && (l & kWait))) continue;
            path.clear();
            int64_t q = i;
            bool wait = false;
            while (l & kClimb) {
              path.emplace_back(q, l);
              q += offset_[l & kCode];
              if (upwards && (q >= top || (load(q) & (kClimb | kWait)) == (kClimb | kWait))) {
                wait = true;
                break;
              }
              l = load(q);
            }
            for (const auto& [v, c] : path) {
              if (!wait) {
                store(v, l);
              } else {  // marked only where no thread has written the number since
                L expected = c;
                std::atomic_ref<L>(label[v]).compare_exchange_strong(expected, L(c | kWait), std::memory_order_relaxed);
              }
            }
          }
          layerDone(upwards ? 0.35 : 0.45, upwards ? 0.45 : 0.55);
        }
      });
      if (gate_.cancelled()) return;
    }
  }

  // 3. The basin graph: for each pair of 26-adjacent filled voxels in two basins, the pair's level min(s(u), s(v)),
  // the highest kept per pair of basins (each voxel pair met once, from the one with the lower index); and the
  // plateau voxels (at their summit's distance) with their summits, in index order. Only voxels with another basin
  // about them look at their neighbours: those whose filled neighbours' greatest label and greatest ~label (the least
  // label) are not both their own.
  template <class L>
  void joinBasins(const L* label) {
    struct Labels {
      L most = 0, least = 0;  // label + 1 and ~label: 0 for empty voxels
    };
    auto labels = [&](int64_t i, int) { return i >= 0 && data_[i] ? Labels{L(label[i] + 1), L(~label[i])} : Labels{}; };
    auto same = [](Labels v, int, int) { return v; };
    auto both = [](Labels a, Labels b) { return Labels{std::max(a.most, b.most), std::max(a.least, b.least)}; };
    done_ = 0;
    parallelChunks(0, nz_, grain_, threads_, [&](int t, int64_t zb, int64_t ze) {
      EdgeTable& table = tables_[size_t(t)];
      greatestAbout<Labels>(
          d_, zb, ze, labels, same, both,
          [&](int64_t z, int64_t y0, int64_t y1, const Labels* below, const Labels* at, const Labels* above) {
            for (int64_t j = 0; j < (y1 - y0) * nx_; ++j) {
              const int64_t i = layer_ * z + nx_ * y0 + j;
              const uint32_t s = data_[i];
              if (!s) continue;
              const L own = label[i];
              if (s == comps_[own].peak) plateau_voxels_[size_t(z)].emplace_back(uint32_t(i), own);
              basin_depth_[size_t(t)][size_t(own)] += std::sqrt(double(s));
              ++basin_voxels_[size_t(t)][size_t(own)];
              Labels m = at[j];
              if (below) m = both(m, below[j]);
              if (above) m = both(m, above[j]);
              if (m.most == L(own + 1) && m.least == L(~own)) continue;  // one basin about it
              analysis_detail::forEach26(j % nx_, y0 + j / nx_, z, nx_, ny_, nz_, [&](int64_t q) {
                if (q <= i) return;  // met from the other voxel
                const uint32_t v = data_[q];
                if (v && label[q] != own) table.raise(own, label[q], std::min(s, v));
              });
            }
            return layerDone(0.55, 0.9, bands_);
          });
    });
  }

  // 4. Kruskal's merge from the highest edge down (among equal levels, the lower pair of summits' numbers first). The
  // higher summit of two sets survives (the earlier among equals); the other dies at the edge's level, unless both
  // summits lie at that level: then they are one plateau.
  void mergeBasins() {
    std::vector<std::pair<uint32_t, uint64_t>> edges;
    for (const EdgeTable& table : tables_)
      for (const EdgeTable::Edge& e : table.slots())
        if (e.pair != EdgeTable::kEmpty) edges.emplace_back(e.level, e.pair);
    tables_ = {};
    // highest first, and among equal levels by the pair: the threads' tables hold the edges in an order that depends
    // on which thread met them, and which of two sets a third dies into at one level must not
    std::sort(edges.begin(), edges.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    std::vector<uint32_t> parent(comps_.size());
    plateau_.resize(comps_.size());
    for (uint32_t k = 0; k < comps_.size(); ++k) parent[k] = plateau_[k] = k;
    for (const auto& [level, pair] : edges) {
      uint32_t a = findRoot(parent, uint32_t(pair >> 32)), b = findRoot(parent, uint32_t(pair));
      if (a == b) continue;
      if (comps_[b].peak > comps_[a].peak || (comps_[b].peak == comps_[a].peak && b < a)) std::swap(a, b);
      parent[b] = a;  // a survives
      comps_[b].absorbed_by = a;
      if (comps_[a].peak == level && comps_[b].peak == level) {
        plateau_[findRoot(plateau_, b)] = findRoot(plateau_, a);
      } else {
        comps_[b].dead = true;
        comps_[b].saddle = level;
      }
    }
  }

  static double dynamic(const Component& c) {  // in voxels
    return std::sqrt(double(c.peak)) - (c.dead ? std::sqrt(double(c.saddle)) : 0.0);
  }

  // Each reported spot's plateau voxels, in index order: spot k's are voxels[start[k] .. start[k + 1]). Each plateau's
  // voxels are its summits' basins' voxels at the summits' distance (a path up from such a voxel never leaves that
  // distance).
  void plateauVoxels(const std::vector<int64_t>& spot_of, std::vector<uint32_t>& voxels, std::vector<int64_t>& start) {
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int64_t> fill(start.begin(), start.end() - 1);
      for (const auto& layer_voxels : plateau_voxels_) {
        for (const auto& [i, summit] : layer_voxels) {
          const int64_t spot = spot_of[findRoot(plateau_, summit)];
          if (spot < 0) continue;
          if (pass == 0) {
            ++start[size_t(spot) + 1];
          } else {
            voxels[size_t(fill[size_t(spot)]++)] = i;
          }
        }
      }
      if (pass == 0) {
        for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
        voxels.resize(size_t(start.back()));
      }
    }
    plateau_voxels_ = {};
  }

  // 5. Reported maxima: plateau roots that stand out by min_dynamic (survivors always do). A set that died at its own
  // summit's level was a plateau touching a higher voxel, not a maximum. Their plateau voxels' mean is the centre;
  // the voxel nearest it, the earliest among equals, is `voxel`.
  std::vector<HotSpot> spots() {
    std::vector<int64_t> spot_of(comps_.size(), -1);
    std::vector<uint32_t> spot_comp;
    for (uint32_t k = 0; k < comps_.size(); ++k) {
      const Component& c = comps_[k];
      if (plateau_[k] != k) continue;  // absorbed into another plateau
      const double least =
          std::max(params_.min_dynamic_voxels, params_.min_dynamic_fraction * std::sqrt(double(c.peak)));
      if (c.dead && (c.saddle == c.peak || dynamic(c) < least)) continue;
      spot_of[k] = int64_t(spot_comp.size());
      spot_comp.push_back(k);
    }
    std::vector<uint32_t> voxels;
    std::vector<int64_t> start(spot_comp.size() + 1, 0);
    plateauVoxels(spot_of, voxels, start);
    std::vector<double> depth(spot_comp.size(), 0.0);
    std::vector<int64_t> count(spot_comp.size(), 0);
    regions(spot_of, depth, count);
    std::vector<HotSpot> out;
    spot_modulus_.assign(spot_comp.size(), 0.0);
    for (size_t spot = 0; spot < spot_comp.size(); ++spot) {
      out.push_back(spotOf(comps_[spot_comp[spot]], voxels.data() + start[spot], start[spot + 1] - start[spot]));
      out.back().modulus = regionModulus(std::sqrt(double(comps_[spot_comp[spot]].peak)), depth[spot], count[spot]) *
                           distance_.voxelSize();
      spot_modulus_[spot] = out.back().modulus;
    }
    std::stable_sort(out.begin(), out.end(), [](const HotSpot& a, const HotSpot& b) { return a.radius > b.radius; });
    return out;
  }

  // The region each reported spot feeds: the basins of the sets that died into it (or joined its plateau), before it
  // died itself, with their voxels' summed distances (depth) and counts.
  void regions(const std::vector<int64_t>& spot_of, std::vector<double>& depth, std::vector<int64_t>& count) {
    std::vector<int64_t> owner(comps_.size(), -2);  // -2: not resolved yet
    std::vector<uint32_t> path;
    for (uint32_t k = 0; k < comps_.size(); ++k) {
      uint32_t j = k;
      int64_t found = -1;
      path.clear();
      for (;;) {
        if (owner[j] != -2) {
          found = owner[j];
          break;
        }
        path.push_back(j);
        if (const int64_t spot = spot_of[findRoot(plateau_, j)]; spot >= 0) {
          found = spot;
          break;
        }
        if (comps_[j].absorbed_by == UINT32_MAX) break;
        j = comps_[j].absorbed_by;
      }
      for (uint32_t p : path) owner[p] = found;
    }
    if (keep_labels_) owner_ = owner;
    for (size_t t = 0; t < basin_depth_.size(); ++t) {
      for (size_t k = 0; k < comps_.size(); ++k) {
        if (owner[k] < 0) continue;
        depth[size_t(owner[k])] += basin_depth_[t][k];
        count[size_t(owner[k])] += basin_voxels_[t][k];
      }
    }
    basin_depth_ = {};
    basin_voxels_ = {};
  }

  HotSpot spotOf(const Component& c, const uint32_t* voxels, int64_t count) const {
    const double h = distance_.voxelSize();
    const GridFrame& frame = distance_.frame();
    const glm::ivec3 lo = distance_.boxMin();
    auto coordinates = [&](uint32_t i) {
      return glm::ivec3(int32_t(i % uint32_t(nx_)), int32_t(i / uint32_t(nx_) % uint32_t(ny_)),
                        int32_t(i / uint32_t(layer_)));
    };
    int64_t sx = 0, sy = 0, sz = 0;
    for (int64_t n = 0; n < count; ++n) {
      const glm::ivec3 v = coordinates(voxels[n]);
      sx += v.x;
      sy += v.y;
      sz += v.z;
    }
    HotSpot hs;
    const glm::dvec3 mean = glm::dvec3(double(sx), double(sy), double(sz)) / double(count);
    hs.centre = frame.origin + (glm::dvec3(lo) + mean + 0.5) * h;
    hs.plateau_voxels = count;
    hs.radius = std::sqrt(double(c.peak)) * h;
    hs.dynamic = dynamic(c) * h;
    hs.saddle = c.dead ? std::sqrt(double(c.saddle)) * h : 0.0;
    hs.isolated = !c.dead || dynamic(c) >= std::max(params_.isolation_voxels,
                                                    params_.isolation_fraction * std::sqrt(double(c.peak)));
    double best = INFINITY;
    for (int64_t n = 0; n < count; ++n) {
      const glm::ivec3 v = coordinates(voxels[n]) + lo;
      const glm::dvec3 p = frame.voxelCentre(v.x, v.y, v.z) - hs.centre;
      const double dd = p.x * p.x + p.y * p.y + p.z * p.z;
      if (dd < best) {
        best = dd;
        hs.voxel = v;
      }
    }
    return hs;
  }

  const bool keep_labels_;  // keep each voxel's summit (for the modulus field)
  const DistanceField& distance_;
  const HotSpotParams& params_;
  const Dims d_;
  const int64_t nx_, ny_, nz_, layer_;
  const uint32_t* data_;
  analysis_detail::ProgressGate gate_;
  const int threads_;
  const int64_t bands_, grain_;
  int64_t offset_[26];
  std::atomic<int64_t> done_{0};
  std::unique_ptr<uint16_t[], decltype(&std::free)> code_{nullptr, &std::free};
  std::vector<uint32_t> summit_voxel_;
  std::vector<Component> comps_;
  std::vector<EdgeTable> tables_;
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> plateau_voxels_;
  std::vector<std::vector<double>> basin_depth_;    // per thread, per summit: the summed distance of its basin
  std::vector<std::vector<int64_t>> basin_voxels_;  // ... and its voxels
  std::vector<uint32_t> plateau_;
  std::unique_ptr<uint32_t[], decltype(&std::free)> wide_{nullptr, &std::free};  // kept 32-bit labels
  std::vector<int64_t> owner_;        // with keep_labels_: each summit's reported spot
  std::vector<double> spot_modulus_;  // each reported spot's modulus, model units

 public:
  // After run() with keep_labels: each filled voxel of the box gets the modulus of the spot whose region holds it, at
  // most half its local thickness (`radius`: squared voxels over the same box, or null), written to `out` (the box's
  // layout, model units).
  void paintModulus(const DistanceField* radius, float* out) const {
    const double h = distance_.voxelSize();
    parallelChunks(0, nz_, grain_, threads_, [&](int, int64_t zb, int64_t ze) {
      for (int64_t i = layer_ * zb; i < layer_ * ze; ++i) {
        if (!data_[i]) continue;
        const uint32_t summit = wide_ ? wide_[size_t(i)] : uint32_t(code_[size_t(i)]);
        const int64_t spot = summit < owner_.size() ? owner_[summit] : -1;
        double m = spot >= 0 ? spot_modulus_[size_t(spot)] : 0.0;
        if (radius) m = std::min(m, std::sqrt(double(radius->data()[i])) * h);
        out[i] = float(m);
      }
    });
  }
};

}  // namespace

Result<std::vector<HotSpot>> findHotSpots(const DistanceField& distance, const HotSpotParams& params,
                                          const ProgressFn& progress) {
  if (distance.outside() != 0) {
    return makeError(ErrorCode::kInvalidArgument, "hot spots need a distance field, not a clearance field");
  }
  const Dims d = distance.boxDims();
  if (d.count() == 0) return std::vector<HotSpot>{};
  if (d.count() >= int64_t(UINT32_MAX)) {
    return makeError(ErrorCode::kLimit, "hot spots: the model's bounding box has more than 2^32 voxels");
  }
  if (!distance.isDense()) {  // the sweeps index the box by constant strides
    const DistanceField dense = distance.denseCopy();
    if (!dense.data()) {
      return makeError(ErrorCode::kLimit,
                       "hot spots: cannot allocate " + std::to_string(d.count() >> 18) + " MiB for the field");
    }
    return findHotSpots(dense, params, progress);
  }
  return HotSpotSearch(distance, params, progress).run();
}

}  // namespace vox

namespace vox {

Result<ScalarField> computeModulusField(const DistanceField& distance, const DistanceField* radius,
                                        const HotSpotParams& params, const ProgressFn& progress) {
  if (distance.outside() != 0) {
    return makeError(ErrorCode::kInvalidArgument, "the modulus needs a distance field, not a clearance field");
  }
  if (radius &&
      (radius->boxDims() != distance.boxDims() || radius->boxMin() != distance.boxMin() || !radius->isDense())) {
    return makeError(ErrorCode::kInvalidArgument, "the modulus: the thickness is not over the distance's box");
  }
  const Dims d = distance.boxDims();
  ScalarField out(distance.gridDims(), distance.frame());
  if (d.count() == 0) return out;
  if (d.count() >= int64_t(UINT32_MAX)) {
    return makeError(ErrorCode::kLimit, "the modulus: the model's bounding box has more than 2^32 voxels");
  }
  if (!distance.isDense()) {
    const DistanceField dense = distance.denseCopy();
    if (!dense.data()) {
      return makeError(ErrorCode::kLimit,
                       "the modulus: cannot allocate " + std::to_string(d.count() >> 18) + " MiB for the field");
    }
    return computeModulusField(dense, radius, params, progress);
  }
  HotSpotSearch search(distance, params, progress, true);
  if (auto spots = search.run(); !spots) return spots.error();
  std::vector<float> box(size_t(d.count()), 0.0f);
  search.paintModulus(radius, box.data());
  const glm::ivec3 lo = distance.boxMin();
  for (int64_t z = 0; z < d.nz; ++z)
    for (int64_t y = 0; y < d.ny; ++y)
      std::copy_n(box.data() + d.nx * (y + d.ny * z), d.nx, &out.at(lo.x, lo.y + y, lo.z + z));
  return out;
}

}  // namespace vox
