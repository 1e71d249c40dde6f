// Local thickness (Hildebrand and Rüegsegger 1997), see vox/analysis/thickness.h and docs/accuracy.md.
//
// R(p)^2 = max { s(c) : |p - c|^2 < s(c) } over filled voxels c, s the squared distance. Every filled voxel lies in
// its own ball, so the field starts as s itself and balls are painted over it with max. A ball that lies inside a
// larger ball of a voxel within nine voxels (on each axis) changes nothing and is skipped. The test is exact and
// done on the balls as sets of voxel centres (LatticeCover): far stronger than the continuous
// r(c) + |c - n| <= r(n), which the discrete distance field fails at most voxels (on a ball of radius 11, 4,747 of
// 5,800 voxels survive it, 73 the lattice test). What is left (about the medial surface) is sorted by radius and
// painted largest first; each voxel takes the first ball that reaches it, and balls find the voxels still open
// through a bit pyramid (analysis/open_voxels.h), so a ball inside material already painted costs a few words. A
// larger ball about a neighbour along an axis, painted before, leaves a ball's open voxels on one side of a plane
// (ballWindow), and the walk visits only the box those planes leave: on each axis along which the field grows, the
// box stops at or behind the centre.
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "analysis/huge_array.h"
#include "analysis/morton.h"
#include "analysis/open_voxels.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/thickness.h"
#include "vox/core/parallel.h"
#include "vox/core/prefetch.h"

