// Exact Euclidean distance transform (docs/conventions.md, "Distance and thickness"), see vox/analysis/distance.h.
//
// Felzenszwalb and Huttenlocher (2012): the squared distance along a line is the lower envelope of the parabolas
// (q - p)^2 + f(p) of its sites p, found in one sweep. Three passes: X from the bit words (a 1D distance to the
// nearest site is plain run-length arithmetic), then Y (slice by slice, right after X) and Z over the result in place.
// A zero of the line (a voxel that is its own nearest site) beats every parabola of a site on its other side, so the
// line splits at its zeros into pieces transformed on their own, each with the zeros that bound it as sites: the passes
// cost the runs of nonzero values, not the box. Positions past the ends of a distance line are empty voxels (zeros); a
// clearance line ends at the grid, past which nothing is filled.
#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>

#include "analysis/distance_lanes.h"
#include "analysis/distance_pages.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/distance.h"
#include "vox/core/bits.h"
#include "vox/core/parallel.h"
#include "vox/core/prefetch.h"

namespace vox {

DistanceField::DistanceField(Dims grid_dims, GridFrame frame, glm::ivec3 box_min, Dims box_dims, uint32_t outside)
    : grid_dims_(grid_dims), frame_(std::move(frame)), box_min_(box_min), box_dims_(box_dims), outside_(outside) {
  stored_ = box_dims_.count();
  if (stored_ > 0) data_.reset(static_cast<uint32_t*>(std::calloc(size_t(stored_), sizeof(uint32_t))));
}

DistanceField::DistanceField(Dims grid_dims, GridFrame frame, glm::ivec3 box_min, Dims box_dims, uint32_t outside,
                             std::vector<Row> spans)
    : grid_dims_(grid_dims),
      frame_(std::move(frame)),
      box_min_(box_min),
      box_dims_(box_dims),
      outside_(outside),
      rows_(std::move(spans)) {
  if (box_dims_.count() == 0) {
    rows_.clear();
    return;
  }
  for (Row& r : rows_) {
    r.base = stored_ - r.lo;
    stored_ += r.hi - r.lo;
  }
  if (stored_ > 0) data_.reset(static_cast<uint32_t*>(std::calloc(size_t(stored_), sizeof(uint32_t))));
}

DistanceField DistanceField::denseCopy() const {
  DistanceField c(grid_dims_, frame_, box_min_, box_dims_, outside_);
  c.max_squared_ = max_squared_;
  if (!c.data()) return c;
  if (isDense()) {
    std::copy(data(), data() + stored_, c.data());
    return c;
  }
  const Dims d = box_dims_;
  parallelChunks(0, d.nz, 1, threadsFor(d.count() / 4), [&](int, int64_t zb, int64_t ze) {
    for (int64_t z = zb; z < ze; ++z) {
      for (int64_t y = 0; y < d.ny; ++y) {
        const Row r = row(y, z);
        uint32_t* out = c.data() + (y + int64_t(d.ny) * z) * d.nx;
        if (outside_ != 0) {
          std::fill(out, out + r.lo, outside_);
          std::fill(out + r.hi, out + d.nx, outside_);
        }
        std::copy(data() + r.base + r.lo, data() + r.base + r.hi, out + r.lo);
      }
    }
  });
  return c;
}

namespace {

using analysis_detail::ProgressGate;
constexpr uint32_t kInf = DistanceField::kInfinite;

struct Box {
  glm::ivec3 lo{0}, hi{0};  // [lo, hi)
  bool empty() const { return hi.x <= lo.x || hi.y <= lo.y || hi.z <= lo.z; }
};

// Bounding box of the filled voxels (empty box when there are none), parallel over layers.
// The first and last set bits of a row of wpr words (padded x), {-1, -1} when none is set.
inline std::pair<int64_t, int64_t> setBitRange(const uint64_t* row, int64_t wpr) {
  int64_t first = -1, last = -1;
  for (int64_t w = 0; w < wpr; ++w) {
    if (!row[w]) continue;
    if (first < 0) first = w * 64 + std::countr_zero(row[w]);
    last = w * 64 + 63 - std::countl_zero(row[w]);
  }
  return {first, last};
}

Box filledBox(const VoxelGrid& g) {
  const int threads = threadsFor(g.allocatedLayers() * g.wordsPerLayer());
  std::vector<Box> part(size_t(threads), Box{glm::ivec3(INT32_MAX), glm::ivec3(INT32_MIN)});
  const int64_t wpr = g.wordsPerRow();
  parallelChunks(0, g.nz(), 1, threads, [&](int t, int64_t z0, int64_t z1) {
    Box& b = part[size_t(t)];
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      if (!g.layerAllocated(z)) continue;
      for (int32_t y = 0; y < g.ny(); ++y) {
        const auto [first, last] = setBitRange(g.rowWords(y, z), wpr);
        if (first < 0) continue;
        b.lo = glm::min(b.lo, glm::ivec3(int32_t(first - 1), y, z));
        b.hi = glm::max(b.hi, glm::ivec3(int32_t(last), y + 1, z + 1));  // last padded bit = voxel last - 1
      }
    }
  });
  Box box{glm::ivec3(INT32_MAX), glm::ivec3(INT32_MIN)};
  for (const Box& b : part) {
    box.lo = glm::min(box.lo, b.lo);
    box.hi = glm::max(box.hi, b.hi);
  }
  if (box.empty()) return Box{};
  return box;
}

// Each row's span of filled voxels (box x), parallel over slices: the rows of a packed distance field. The box is
// the filled bounding box, so every filled voxel of a row lies inside it.
std::vector<DistanceField::Row> filledSpans(const VoxelGrid& g, const Box& box) {
  const glm::ivec3 size = box.hi - box.lo;
  std::vector<DistanceField::Row> spans(size_t(int64_t(size.y) * size.z));
  const int64_t wpr = g.wordsPerRow(), begin = int64_t(box.lo.x) + 1;  // padded x of the box's first voxel
  parallelChunks(0, size.z, 1, threadsFor(int64_t(size.y) * size.z * wpr), [&](int, int64_t zb, int64_t ze) {
    for (int64_t zi = zb; zi < ze; ++zi) {
      for (int32_t yi = 0; yi < size.y; ++yi) {
        const auto [first, last] = setBitRange(g.rowWords(box.lo.y + yi, box.lo.z + int32_t(zi)), wpr);
        if (first < 0) continue;
        spans[size_t(yi + int64_t(size.y) * zi)] =
            DistanceField::Row{0, int32_t(first - begin), int32_t(last + 1 - begin)};
      }
    }
  });
  return spans;
}

// Pass 1 along X, slice zi of the box: for each row, the squared distance to the nearest site along the row.
// to_empty: sites are the empty voxels (the box is the filled bounding box, so the row's runs end inside it).
// Otherwise (clearance, box = grid) sites are the filled voxels; a row without one stays kInf.
void rowsX(const VoxelGrid& g, DistanceField& f, bool to_empty, int64_t zi) {
  const glm::ivec3 lo = f.boxMin();
  const Dims d = f.boxDims();
  uint32_t* data = f.data();
  const int32_t z = lo.z + int32_t(zi);
  for (int32_t yi = 0; yi < d.ny; ++yi) {
    const uint64_t* row = g.rowWords(lo.y + yi, z);
    const DistanceField::Row r = f.row(yi, zi);
    const int64_t begin = int64_t(lo.x) + 1, end = int64_t(lo.x) + d.nx + 1;  // padded x range of the box
    const int64_t out = r.base - begin;  // data[out + xp]: voxel x = xp - 1 (inside the row's span)
    if (to_empty) {
      // runs of filled voxels [a, b) (padded x); the bits at a - 1 and b are empty
      for (int64_t xp = begin; xp < end;) {
        const int64_t a = nextBit(row, xp, end, true);
        if (a >= end) break;
        const int64_t b = nextBit(row, a, end + 1, false);  // the bit after the box is empty
        for (int64_t q = a; q < b; ++q) {
          const int64_t dist = std::min(q - (a - 1), b - q);
          data[out + q] = uint32_t(dist * dist);
        }
        xp = b;
      }
    } else {
      // gaps of empty voxels [a, b) between filled runs; a - 1 is filled when a > begin, b when b < end
      for (int64_t xp = begin; xp < end;) {
        const int64_t a = nextBit(row, xp, end, false);
        if (a >= end) break;
        const int64_t b = nextBit(row, a, end, true);
        const bool left = a > begin, right = b < end;
        for (int64_t q = a; q < b; ++q) {
          int64_t dist = INT64_MAX;
          if (left) dist = q - (a - 1);
          if (right) dist = std::min(dist, b - q);
          data[out + q] = dist == INT64_MAX ? kInf : uint32_t(dist * dist);
        }
        xp = b;
      }
    }
  }
}

// Scratch of one thread for the 1D transform of lines up to n long: the parabolas of the envelope, parabola k the
// lowest from the point num / den on. Kept as a fraction so that every comparison is exact integer arithmetic (for
// lines up to kMaxDim long |num| < 2^31, 0 < den <= 2^16); the first parabola, lowest from minus infinity, has
// num / den = kNever, which nothing hides.
struct Parabola {
  int64_t site;  // position
  int64_t g;     // value + site^2
  int64_t num, den;
};
constexpr int64_t kNever = -(int64_t(1) << 40);
struct LineScratch {
  std::vector<Parabola> p;
  std::vector<int32_t> takeover;  // per position of the piece, how many parabolas start there
  explicit LineScratch(int64_t n) : p(size_t(n) + 3), takeover(size_t(n) + 1) {}
};

// Lower envelope over the sites of piece [a, b) of line f (n long): zeros at a - 1 and b when they lie in the line
// or when `kBorder` (ends count as zeros: a distance line, whose values inside a piece are all finite; when `sites`
// is given only the sites it marks are taken, analysis/distance_lanes.h), and every finite value inside. Leaves the
// parabolas in s.p[0, k] and returns k, or -1 when the piece has no site (it stays infinite). The envelope's top
// parabola is kept apart from the stack below it, so that a site that hides nothing is compared without a load.
template <bool kBorder>
int64_t buildEnvelope(const uint32_t* f, int64_t stride, int64_t n, int64_t a, int64_t b, const uint64_t* sites,
                      LineScratch& s) {
  Parabola* p = s.p.data();
  int64_t k = 0;  // p[0, k) below the top t
  Parabola t{};
  bool last = b < n || kBorder;
  int64_t q = a;
  if (a > 0 || kBorder) {
    t = Parabola{a - 1, (a - 1) * (a - 1), kNever, 1};
  } else {
    while (q < b && f[q * stride] == kInf) ++q;
    if (q < b) {
      t = Parabola{q, int64_t(f[q * stride]) + q * q, kNever, 1};
      ++q;
    } else if (last) {
      t = Parabola{b, b * b, kNever, 1};
      last = false;
    } else {
      return -1;
    }
  }
  auto push = [&](int64_t x, int64_t fx) {
    const int64_t xx = fx + x * x;
    for (;;) {
      // parabolas t and x meet at (xx - (f(v) + v^2)) / (2 (x - v)), v < x; x hides t when that is at or before
      // the point where t starts to be lowest (never the first parabola: kNever * xd is below every xn * den)
      const int64_t xn = xx - t.g, xd = 2 * (x - t.site);
      if (xn * t.den <= t.num * xd) {
        t = p[--k];
        continue;
      }
      p[k++] = t;
      t = Parabola{x, xx, xn, xd};
      return;
    }
  };
  if (kBorder && sites) {
    for (int64_t w = a >> 6; w * 64 < b; ++w) {  // q = a here
      uint64_t m = sites[w];
      if (w == a >> 6) m &= ~uint64_t(0) << (a & 63);
      if ((w + 1) * 64 > b) m &= ~(~uint64_t(0) << (b & 63));
      for (; m; m &= m - 1) {
        const int64_t x = w * 64 + std::countr_zero(m);
        push(x, f[x * stride]);
      }
    }
  } else {
    for (; q < b; ++q) {
      const uint32_t fq = f[q * stride];
      if (kBorder || fq != kInf) push(q, fq);
    }
  }
  if (last) push(b, 0);
  p[k] = t;
  return k;
}

// Parabola i (i >= 1) is lowest from the first whole position at or after num / den, ceil(num / den): the quotient
// of two integers below 2^32 and 2^16 in double precision lies farther than a rounding from every integer it is
// not, so truncating it and stepping up where that falls short of num is exact. Clamped to [a, b] (the first
// parabola, and any lowest from before the piece, start at a; one starting at b is lowest nowhere in it).
inline int64_t firstLowest(const Parabola& p, int64_t a, int64_t b) {
  const auto c = int64_t(double(p.num) / double(p.den));
  return std::clamp(c + (c * p.den < p.num), a, b);
}

// Writes piece [a, b) of line f from its envelope s.p[0, k] and raises mx to its largest value. The parabola lowest
// at q is the count of those starting at or before q: a running sum over the positions, without a branch per
// position.
void writePiece(uint32_t* f, int64_t stride, int64_t a, int64_t b, int64_t k, LineScratch& s, uint32_t& mx) {
  const Parabola* p = s.p.data();
  int32_t* takeover = s.takeover.data();
  std::fill(takeover, takeover + (b - a) + 1, 0);
  for (int64_t i = 1; i <= k; ++i) ++takeover[firstLowest(p[i], a, b) - a];
  int64_t j = 0;
  uint32_t m = mx;
  for (int64_t q = a; q < b; ++q) {
    j += takeover[q - a];
    const int64_t dq = q - p[j].site;
    const auto v = uint32_t(dq * dq + (p[j].g - p[j].site * p[j].site));
    f[q * stride] = v;
    m = std::max(m, v);
  }
  mx = m;
}

// Transposes a 64 x 64 bit matrix: bit j of word i becomes bit i of word j.
inline void transpose64(uint64_t a[64]) {
  uint64_t m = 0x00000000FFFFFFFFull;
  for (int j = 32; j != 0; j >>= 1, m ^= m << j) {
    for (int k = 0; k < 64; k = (k + j + 1) & ~j) {
      const uint64_t t = ((a[k] >> j) ^ a[k + j]) & m;
      a[k] ^= t << j;
      a[k + j] ^= t;
    }
  }
}

// Passes 2 and 3: the lines along Y (axis 1) or Z (axis 2) of plane o (slice z = o for Y, row y = o for Z), taken
// kTile neighbouring lines in x at a time (each step along the line reads kTile consecutive values), transformed in
// the thread's scratch and written back. The voxels whose value is not zero (filled for a distance, empty for a
// clearance: a pass never turns one into the other) are read from the grid's bit words, 64 x at a time, and only
// they are read, transformed and written: the empty space in the box costs a word per row. Returns the largest
// finite value written.
class PlaneLines {
 public:
  static constexpr int64_t kTile = analysis_detail::kLanes;
  PlaneLines(const VoxelGrid& g, DistanceField& f, int axis, bool border)
      : g_(g),
        f_(f),
        axis_(axis),
        border_(border),
        lanes8_(border && analysis_detail::vectorLanes()),
        nx_(f.boxDims().nx),
        len_(axis == 1 ? f.boxDims().ny : f.boxDims().nz),
        words_((len_ + 63) / 64),
        scratch_(len_),
        tile_(size_t(kTile * (len_ + 2 * kPad)), 0),
        masks_(size_t(words_ * 64), 0),
        keep_(lanes8_ ? size_t(words_ * 64) : 0, 0),
        columns_(size_t(words_ * 64)),
        sites_(lanes8_ ? size_t(words_ * 64) : 0),
        starts_(lanes8_ ? size_t(len_ * 8) : 0, analysis_detail::kNoStart),
        values_(lanes8_ ? size_t(len_ * 8) : 0),
        rows_(size_t(len_)),
        bases_(size_t(len_)) {}
  uint32_t transform(int64_t o) {
    uint32_t mx = 0;
    const glm::ivec3 lo = f_.boxMin();
    const int64_t wpr = g_.wordsPerRow();
    for (int64_t q = 0; q < len_; ++q) {  // the grid's and the field's rows along the lines, found once for all tiles
      const int64_t y = axis_ == 1 ? q : o, z = axis_ == 1 ? o : q;
      rows_[size_t(q)] = g_.rowWords(lo.y + int32_t(y), lo.z + int32_t(z));
      bases_[size_t(q)] = f_.row(y, z).base;
    }
    for (int64_t x0 = 0; x0 < nx_; x0 += kTile) {
      const int64_t w = std::min(kTile, nx_ - x0);
      const uint64_t wmask = w == 64 ? ~uint64_t(0) : (uint64_t(1) << w) - 1;
      const int64_t xp = int64_t(lo.x) + x0 + 1, w0 = xp >> 6, sh = xp & 63;  // padded x of the tile's first voxel
      uint64_t any = 0;
      for (int64_t q = 0; q < len_; ++q) {
        const uint64_t* row = rows_[size_t(q)];
        uint64_t bits = row[w0] >> sh;
        if (sh && w0 + 1 < wpr) bits |= row[w0 + 1] << (64 - sh);
        if (!border_) bits = ~bits;  // clearance: the empty voxels carry the values
        bits &= wmask;
        masks_[size_t(q)] = bits;
        any |= bits;
      }
      if (!any) continue;  // all zeros: already final
      uint32_t* data = f_.data();
      uint32_t* tile = tile_.data() + kPad * kTile;  // step q of line j: tile[q * kTile + j]
      for (int64_t q = 0; q < len_; ++q) {           // the values from the first voxel with one to the last
        if (q + kRowsAhead < len_) {                 // (the voxels that copy reads there)
          if (const uint64_t m = masks_[size_t(q + kRowsAhead)]) {
            const int64_t j0 = std::countr_zero(m), j1 = 64 - std::countl_zero(m);
            const uint32_t* ahead = data + bases_[size_t(q + kRowsAhead)] + x0 + j0;  // inside the row's span
            prefetchBytes(ahead, size_t(j1 - j0) * sizeof(uint32_t));
          }
        }
        const uint64_t m = masks_[size_t(q)];
        uint32_t* dst = tile + q * kTile;
        if (!m) {
          if (lanes8_) std::fill(dst, dst + kTile, 0u);  // keepSites reads every step: zeros, as in the field
          continue;
        }
        const int64_t j0 = std::countr_zero(m), j1 = 64 - std::countl_zero(m);
        const uint32_t* src = data + bases_[size_t(q)] + x0 + j0;  // inside the row's span
        if (lanes8_) std::fill(dst, dst + j0, 0u);
        std::copy(src, src + (j1 - j0), dst + j0);  // zeros where the voxels between have none
        if (lanes8_) std::fill(dst + j1, dst + kTile, 0u);
      }
      // a distance line's sites that its envelope needs (the zeros past its ends are the tile's padding)
      if (lanes8_) analysis_detail::keepSites(tile, len_, masks_.data(), keep_.data());
      for (int64_t b = 0; b < words_; ++b) {
        transposeInto(masks_.data() + b * 64, columns_.data(), b);  // entries past len_ stay zero
        if (lanes8_) transposeInto(keep_.data() + b * 64, sites_.data(), b);
      }
      if (lanes8_) {
        for (int64_t j0 = 0; j0 < w; j0 += 8) mx = std::max(mx, distanceLanes8(tile, j0, std::min<int64_t>(8, w - j0)));
      } else {
        for (int64_t j = 0; j < w; ++j) {
          uint32_t* line = tile + j;
          forRuns(columns_.data() + j * words_, [&](int64_t a, int64_t e) {
            const int64_t k = border_ ? buildEnvelope<true>(line, kTile, len_, a, e, nullptr, scratch_)
                                      : buildEnvelope<false>(line, kTile, len_, a, e, nullptr, scratch_);
            if (k >= 0) writePiece(line, kTile, a, e, k, scratch_, mx);
          });
        }
      }
      for (int64_t q = 0; q < len_; ++q) {
        uint64_t m = masks_[size_t(q)];
        if (!m) continue;
        const int64_t dst = bases_[size_t(q)] + x0;  // data[dst + j] for the voxels with values, in the row's span
        if (m == wmask) {
          std::copy(tile + q * kTile, tile + q * kTile + w, data + dst);
        } else {
          for (; m; m &= m - 1) {
            const int j = std::countr_zero(m);
            data[dst + j] = tile[q * kTile + j];
          }
        }
      }
    }
    return mx;
  }