namespace vox {
namespace {

using analysis_detail::ProgressGate;

// True when the ball of squared radius sc lies inside the ball of squared radius sn whose centre is at squared
// distance d2, as continuous balls: sqrt(sc) + sqrt(d2) <= sqrt(sn)  <=>  sn - sc - d2 >= 0 and
// 4 sc d2 <= (sn - sc - d2)^2.
inline bool ballInside(int64_t sc, int64_t sn, int64_t d2) {
  const int64_t rhs = sn - sc - d2;
  return rhs >= 0 && 4 * sc * d2 <= rhs * rhs;
}

struct Offset {
  int32_t dx, dy, dz, d2;
  int32_t cls;    // index of its class (sorted absolute components) in LatticeCover
  int64_t delta;  // dx + nx dy + plane dz: the step in the field's memory
};

// The same question for the balls as sets of voxel centres, which is what painting uses (the open ball of squared
// radius s holds the offsets e with |e|^2 < s, and s is a lattice shell itself, the nearest empty voxel, so its
// lattice ball is noticeably smaller than the continuous one): ball(c) lies in ball(c + d) iff
// max { |e - d|^2 : |e|^2 < sc } < sn. far[k][sc] holds that maximum for the offset class k, for sc up to a limit;
// larger balls fall back to the continuous test (exact too, only weaker).
class LatticeCover {
 public:
  static constexpr int64_t kMaxTable = int64_t(1) << 18;  // balls up to radius 512: 512 KiB per class
  // Neighbours up to kReach voxels away on each axis are tried (219 offset classes, 6,858 offsets): a ball that is
  // not inside its face or diagonal neighbour's is often inside one a few voxels farther along the gradient, and
  // every ball dropped here saves painting it; a farther reach drops few more.
  static constexpr int kReach = 9;
  static constexpr int kClasses = 219;  // (a, b, c) with kReach >= a >= 1, a >= b >= c >= 0
  // far - s below 2 r |d| + |d|^2 with r <= 512 and |d| <= sqrt(3) kReach < 2 kReach: 16 bits hold it
  static_assert(2 * 512 * (2 * kReach) + 3 * kReach * kReach < INT16_MAX);
  explicit LatticeCover(int64_t max_s)
      : limit_(std::min(max_s, kMaxTable)),
        far_((size_t(limit_) + 1) * size_t(kClasses)),
        columns_((size_t(limit_) + 1) * size_t(kClasses)) {
    const int K = kReach;
    for (int a = 1; a <= K; ++a)
      for (int b = 0; b <= a; ++b)
        for (int c = 0; c <= b; ++c) cls_.push_back({a, b, c});
    const size_t n = cls_.size();
    static_assert(kClasses == kReach * (kReach + 1) * (kReach + 2) / 6 + kReach * (kReach + 1) / 2 + kReach);
    parallelChunks(0, int64_t(n), 1, threadsFor(limit_ * int64_t(n)), [&](int, int64_t kb, int64_t ke) {
      std::vector<int64_t> f;
      for (int64_t k = kb; k < ke; ++k) {
        f.assign(size_t(limit_) + 1, INT64_MIN);
        const int64_t rmax = int64_t(std::sqrt(double(limit_))) + 1;
        const auto& d = cls_[size_t(k)];
        // e with ex >= ey >= ez >= 0 only: among the offsets with the same components in any order and signs, the
        // one farthest from -d is the one whose components are ordered as d's, d[0] >= d[1] >= d[2] >= 0 (the
        // rearrangement inequality), which leaves a sixth of the octant to visit
        for (int64_t ex = 0; ex <= rmax; ++ex)
          for (int64_t ey = 0; ey <= ex && ex * ex + ey * ey < limit_; ++ey)
            for (int64_t ez = 0; ez <= ey && ex * ex + ey * ey + ez * ez < limit_; ++ez) {
              const int64_t m = ex * ex + ey * ey + ez * ez;
              const int64_t a = ex + d[0], b = ey + d[1], c = ez + d[2];
              f[size_t(m) + 1] = std::max(f[size_t(m) + 1], a * a + b * b + c * c);
            }
        for (size_t i = 1; i < f.size(); ++i) f[i] = std::max(f[i], f[i - 1]);
        for (size_t i = 1; i < f.size(); ++i) {
          far_[i * n + size_t(k)] = int16_t(f[i] - int64_t(i));
          columns_[size_t(k) * f.size() + i] = int16_t(f[i] - int64_t(i));
        }
      }
    });
  }
  // Asks for the table's row of balls of squared radius sc ahead of the tests that read it.
  void prefetch(int64_t sc) const {
    if (sc <= limit_) prefetchBytes(far_.data() + size_t(sc) * kClasses, kClasses * sizeof(int16_t));
  }
  int64_t limit() const { return limit_; }
  // The table's row of balls of squared radius sc <= limit(), by class, and its column of class k, by squared radius:
  // far(d, sc) = row(sc)[k] + sc = column(k)[sc] + sc for the offsets d of class k.
  const int16_t* row(int64_t sc) const { return far_.data() + size_t(sc) * kClasses; }
  const int16_t* column(int k) const { return columns_.data() + size_t(k) * size_t(limit_ + 1); }
  int classOf(int dx, int dy, int dz) const {
    int a[3] = {std::abs(dx), std::abs(dy), std::abs(dz)};
    std::sort(a, a + 3, [](int u, int v) { return u > v; });
    for (size_t k = 0; k < cls_.size(); ++k)
      if (a[0] == cls_[k][0] && a[1] == cls_[k][1] && a[2] == cls_[k][2]) return int(k);
    return -1;
  }
  // True when every voxel of ball(c) (squared radius sc) lies in ball(n) (sn), n at offset o from c.
  bool inside(int64_t sc, int64_t sn, const Offset& o) const {
    if (sn <= sc) return false;
    if (sc <= limit_) return far_[size_t(sc) * kClasses + size_t(o.cls)] + sc < sn;
    return ballInside(sc, sn, o.d2);
  }

 private:
  int64_t limit_;
  std::vector<std::array<int, 3>> cls_;
  // far[s][class] - s, classes adjacent: one centre's tests share cache lines. The difference fits 16 bits: it lies
  // between -3 (the gap from s down to the lattice shell below it) and 2 r |d| + |d|^2 <= 2 * 512 * 15.6 + 243 for
  // the tabled balls (r <= 512) and offsets up to 9 voxels on each axis.
  analysis_detail::HugeArray<int16_t> far_;  // read at scattered rows: on 2 MiB pages where the kernel gives them
  // The same values by class: a voxel's first tests try one class each, the offsets that held its neighbours' balls,
  // and a class's column (200 KB at R = 1000) stays in the caches where the rows of the table (44 MB) do not. (The
  // table twice: 88 MB at R = 1000, 230 MB for balls up to radius 512.)
  analysis_detail::HugeArray<int16_t> columns_;
};

// Neighbours within kReach voxels on each axis, nearest first (the face neighbour in the direction of the gradient
// usually settles it at once), in lists by the direction of the distance field's gradient: a ball lies inside a
// neighbour's only when the neighbour is about |d| deeper (the field grows by at most 1 per voxel), that is along
// the gradient, so a list holds the offsets within kConeDeg of one of the directions (a, b, c), components in
// -kSteps..kSteps, and the centre tries the list of its rounded gradient (central differences). Where those are all
// zero (a crest between equal neighbours: the middle of a plate), it tries the list toward its largest neighbour
// of the 26, or only the 26 where none is larger (all 6,858 offsets there took plate_holes' containment test a
// billion tries for 160 k such voxels, nearly all of them centres). Any offset left out only keeps a ball that could
// have been dropped: the result is the same. A narrow cone about many directions keeps hardly more balls than a
// wide one about few, for far fewer tries.
class RidgeOffsets {
 public:
  static constexpr int kSteps = 6;
  static constexpr double kConeDeg = 15.0;
  // nx and plane: the strides of the field, for each offset's step in memory (Offset::delta).
  RidgeOffsets(const LatticeCover& cover, int64_t nx, int64_t plane) {
    const int K = LatticeCover::kReach;
    for (int dz = -K; dz <= K; ++dz)
      for (int dy = -K; dy <= K; ++dy)
        for (int dx = -K; dx <= K; ++dx) {
          const int d2 = dx * dx + dy * dy + dz * dz;
          if (d2 > 0) all_.push_back(Offset{dx, dy, dz, d2, cover.classOf(dx, dy, dz), dx + nx * dy + plane * dz});
        }
    std::stable_sort(all_.begin(), all_.end(), [](const Offset& a, const Offset& b) { return a.d2 < b.d2; });
    const double cos_cone = std::cos(kConeDeg * 3.14159265358979 / 180.0);
    lists_.resize(size_t(kSide * kSide * kSide));
    for (int c = -kSteps; c <= kSteps; ++c)
      for (int b = -kSteps; b <= kSteps; ++b)
        for (int a = -kSteps; a <= kSteps; ++a) {
          if (!a && !b && !c) continue;
          std::vector<Offset>& list = lists_[size_t(key(a, b, c))];
          const double n = std::sqrt(double(a * a + b * b + c * c));
          for (const Offset& o : all_) {
            const double dot = (a * o.dx + b * o.dy + c * o.dz) / (n * std::sqrt(double(o.d2)));
            if (o.d2 <= 3 || dot >= cos_cone) list.push_back(o);
          }
        }
    for (const Offset& o : all_)
      if (o.d2 <= 3) lists_[size_t(key(0, 0, 0))].push_back(o);
    // (a box whose steps reach past 32 bits, slices of more than 238 M voxels, keeps no steps: stepsFit())
    steps_fit_ = int64_t(K) * (1 + nx + plane) <= INT32_MAX;
    steps_.resize(lists_.size());
    for (size_t i = 0; i < lists_.size() && steps_fit_; ++i)
      for (const Offset& o : lists_[i]) steps_[i].push_back(Step{int32_t(o.delta), o.cls});
  }
  // An offset as the test inside the box reads it: its step in memory and its class, in 8 bytes (the lists of steps
  // take 2.4 MB, those of offsets 10 MB).
  struct Step {
    int32_t delta, cls;
  };
  // The list for a voxel of squared distance s, field(dx, dy, dz) the field at an offset from it (0 outside the box).
  template <class Field>
  size_t listFor(Field&& field, int64_t s) const {
    const int64_t gx = field(1, 0, 0) - field(-1, 0, 0), gy = field(0, 1, 0) - field(0, -1, 0),
                  gz = field(0, 0, 1) - field(0, 0, -1);
    if (gx || gy || gz) return index(gx, gy, gz);
    int64_t best = s, bx = 0, by = 0, bz = 0;
    for (int64_t dz = -1; dz <= 1; ++dz)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dx = -1; dx <= 1; ++dx) {
          const int64_t v = field(dx, dy, dz);
          if (v > best) {
            best = v;
            bx = dx;
            by = dy;
            bz = dz;
          }
        }
    return index(bx, by, bz);  // (the 26 alone where none is larger)
  }
  const std::vector<Offset>& offsets(size_t list) const { return lists_[list]; }
  const std::vector<Step>& steps(size_t list) const { return steps_[list]; }
  bool stepsFit() const { return steps_fit_; }