 private:
  static constexpr int64_t kPad = analysis_detail::kSitePad;  // zero steps before and after the tile's lines
  static constexpr int64_t kRowsAhead = prefetch_distance::kDistanceRows;  // rows a tile reads are asked ahead
  // The runs [a, e) of set bits of a line's words (words_ of them), in order: f(a, e).
  template <class F>
  void forRuns(const uint64_t* col, F&& f) const {
    for (int64_t q = 0; q < len_;) {
      int64_t wi = q >> 6;
      uint64_t cur = col[wi] & (~uint64_t(0) << (q & 63));
      while (!cur && ++wi < words_) cur = col[wi];
      if (!cur) break;
      const int64_t a = wi * 64 + std::countr_zero(cur);
      uint64_t inv = ~col[wi] & (~uint64_t(0) << (a & 63));
      while (!inv && ++wi < words_) inv = ~col[wi];
      const int64_t e = inv ? std::min(len_, wi * 64 + std::countr_zero(inv)) : len_;
      f(a, e);
      q = e;
    }
  }
  // Distance lines j0 .. j0 + n - 1 (n <= 8) of the tile: each line's envelopes mark where their parabolas start
  // being lowest, then analysis_detail::writeLanes8 writes the eight lines' values at once. Returns their largest.
  uint32_t distanceLanes8(uint32_t* tile, int64_t j0, int64_t n) {
    int64_t q0 = len_, q1 = 0;
    for (int64_t l = 0; l < n; ++l) {
      const int64_t j = j0 + l;
      const uint64_t* col = columns_.data() + j * words_;
      const uint64_t* sites = sites_.data() + j * words_;
      const uint32_t* line = tile + j;
      forRuns(col, [&](int64_t a, int64_t e) {
        q0 = std::min(q0, a);
        q1 = std::max(q1, e);
        const int64_t k = buildEnvelope<true>(line, kTile, len_, a, e, sites, scratch_);
        const Parabola* p = scratch_.p.data();
        for (int64_t i = 0; i <= k; ++i) {
          const int64_t at = firstLowest(p[i], a, e);
          if (at == e) break;  // and every later one
          starts_[size_t(at * 8 + l)] = int32_t(p[i].site);
          values_[size_t(at * 8 + l)] = int32_t(p[i].g - p[i].site * p[i].site);
        }
      });
    }
    if (q0 >= q1) return 0;
    return analysis_detail::writeLanes8(tile, masks_.data(), starts_.data(), values_.data(), j0, q0, q1, 0);
  }
  // Word b of each of 64 lines (words_ words a line) from 64 steps' words of one bit per line.
  void transposeInto(const uint64_t* steps, uint64_t* lines, int64_t b) const {
    uint64_t t[64];
    std::copy(steps, steps + 64, t);
    transpose64(t);
    for (int64_t j = 0; j < 64; ++j) lines[j * words_ + b] = t[j];
  }
  const VoxelGrid& g_;
  DistanceField& f_;
  int axis_;
  bool border_;
  bool lanes8_;  // a distance's lines with the vector steps: keepSites, eight lines written at once (distanceLanes8)
  int64_t nx_, len_, words_;
  LineScratch scratch_;
  std::vector<uint32_t> tile_;
  std::vector<uint64_t> masks_;    // the tile's voxels with values, a word per step along the lines
  std::vector<uint64_t> keep_;     // those a distance line's envelope needs as sites
  std::vector<uint64_t> columns_;  // masks_ transposed: words_ words per line
  std::vector<uint64_t> sites_;    // keep_ transposed
  std::vector<int32_t> starts_;    // analysis_detail::writeLanes8's starts and values
  std::vector<int32_t> values_;
  std::vector<const uint64_t*> rows_;  // the grid's bit row at each step along the plane's lines
  std::vector<int64_t> bases_;         // and the field's (DistanceField::Row::base)
};

// Passes 1 and 2 slice by slice (a Y line lies in its slice, so the slice is transformed along Y while the X pass
// has just left it in cache), then pass 3 row by row. Returns the field's largest finite value.
uint32_t transformBox(const VoxelGrid& g, DistanceField& f, bool to_empty, ProgressGate& gate) {
  const Dims d = f.boxDims();
  const int threads = threadsFor(d.count() / 4);
  std::vector<uint32_t> maxima(size_t(threads), 0);
  std::atomic<int64_t> done{0};
  parallelChunks(0, d.nz, 1, threads, [&](int, int64_t zb, int64_t ze) {
    PlaneLines lines(g, f, 1, to_empty);
    for (int64_t z = zb; z < ze; ++z) {
      if (gate.cancelled()) return;
      rowsX(g, f, to_empty, z);
      lines.transform(z);
      gate.report(0.6 * double(done.fetch_add(1) + 1) / double(d.nz));
    }
  });
  if (gate.cancelled()) return 0;
  done = 0;
  parallelChunks(0, d.ny, 1, threads, [&](int t, int64_t yb, int64_t ye) {
    PlaneLines lines(g, f, 2, to_empty);
    for (int64_t y = yb; y < ye; ++y) {
      if (gate.cancelled()) return;
      maxima[size_t(t)] = std::max(maxima[size_t(t)], lines.transform(y));
      gate.report(0.6 + 0.4 * double(done.fetch_add(1) + 1) / double(d.ny));
    }
  });
  return *std::max_element(maxima.begin(), maxima.end());
}

Result<DistanceField> transform(const VoxelGrid& grid, bool to_empty, bool packed, const ProgressFn& progress) {
  const char* what = to_empty ? "distance transform" : "clearance transform";
  if (grid.empty()) return makeError(ErrorCode::kInvalidArgument, std::string(what) + ": the grid is empty");
  const Box filled = filledBox(grid);
  Box box = filled;
  if (!to_empty && !filled.empty()) box = Box{glm::ivec3(0), glm::ivec3(grid.nx(), grid.ny(), grid.nz())};
  if (box.empty()) {
    DistanceField f(grid.dims(), grid.frame(), glm::ivec3(0), Dims{}, to_empty ? 0 : kInf);
    if (progress && !progress(1.0)) return makeError(ErrorCode::kCancelled, std::string(what) + " cancelled");
    return f;
  }
  const glm::ivec3 size = box.hi - box.lo;
  const Dims dims{size.x, size.y, size.z};
  // packed: a distance field's rows' spans of filled voxels (a clearance field, the whole grid, whose rows' empty
  // voxels mostly run from end to end, is dense)
  DistanceField f = packed ? DistanceField(grid.dims(), grid.frame(), box.lo, dims, 0, filledSpans(grid, box))
                           : DistanceField(grid.dims(), grid.frame(), box.lo, dims, to_empty ? 0 : kInf);
  if (!f.data()) {
    return makeError(ErrorCode::kLimit, std::string(what) + ": cannot allocate " +
                                            std::to_string(f.memoryBytes() >> 20) + " MiB for the distances");
  }
  analysis_detail::adviseHugePages(grid, f, to_empty);
  ProgressGate gate(progress);
  auto cancelled = [&] { return makeError(ErrorCode::kCancelled, std::string(what) + " cancelled"); };
  const uint32_t mx = transformBox(grid, f, to_empty, gate);
  if (gate.cancelled()) return cancelled();
  f.setMaxSquared(mx);
  if (!gate.report(1.0)) return cancelled();
  return f;
}

}  // namespace