 private:
  static constexpr int kSide = 2 * kSteps + 1;
  static int key(int a, int b, int c) { return (a + kSteps) + kSide * (b + kSteps) + kSide * kSide * (c + kSteps); }
  size_t index(int64_t gx, int64_t gy, int64_t gz) const {
    const int64_t m = std::max({std::abs(gx), std::abs(gy), std::abs(gz)});
    if (m == 0) return size_t(key(0, 0, 0));  // (the 26 neighbours)
    // round(kSteps g / m), one division for the three (which list a centre tries only changes how soon it is dropped)
    const double scale = double(kSteps) / double(m);
    auto q = [scale](int64_t g) {
      const double v = double(g) * scale;
      return int(v + (v < 0 ? -0.5 : 0.5));
    };
    return size_t(key(q(gx), q(gy), q(gz)));
  }
  std::vector<Offset> all_;
  std::vector<std::vector<Offset>> lists_;
  std::vector<std::vector<Step>> steps_;  // lists_ as steps
  bool steps_fit_ = true;
};

struct Centre {
  uint32_t s;
  uint16_t x, y, z;      // box coordinates (dimensions are at most VoxelGrid::kMaxDim)
  int16_t lo[3], hi[3];  // the ball's window (ballWindow): offsets from the centre on each axis, inclusive
};

// The box about a ball's centre c (squared radius s) outside which the ball will find no voxel open when it is
// painted. A voxel within the ball of squared radius s_q > s about any voxel q is painted before ball(c), by
// induction on the balls larger than s, walked before it: q's ball is walked, or lies inside a larger ball that is
// (the containment test drops a ball only for a larger one), and a walked ball leaves no voxel of its own ball open
// (those outside its window were painted already, by the same argument). So an open voxel p of ball(c) has
// |p - c|^2 < s and |p - q|^2 >= s_q. For q = c + k u (u a unit axis vector, k > 0),
// |p - q|^2 - |p - c|^2 = k^2 - 2 k u.(p - c), and the two give 2 k u.(p - c) < k^2 - (s_q - s): along that axis
// the open voxels lie on c's side of a plane, which cuts the ball at or behind its centre wherever the field grows
// toward q by at least k^2. The window is the tightest such bound on each axis, both ways, over the neighbours
// within kWindowReach voxels; field(dx, dy, dz) gives the squared distance at that offset from c (0 outside the
// box). A ball the planes leave no voxel gets an empty window (lo > hi).
constexpr int kWindowReach = LatticeCover::kReach;  // (the containment test's box check lets both read that far)
template <class Field>
void ballWindow(Centre& c, Field&& field) {
  const int64_t s = c.s;
  const int64_t r = int64_t(std::sqrt(double(s))) + 1;  // at least the ball's reach (int16: r <= 2^14)
  for (int a = 0; a < 3; ++a) {
    int64_t lo = -r, hi = r;
    for (int64_t k = 1; k <= kWindowReach; ++k) {
      int64_t e[3] = {0, 0, 0};
      for (const int64_t sign : {1, -1}) {
        e[a] = sign * k;
        const int64_t sq = field(e[0], e[1], e[2]);
        if (sq <= s) continue;
        // the largest integer u with 2 k u < k^2 - (sq - s), that is u <= floor((k^2 - (sq - s) - 1) / 2k)
        // (the floor of the quotient in doubles, without an integer division: exact, since |num| < 2^53 and a
        // quotient that is not an integer lies at least 1/den from one)
        const int64_t num = k * k - (sq - s) - 1, den = 2 * k;
        const double q = double(num) / double(den);
        const int64_t u = int64_t(q) - (double(int64_t(q)) > q);
        if (sign > 0) {
          hi = std::min(hi, u);
        } else {
          lo = std::max(lo, -u);
        }
      }
    }
    if (lo > hi) {
      lo = 1;
      hi = 0;
    }
    c.lo[a] = int16_t(lo);
    c.hi[a] = int16_t(hi);
  }
}

ThicknessStats statistics(const DistanceField& r, int32_t bins) {
  ThicknessStats st;
  const double h = r.voxelSize();
  const double max_t = 2.0 * std::sqrt(double(r.maxSquared())) * h;
  bins = std::max(bins, 1);
  st.edges.resize(size_t(bins) + 1);
  for (int32_t i = 0; i <= bins; ++i) st.edges[size_t(i)] = max_t * i / bins;
  st.counts.assign(size_t(bins), 0);
  const Dims d = r.boxDims();
  if (d.count() == 0) return st;
  const int threads = threadsFor(d.count() / 4);
  const int64_t plane = int64_t(d.nx) * d.ny;
  auto binOf = [&](double t) {
    const int64_t b = max_t > 0 ? int64_t(t / max_t * bins) : 0;
    return size_t(std::clamp<int64_t>(b, 0, bins - 1));
  };
  uint32_t mn = UINT32_MAX;
  double sum = 0.0;
  if (r.maxSquared() <= (uint32_t(1) << 19)) {
    // The voxels counted by value, each thread on its own (4 MiB at most), then every value's thickness once, in
    // order: exact counts, and sums that do not depend on the thread split.
    std::vector<std::vector<int64_t>> per(static_cast<size_t>(threads),
                                          std::vector<int64_t>(size_t(r.maxSquared()) + 1, 0));
    parallelChunks(0, d.nz, 1, threads, [&](int t, int64_t zb, int64_t ze) {
      std::vector<int64_t>& count = per[size_t(t)];
      const uint32_t* v = r.data() + zb * plane;
      for (int64_t i = 0; i < (ze - zb) * plane; ++i) ++count[v[i]];
    });
    for (size_t value = 1; value <= r.maxSquared(); ++value) {
      int64_t n = 0;
      for (const auto& count : per) n += count[value];
      if (!n) continue;
      const double t = 2.0 * std::sqrt(double(value)) * h;
      st.voxels += n;
      sum += double(n) * t;
      mn = std::min(mn, uint32_t(value));
      st.counts[binOf(t)] += n;
    }
  } else {
    struct Slice {
      int64_t count = 0;
      double sum = 0.0;
      uint32_t min = UINT32_MAX;
      std::vector<int64_t> counts;
    };
    std::vector<Slice> slices(size_t(d.nz));
    parallelChunks(0, d.nz, 1, threads, [&](int, int64_t zb, int64_t ze) {
      for (int64_t z = zb; z < ze; ++z) {
        Slice& sl = slices[size_t(z)];
        sl.counts.assign(size_t(bins), 0);
        const uint32_t* v = r.data() + z * plane;
        for (int64_t i = 0; i < plane; ++i) {
          if (!v[i]) continue;
          const double t = 2.0 * std::sqrt(double(v[i])) * h;
          ++sl.count;
          sl.sum += t;
          sl.min = std::min(sl.min, v[i]);
          ++sl.counts[binOf(t)];
        }
      }
    });
    for (const Slice& sl : slices) {  // in order: the sums do not depend on the thread split
      st.voxels += sl.count;
      sum += sl.sum;
      mn = std::min(mn, sl.min);
      for (int32_t b = 0; b < bins; ++b) st.counts[size_t(b)] += sl.counts[size_t(b)];
    }
  }
  if (st.voxels > 0) {
    st.min = 2.0 * std::sqrt(double(mn)) * h;
    st.max = max_t;
    st.mean = sum / double(st.voxels);
  }
  return st;
}

}  // namespace

namespace {

// Step 1 of local thickness: the centres whose ball is not inside a neighbour's larger ball, per slice. The box is
// walked in slabs of up to 8 slices, each in columns kTile voxels wide, row by row and in a row slice by slice: what
// the offsets read about one row of a column, 19 rows of 82 voxels in each of the slab's slices and the 18 about them,
// stays in the second-level cache (slice by slice, every row would be read again for each of the 19 slices about it).
// A voxel first tries the offsets that held its neighbours' balls along x and along y, on the table's columns (cheap,
// and they settle most voxels); the rest then try the list of their gradient on the table's rows, each row asked for
// two such voxels ahead.
class CentreSearch {
 public:
  static constexpr int64_t kTile = 64;
  static constexpr int64_t kAhead = prefetch_distance::kBallTableRows;
  using Step = RidgeOffsets::Step;

  CentreSearch(DistanceField& f, ProgressGate& gate, int threads)
      : d_(f.boxDims()),
        nx_(d_.nx),
        ny_(d_.ny),
        nz_(d_.nz),
        plane_(nx_ * ny_),
        data_(f.data()),
        cover_(int64_t(f.maxSquared())),
        ridge_(cover_, nx_, plane_),
        gate_(gate),
        threads_(threads),
        slab_(std::clamp<int64_t>(nz_ / (16 * threads), 1, 8)),  // (many slabs a thread: balanced)
        buckets_(static_cast<size_t>(nz_)) {}