Result<DistanceField> computeDistance(const VoxelGrid& grid, const ProgressFn& progress, DistanceLayout layout) {
  return transform(grid, true, layout == DistanceLayout::kPackedRows, progress);
}

Result<DistanceField> computeClearance(const VoxelGrid& grid, const ProgressFn& progress) {
  return transform(grid, false, false, progress);
}

VoxelGrid peelByDistance(const VoxelGrid& grid, const DistanceField& distance, double distance_model) {
  VoxelGrid out = grid;
  if (grid.empty() || distance.boxDims().count() == 0) return out;
  // Largest squared distance (voxel units^2) whose distance in model units, sqrt(s) * h, is at most distance_model.
  const double h = grid.voxelSize();
  auto within = [&](int64_t s) { return std::sqrt(double(s)) * h <= distance_model; };
  int64_t smax = int64_t(std::floor(std::min(distance_model / h * (distance_model / h), 1.0e18)));
  while (within(smax + 1)) ++smax;
  while (smax > 0 && !within(smax)) --smax;
  if (smax <= 0) return out;
  const glm::ivec3 lo = distance.boxMin();
  const Dims d = distance.boxDims();
  const uint32_t* data = distance.data();
  const int threads = threadsFor(d.count() / 4);
  parallelChunks(0, d.nz, 1, threads, [&](int, int64_t zb, int64_t ze) {
    for (int64_t zi = zb; zi < ze; ++zi) {
      const int32_t z = lo.z + int32_t(zi);
      if (!grid.layerAllocated(z)) continue;
      for (int32_t yi = 0; yi < d.ny; ++yi) {
        const DistanceField::Row r = distance.row(yi, zi);
        uint64_t* words = nullptr;
        for (int32_t xi = r.lo; xi < r.hi; ++xi) {
          const uint32_t s = data[r.base + xi];
          if (s == 0 || int64_t(s) > smax) continue;
          if (!words) words = out.mutableRowWords(lo.y + yi, z);
          const int64_t xp = int64_t(lo.x) + xi + 1;
          words[xp >> 6] &= ~(uint64_t(1) << (xp & 63));
        }
      }
    }
  });
  out.releaseEmptyLayers();
  return out;
}

Result<VoxelGrid> peelByDistance(const VoxelGrid& grid, double distance_model, const ProgressFn& progress) {
  if (!(distance_model >= 0) || !std::isfinite(distance_model)) {
    return makeError(ErrorCode::kInvalidArgument, "peel by distance: the distance must be a number >= 0");
  }
  ProgressFn scaled;
  if (progress) scaled = [&](double f) { return progress(0.9 * f); };
  auto dist = computeDistance(grid, scaled);
  if (!dist) return dist.error();
  VoxelGrid out = peelByDistance(grid, *dist, distance_model);
  if (progress && !progress(1.0)) return makeError(ErrorCode::kCancelled, "peel by distance cancelled");
  return out;
}

}  // namespace vox