  // The centres found, per slice (empty when cancelled).
  std::vector<std::vector<Centre>> run() {
    const int64_t slabs = (nz_ + slab_ - 1) / slab_;
    parallelChunks(0, slabs, 1, threads_, [&](int, int64_t kb, int64_t ke) {
      // the step that held each voxel's ball in the row before (y - 1) of the column, for each slice of the slab
      std::vector<const Step*> above(size_t(kTile * slab_));
      for (int64_t k = kb; k < ke; ++k) {
        if (gate_.cancelled()) return;
        const int64_t z0 = k * slab_, z1 = std::min(nz_, z0 + slab_);
        for (int64_t x0 = 0; x0 < nx_; x0 += kTile) {
          std::fill(above.begin(), above.end(), nullptr);
          for (int64_t y = 0; y < ny_; ++y)
            for (int64_t z = z0; z < z1; ++z) row(x0, y, z, above.data() + (z - z0) * kTile);
        }
        gate_.report(0.3 * double(done_.fetch_add(z1 - z0) + (z1 - z0)) / double(nz_));
      }
    });
    return std::move(buckets_);
  }

 private:
  static constexpr int64_t K = LatticeCover::kReach;  // (= kWindowReach)

  int64_t at(int64_t x, int64_t y, int64_t z) const {
    if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return 0;
    return data_[x + nx_ * y + plane_ * z];
  }

  // The test anywhere in the box (offsets that leave it read 0), for any ball (those beyond the table too).
  bool heldAnywhere(int64_t x, int64_t y, int64_t z, int64_t s) const {
    const size_t list =
        ridge_.listFor([&](int64_t dx, int64_t dy, int64_t dz) { return at(x + dx, y + dy, z + dz); }, s);
    for (const Offset& o : ridge_.offsets(list))
      if (cover_.inside(s, at(x + o.dx, y + o.dy, z + o.dz), o)) return true;
    return false;
  }

  void keep(int64_t x, int64_t y, int64_t z, int64_t s, bool interior) {
    Centre c{uint32_t(s), uint16_t(x), uint16_t(y), uint16_t(z), {}, {}};
    if (interior) {
      const uint32_t* here = data_ + x + nx_ * y + plane_ * z;
      ballWindow(c, [&](int64_t dx, int64_t dy, int64_t dz) { return here[dx + nx_ * dy + plane_ * dz]; });
    } else {
      ballWindow(c, [&](int64_t dx, int64_t dy, int64_t dz) { return at(x + dx, y + dy, z + dz); });
    }
    buckets_[size_t(z)].push_back(c);
  }

  // The row y of slice z within the column from x0; up[x - x0]: the step that held each voxel's ball in the row
  // before, updated.
  void row(int64_t x0, int64_t y, int64_t z, const Step** up) {
    const int64_t x1 = std::min(nx_, x0 + kTile);
    const uint32_t* row = data_ + plane_ * z + nx_ * y;
    if (y < K || z < K || y >= ny_ - K || z >= nz_ - K || !ridge_.stepsFit()) {  // offsets may leave the box
      for (int64_t x = x0; x < x1; ++x)
        if (row[x] && !heldAnywhere(x, y, z, row[x])) keep(x, y, z, row[x], false);
      return;
    }
    std::array<int32_t, kTile> rest;  // the row's voxels left to the second pass (the first n written)
    const int n = firstPass(row, x0, x1, up, rest);
    secondPass(row, x0, y, z, up, rest, n);
  }

  // The steps that held the neighbours before along x and y, where no offset leaves the box and the table holds the
  // ball; returns how many voxels are left (in `rest`).
  int firstPass(const uint32_t* row, int64_t x0, int64_t x1, const Step** up, std::array<int32_t, kTile>& rest) const {
    const Step* last = nullptr;
    int n = 0;
    for (int64_t x = x0; x < x1; ++x) {
      const int64_t s = row[x];
      if (!s) {
        up[x - x0] = nullptr;
        continue;
      }
      if (x >= K && x < nx_ - K && s <= cover_.limit()) {
        const uint32_t* here = row + x;
        auto holds = [&](const Step* o) {
          const int64_t sn = here[o->delta];
          return (sn > s) & (cover_.column(o->cls)[s] + s < sn);
        };
        if (last && holds(last)) {
          up[x - x0] = last;
          continue;
        }
        if (up[x - x0] && holds(up[x - x0])) {
          last = up[x - x0];
          continue;
        }
      }
      rest[size_t(n++)] = int32_t(x);
    }
    return n;
  }

  // The voxels the first pass left: the step that held the voxel before it in this pass, then the offsets of its
  // gradient.
  void secondPass(const uint32_t* row, int64_t x0, int64_t y, int64_t z, const Step** up,
                  const std::array<int32_t, kTile>& rest, int n) {
    const Step* before = nullptr;
    for (int i = 0; i < std::min<int>(n, kAhead); ++i) cover_.prefetch(row[rest[size_t(i)]]);
    for (int i = 0; i < n; ++i) {
      if (i + kAhead < n) cover_.prefetch(row[rest[size_t(i + kAhead)]]);
      const int64_t x = rest[size_t(i)], s = row[x];
      up[x - x0] = nullptr;
      const bool interior = x >= K && x < nx_ - K;
      if (!interior || s > cover_.limit()) {
        if (!heldAnywhere(x, y, z, s)) keep(x, y, z, s, interior);
        continue;
      }
      const uint32_t* here = row + x;
      const int16_t* far = cover_.row(s);
      const size_t list = ridge_.listFor(
          [&](int64_t dx, int64_t dy, int64_t dz) { return int64_t(here[dx + nx_ * dy + plane_ * dz]); }, s);
      auto holds = [&](const Step& o) {  // (both worked out: one branch, mostly not taken)
        const int64_t sn = here[o.delta];
        return (sn > s) & (far[o.cls] + s < sn);
      };
      const Step* hit = before && holds(*before) ? before : nullptr;
      if (!hit) {
        for (const Step& o : ridge_.steps(list)) {
          if (holds(o)) {
            hit = &o;
            break;
          }
        }
      }
      if (hit) {
        up[x - x0] = before = hit;
      } else {
        keep(x, y, z, s, true);
      }
    }
  }

  const Dims d_;
  const int64_t nx_, ny_, nz_, plane_;
  const uint32_t* data_;
  const LatticeCover cover_;
  const RidgeOffsets ridge_;
  ProgressGate& gate_;
  const int threads_;
  const int64_t slab_;
  std::vector<std::vector<Centre>> buckets_;
  std::atomic<int64_t> done_{0};
};

// All centres, largest ball first (a counting sort by s), balls of one size in Morton order: the order among equal
// balls does not change the result, and neighbours in space walk the same bricks while they are cached.
std::vector<Centre> orderCentres(std::vector<std::vector<Centre>>& buckets, uint32_t max_squared) {
  std::vector<Centre> centres;
  std::vector<int64_t> start(size_t(max_squared) + 2, 0);
  for (const auto& b : buckets)
    for (const Centre& c : b) ++start[size_t(max_squared - c.s) + 1];
  for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  const std::vector<int64_t> first = start;
  centres.resize(size_t(start.back()));
  for (auto& b : buckets) {
    for (const Centre& c : b) centres[size_t(start[size_t(max_squared - c.s)]++)] = c;
    std::vector<Centre>().swap(b);
  }
  auto morton = [](const Centre& c) { return analysis_detail::mortonCode(c.x, c.y, c.z); };
  const int64_t values = int64_t(first.size()) - 1;
  parallelChunks(0, values, 1, threadsFor(int64_t(centres.size())), [&](int, int64_t vb, int64_t ve) {
    for (int64_t v = vb; v < ve; ++v) {
      std::sort(centres.begin() + first[size_t(v)], centres.begin() + first[size_t(v) + 1],
                [&](const Centre& a, const Centre& b) { return morton(a) < morton(b); });
    }
  });
  return centres;
}

// Step 2: paint, largest ball first; a voxel takes the first ball that reaches it and is never visited again. Each
// thread walks the whole list of balls and paints only the voxels it owns (analysis/open_voxels.h), each ball within
// its window.
void paintBalls(DistanceField& f, const std::vector<Centre>& centres, const ThicknessParams& params, ProgressGate& gate,
                int threads) {
  const Dims d = f.boxDims();
  const int64_t nx = d.nx, plane = int64_t(d.nx) * d.ny;
  uint32_t* data = f.data();
  analysis_detail::OpenVoxels open(
      d, threads, [&](int64_t x, int64_t y, int64_t z) { return data[x + nx * y + plane * z] != 0; },
      params.simd == ThicknessParams::Simd::kSse2 ? analysis_detail::OpenVoxels::Simd::kSse2
                                                  : analysis_detail::OpenVoxels::Simd::kAuto);
  const int64_t total_centres = int64_t(centres.size());
  forChunks(threads, threads, [&](int t, int64_t, int64_t) {
    for (int64_t k = 0; k < total_centres && open.anyOpen(t); ++k) {
      if ((k & 4095) == 0) {
        if (gate.cancelled()) return;
        if (t == 0) gate.report(0.3 + 0.65 * double(k) / double(total_centres));
      }
      const Centre c = centres[size_t(k)];
      const uint32_t s = c.s;
      const analysis_detail::OpenVoxels::Window w{{c.lo[0], c.lo[1], c.lo[2]}, {c.hi[0], c.hi[1], c.hi[2]}};
      open.paintBall(t, c.x, c.y, c.z, s, w,
                     [&](int64_t x, int64_t y, int64_t z) { data[x + nx * y + plane * z] = s; });
    }
  });
}

}  // namespace

Result<Thickness> computeThickness(DistanceField&& distance, const ThicknessParams& params,
                                   const ProgressFn& progress) {
  if (distance.outside() != 0) {
    return makeError(ErrorCode::kInvalidArgument, "local thickness needs a distance field, not a clearance field");
  }
  Thickness out;
  if (distance.isDense()) {
    out.radius = std::move(distance);
  } else {  // the painting steps through the box by constant strides
    out.radius = distance.denseCopy();
    distance = DistanceField();
    if (out.radius.boxDims().count() > 0 && !out.radius.data()) {
      return makeError(ErrorCode::kLimit, "local thickness: cannot allocate " +
                                              std::to_string(out.radius.boxDims().count() >> 18) +
                                              " MiB for the field");
    }
  }
  DistanceField& f = out.radius;
  ProgressGate gate(progress);
  auto cancelled = [] { return makeError(ErrorCode::kCancelled, "local thickness cancelled"); };
  if (f.boxDims().count() > 0) {
    const int threads = threadsFor(f.boxDims().count() / 4);
    std::vector<std::vector<Centre>> buckets = CentreSearch(f, gate, threads).run();
    if (gate.cancelled()) return cancelled();
    const std::vector<Centre> centres = orderCentres(buckets, f.maxSquared());
    out.ball_centres = int64_t(centres.size());
    paintBalls(f, centres, params, gate, threads);
    if (gate.cancelled()) return cancelled();
  }
  out.stats = statistics(f, params.histogram_bins);
  if (!gate.report(1.0)) return cancelled();
  return out;
}

Result<Thickness> computeThickness(const DistanceField& distance, const ThicknessParams& params,
                                   const ProgressFn& progress) {
  DistanceField copy = distance.denseCopy();
  if (distance.boxDims().count() > 0 && !copy.data()) {
    return makeError(ErrorCode::kLimit, "local thickness: cannot allocate " +
                                            std::to_string(distance.boxDims().count() >> 18) + " MiB for the field");
  }
  return computeThickness(std::move(copy), params, progress);
}

}  // namespace vox
