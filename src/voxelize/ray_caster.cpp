// Exact ray/triangle crossings for the scan-line voxelizer.
//
// Builds on:
//  - the thesis, section 4.3 (rays parallel to X through the voxel centres, crossings sorted, voxels between an
//    odd and the next even crossing filled; 4.3.2: skip facets whose Y/Z extent misses the ray);
//  - H. Edelsbrunner and E. P. Mücke, "Simulation of Simplicity: a technique to cope with degenerate cases in
//    geometric algorithms", ACM Transactions on Graphics 9(1):66-104, 1990: every centre is displaced by
//    (eps, eps^3, eps^2); a determinant that is exactly zero is decided by the leading coefficient of its expansion
//    in eps, so no ray passes through an edge or a vertex and no centre lies on a face;
//  - J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997, for
//    the exact signs (exact_predicates.h).
//
// Why this is exact and crack-free: a ray crosses triangle T iff the displaced point (v + eps^3, w + eps^2) lies
// inside T's projection onto (v, w). That is decided by three edge tests, each the sign of an orientation
// determinant that is affine in the point, so its SoS sign is determined by the exact value, then by the eps^2
// coefficient, then by the eps^3 coefficient. The test of edge p->q is exactly the negation of the test of q->p,
// so two triangles sharing an edge always disagree about the side: a ray through a shared edge or vertex of a
// closed mesh is counted exactly once per passage. Where along the ray the crossing lies is decided by the exact
// sign of the 3D orientation of T and the centre (orient3d), the centre's own eps in u settling exact ties.
#include "voxelize/ray_caster.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "voxelize/exact_predicates.h"
#include "vox/core/parallel.h"

namespace vox::voxelize_detail {
namespace {

// Side of the displaced ray point r = (v + eps^3, w + eps^2) relative to the directed edge p -> q: the sign of
// det[p - r; q - r]. That determinant is affine in r with d/dw = (q.v - p.v) and d/dv = (p.w - q.w); eps^2 (w)
// dominates eps^3 (v). Zero only when p and q coincide in projection.
inline int edgeSide(double pv, double pw, double qv, double qw, double v, double w) {
  const int s = orient2d(pv, pw, qv, qw, v, w);
  if (s != 0) return s;
  if (qv != pv) return qv > pv ? 1 : -1;
  if (pw != qw) return pw > qw ? 1 : -1;
  return 0;
}

// int32_t(t) clamped to [lo, hi], NaN-safe, without std::floor/ceil (library calls on the x86-64 baseline).
inline int32_t clampedIndex(double t, int32_t lo, int32_t hi) {
  if (!(t > double(lo))) return lo;
  if (!(t < double(hi))) return hi;
  return int32_t(t);
}

// Index of the first centre >= value (n when none): estimated from the grid formula, then settled by exact
// comparisons with the stored centres (non-decreasing), usually one or two.
int32_t firstAtOrAbove(const std::vector<double>& centres, double origin, double inv_h, double value) {
  const int32_t n = int32_t(centres.size());
  // Truncation rather than std::ceil (a library call on the x86-64 baseline), times 1 / h rather than a division:
  // an estimate off by one or two at most, which the comparisons below settle.
  int32_t i = clampedIndex((value - origin) * inv_h + 0.5, 0, n);
  while (i > 0 && centres[size_t(i) - 1] >= value) --i;
  while (i < n && centres[size_t(i)] < value) ++i;
  return i;
}

std::vector<double> centresAlong(const GridPlacement& placement, int axis) {
  const int32_t n = axis == 0 ? placement.dims.nx : axis == 1 ? placement.dims.ny : placement.dims.nz;
  const double origin = placement.frame.origin[axis];
  const double h = placement.frame.voxel_size;
  const double first = placement.first[axis];
  std::vector<double> c(static_cast<size_t>(n));
  // docs/conventions.md, "Grid placement": min + (i + 0.5) * h, in double, exactly so, with i counted on the lattice
  // (first + i), so that a grid over part of the lattice has exactly the lattice's centres.
  for (int32_t i = 0; i < n; ++i) c[size_t(i)] = origin + (double(i) + first + 0.5) * h;
  return c;
}

// How far from an integer t = (value - c[0]) / h, in voxels, must lie for c[floor(t)] < value < c[floor(t) + 1] to
// hold with room to spare for an error of the value (RayCaster::slack_u_). Each centre c[i] = fl(origin +
// fl((i + 0.5) h)) lies within 2.01 u (|origin| + n h) of its exact value, so c[i] - (c[0] + i h) within twice that;
// t computed as fl(fl(value - c[0]) * fl(1 / h)) is within 3.01 u |t| of (value - c[0]) / h, and the callers accept
// only 0 < t < n - 1, so within 3.01 u n. Doubled: the roundings of the slack itself are far inside that.
double gridSlack(const std::vector<double>& c, double origin, int32_t first, double h, double inv_h) {
  const double n = double(c.size());
  // Centres of a grid over part of a lattice (placement.first) are as far from the lattice origin as first + n.
  const double centre_error = 4.02 * kUnitRoundoff * (std::abs(origin) + (n + std::abs(double(first))) * h);
  return 2.0 * (centre_error * inv_h + 3.01 * kUnitRoundoff * n);
}

// Sets f = floor(t) (for t >= 0, within int32_t) and says whether t's fractional part lies farther than delta from 0
// and from 1, so that centres f and f + 1 lie on either side of the value t stands for (gridSlack). False for t < 0,
// where t - f <= 0.
inline bool clearOfCentres(double t, double delta, int32_t& f) {
  f = int32_t(t);
  const double fr = t - double(f);
  return (fr > delta) & (fr < 1.0 - delta);
}

}  // namespace

void CrossingList::grow(size_t needed) {
  const size_t capacity = std::max({needed, 2 * capacity_, size_t(4096)});
  std::unique_ptr<Crossing[]> data(new Crossing[capacity]);
  std::copy(begin(), end(), data.get());
  data_ = std::move(data);
  capacity_ = capacity;
}

RayCaster::RayCaster(const TriangleMesh& mesh, const GridPlacement& placement, RayAxes axes, int threads)
    : mesh_(mesh),
      axes_(axes),
      inv_h_(1.0 / placement.frame.voxel_size),
      // The corner of the grid's voxel (0, 0, 0): only estimates use these, the stored centres settle them.
      origin_u_(placement.frame.origin[axes.u] + placement.first[axes.u] * placement.frame.voxel_size),
      origin_v_(placement.frame.origin[axes.v] + placement.first[axes.v] * placement.frame.voxel_size),
      origin_w_(placement.frame.origin[axes.w] + placement.first[axes.w] * placement.frame.voxel_size) {
  cu_ = centresAlong(placement, axes.u);
  cv_ = centresAlong(placement, axes.v);
  cw_ = centresAlong(placement, axes.w);
  slack_u_ =
      gridSlack(cu_, placement.frame.origin[axes.u], placement.first[axes.u], placement.frame.voxel_size, inv_h_);
  slack_v_ =
      gridSlack(cv_, placement.frame.origin[axes.v], placement.first[axes.v], placement.frame.voxel_size, inv_h_);
  static_assert(kMaxResolution < Crossing::kMaxRays && kMaxResolution < Crossing::kMaxLength);
  assert(cv_.size() < size_t(Crossing::kMaxRays) && cu_.size() < size_t(Crossing::kMaxLength));
  // Counting sort by first row, so a sweep activates triangles in order. Chunks of the input are contiguous and
  // scattered in chunk order, so the result (row, then input order) does not depend on the number of threads.
  // The first pass keeps each triangle's rows (8 bytes, row_lo < 0 for a dropped triangle) so the second only
  // scatters.
  struct Rows {
    int32_t lo = -1, hi = 0;
  };
  const int64_t nt = int64_t(mesh.triangles.size());
  const size_t rows = cw_.size();
  threads = int(std::clamp<int64_t>(threads, 1, std::max<int64_t>(1, nt / 16384)));
  std::vector<Rows> tri_rows(static_cast<size_t>(nt));
  std::vector<std::vector<size_t>> count(size_t(threads), std::vector<size_t>(rows, 0));
  std::vector<std::vector<size_t>> ends(size_t(threads), std::vector<size_t>(rows + 1, 0));  // by one past last row
  forChunks(nt, threads, [&](int c, int64_t begin, int64_t end) {
    auto& mine = count[size_t(c)];
    auto& mine_end = ends[size_t(c)];
    for (int64_t i = begin; i < end; ++i) {
      Tri t;
      if (!classify(size_t(i), t)) continue;
      tri_rows[size_t(i)] = Rows{t.row_lo, t.row_hi};
      ++mine[size_t(t.row_lo)];
      ++mine_end[size_t(t.row_hi)];
    }
  });
  row_start_.assign(rows + 1, 0);
  active_.assign(rows, 0);
  size_t total = 0, active = 0;
  for (size_t r = 0; r < rows; ++r) {
    row_start_[r] = total;
    for (size_t c = 0; c < count.size(); ++c) {
      const size_t n = count[c][r];
      count[c][r] = total;  // becomes the chunk's next slot in row r
      total += n;
      active += n;
      active -= ends[c][r];
    }
    active_[r] = int32_t(active);
  }
  row_start_[rows] = total;
  entries_.resize(total);
  forChunks(nt, threads, [&](int c, int64_t begin, int64_t end) {
    auto& next = count[size_t(c)];
    for (int64_t i = begin; i < end; ++i) {
      const Rows& r = tri_rows[size_t(i)];
      if (r.lo >= 0) entries_[next[size_t(r.lo)]++] = Entry{uint32_t(i), r.hi};
    }
  });
}

bool RayCaster::classify(size_t i, Tri& t) const {
  const Triangle& in = mesh_.triangles[i];
  for (int k = 0; k < 3; ++k) {
    const float* xyz = &in.v[k].x;  // x, y, z are contiguous; glm's operator[] would switch on the index
    t.p[k][0] = xyz[axes_.u];
    t.p[k][1] = xyz[axes_.v];
    t.p[k][2] = xyz[axes_.w];
  }
  // Orientation of the projection = sign of the normal's u component, exactly. Zero area: no displaced ray can be
  // strictly inside (the three edge signs sum to the area), so the triangle is never crossed.
  t.sign = orient2d(t.p[0][1], t.p[0][2], t.p[1][1], t.p[1][2], t.p[2][1], t.p[2][2]);
  if (t.sign == 0) return false;
  // The displaced ray (v + eps^3, w + eps^2) can be inside the projection only when min <= centre < max on both
  // axes: at centre == max it is already past the maximum.
  t.row_lo = firstAtOrAbove(cw_, origin_w_, inv_h_, std::min({t.p[0][2], t.p[1][2], t.p[2][2]}));
  t.row_hi = firstAtOrAbove(cw_, origin_w_, inv_h_, std::max({t.p[0][2], t.p[1][2], t.p[2][2]}));
  if (t.row_lo >= t.row_hi) return false;
  t.ray_lo = firstAtOrAbove(cv_, origin_v_, inv_h_, std::min({t.p[0][1], t.p[1][1], t.p[2][1]}));
  t.ray_hi = firstAtOrAbove(cv_, origin_v_, inv_h_, std::max({t.p[0][1], t.p[1][1], t.p[2][1]}));
  return t.ray_lo < t.ray_hi;
}

RayCaster::RowSweep::RowSweep(const RayCaster& caster, int32_t row_begin, int32_t row_end)
    : caster_(caster), row_(row_begin) {
  // Exactly the most planes any of these rows holds: the vector never grows, so nothing is copied and no smaller
  // blocks are left behind in the heap between the grid's layers.
  const int32_t lo = std::clamp(row_begin, 0, caster.rows()), hi = std::clamp(row_end, lo, caster.rows());
  int32_t most = 0;
  for (int32_t r = lo; r < hi; ++r) most = std::max(most, caster.active_[size_t(r)]);
  planes_.reserve(size_t(most));
  const size_t begin = caster.row_start_[size_t(lo)];
  for (size_t e = 0; e < begin; ++e) {
    if (caster.entries_[e].row_hi > row_begin)
      planes_.emplace_back(caster.entries_[e].triangle, caster.entries_[e].row_hi, caster);
  }
}

void RayCaster::RowSweep::next(CrossingList& out) {
  if (row_ >= caster_.rows()) return;
  const size_t begin = caster_.row_start_[size_t(row_)], end = caster_.row_start_[size_t(row_) + 1];
  // The triangles of a row lie anywhere in the mesh: fetch a few ahead so their cache misses overlap.
  constexpr size_t kAhead = prefetch_distance::kRowTriangles;
  for (size_t e = begin; e < std::min(end, begin + kAhead); ++e) caster_.prefetch(e);
  for (size_t e = begin; e < end; ++e) {
    if (e + kAhead < end) caster_.prefetch(e + kAhead);
    planes_.emplace_back(caster_.entries_[e].triangle, caster_.entries_[e].row_hi, caster_);
  }
  for (size_t k = 0; k < planes_.size();) {
    caster_.rowCrossings(planes_[k], row_, out);
    if (planes_[k].row_hi > row_ + 1) {
      ++k;
    } else {
      // This was the triangle's last row: the last plane takes its place (and is handled next), so a removal moves
      // one plane rather than shifting the rest.
      if (k + 1 != planes_.size()) planes_[k] = planes_.back();
      planes_.pop_back();
    }
  }
  ++row_;
}

inline int32_t RayCaster::firstPast(const Plane& pl, double w_term, double v, double w) const {
  if (pl.fixed_first >= 0) return pl.fixed_first;
  // The crossing lies at u = x_c = a.u - (n.v (v - a.v) + n.w (w - a.w)) / n.u. Centre i = (u_i + eps, v + eps^3,
  // w + eps^2) is past it iff u_i >= x_c (at u_i == x_c the displacement eps along u puts it past). Fast path: x_c
  // in double, within pl.margin of the exact value (see Plane); a centre farther than that from the estimate is
  // decided by comparing doubles.
  const double num = pl.n_v * (v - pl.a[1]) + w_term;
  double x = pl.a[0] - num * pl.inv_nu;
  const double margin = pl.margin;
  // The crossing lies inside the triangle, so clamping to the vertices' u range only moves the estimate closer.
  if (!(x >= pl.umin)) x = pl.umin;  // also catches NaN
  if (!(x <= pl.umax)) x = pl.umax;
  // Exact decision otherwise: orient3d(A, B, C, P) = -sign(n . (P - A)); the centre is past iff n . (P - A) has
  // the sign of n.u or is exactly 0 (then the eps displacement along u, coefficient n.u, decides for "past").
  auto past = [&](int32_t i) {
    const double d = cu_[size_t(i)] - x;
    if (d > margin) return true;
    if (-d > margin) return false;
    return exactPast(pl, i, v, w);
  };
  const int32_t n = length();
  // About ceil((x - u_0) / h); the exact tests below correct any error of the estimate.
  const double t = (x - cu_[0]) * inv_h_;
  int32_t i = clampedIndex(t, 0, n);
  if (i < n && double(i) < t) ++i;
  // Usually centre i is past and centre i - 1 is not, both by more than the margin: one branch, two loads.
  if (i > 0 && i < n && cu_[size_t(i)] - x > margin && x - cu_[size_t(i) - 1] > margin) return i;
  if (i < n && !past(i)) {
    do {
      ++i;
    } while (i < n && !past(i));
  } else {
    while (i > 0 && past(i - 1)) --i;
  }
  return i;
}

void RayCaster::rowCrossings(const Plane& plane, int32_t row, CrossingList& out) const {
  const double w = cw_[size_t(row)];
  // The section of the projection with the line at w, [lo, hi]: the crossed rays of this row are the rays strictly
  // inside it, plus any the exact tests admit at its ends. The row lies in [P0.w, P2.w), so the long edge and one
  // short edge span it (both ends of the section when it is a horizontal edge at w = P0.w = P1.w). Interpolated
  // from the edge's lower end, with 0 <= w - p.w <= q.w - p.w, each end is within about 8 ulps of the largest
  // coordinate involved; the section margin is over a thousand times that. Rays farther than the margin outside
  // [lo, hi] miss the triangle (the closed projection is at positive distance from them, and so from the displaced
  // ray); rays farther than the margin inside cross it (the displaced ray is interior: even where the section is a
  // horizontal edge at w = w_min, the displacement eps^2 along w moves it into the triangle); only rays within the
  // margin of an end need the exact edge tests.
  const double v_long = plane.long_v + (w - plane.long_w) * plane.long_slope;
  const double v_short = w < plane.high_w ? plane.low_v + (w - plane.low_w) * plane.low_slope
                                          : plane.high_v + (w - plane.high_w) * plane.high_slope;
  const double lo = std::min(v_long, v_short), hi = std::max(v_long, v_short);
  const double margin = plane.section_margin;
  const int32_t nv = raysPerRow();
  const double v0 = cv_[0];
  const double* cv = cv_.data();
  int32_t j = 0, j_end = 0;
  // Usually both ends lie inside the grid's rays, each farther than the margin from every centre: in t = (v - v0) /
  // h, farther than delta from an integer (see gridSlack). Then the crossed rays are those from the first centre
  // above lo to the last below hi, counted from the integer parts.
  const double t_lo = (lo - v0) * inv_h_, t_hi = (hi - v0) * inv_h_;
  bool ends_clear = false;
  if (t_lo > 0.0 && t_hi < double(nv - 1)) {  // false for NaN; with lo <= hi, both in (0, nv - 1)
    const double delta = slack_v_ + 2.0 * margin * inv_h_;
    int32_t f_lo, f_hi;
    ends_clear = clearOfCentres(t_lo, delta, f_lo) & clearOfCentres(t_hi, delta, f_hi);
    j = f_lo + 1;
    j_end = f_hi + 1;  // >= j: t_lo <= t_hi
  }
  if (!ends_clear) {
    // The first ray at or above outer_lo, and the first at or above inner_hi, by comparisons with the stored
    // centres: usually ceil((value - v0) / h), confirmed by the centres either side with one predictable branch;
    // otherwise (a value exactly on a centre, or outside the grid) the general search.
    const double outer_lo = lo - margin, outer_hi = hi + margin, inner_lo = lo + margin, inner_hi = hi - margin;
    auto firstRayAtOrAbove = [&](double value) {
      const double t = (value - v0) * inv_h_;
      if (t > 0.0 && t < double(nv - 1)) {
        const int32_t k = int32_t(t) + 1;
        if (cv[k - 1] < value && cv[k] >= value) return k;
      }
      return firstAtOrAbove(cv_, origin_v_, inv_h_, value);
    };
    j = firstRayAtOrAbove(outer_lo);
    j_end = std::max(j, firstRayAtOrAbove(inner_hi));
    // Usually no ray lies within the margin of either end: then rays [j, j_end) are exactly the crossed ones.
    if ((j < nv && cv[j] <= inner_lo) || (j_end < nv && cv[j_end] <= outer_hi)) {
      int32_t k_end = j_end;
      while (k_end < nv && cv[k_end] <= outer_hi) ++k_end;
      exactCrossings(plane, row, j, k_end, out);
      return;
    }
  }
  if (j_end <= j) return;
  Crossing* o = out.append(size_t(j_end - j));
  if (plane.fixed_first >= 0) {
    for (int32_t k = j; k < j_end; ++k) o[k - j] = Crossing{k, plane.fixed_first, plane.sign};
    return;
  }
  if (!std::isfinite(plane.margin) || length() < 2) {
    placeCrossings(plane, row, j, j_end, o);
    return;
  }
  placeRun(plane, row, j, j_end, o);
}

void RayCaster::placeRun(const Plane& plane, int32_t row, int32_t j, int32_t j_end, Crossing* o) const {
  const double w = cw_[size_t(row)];
  const double* cv = cv_.data();
  // firstPast's usual case as straight-line code, two rays at a time where SSE2 is there: the estimate x of each
  // crossing and t = (x - u0) / h, so that centre floor(t) + 1 is the first past it whenever t's fractional part is
  // farther than delta from 0 and from 1 (x is within the plane's margin of the crossing; see gridSlack); a flag
  // records whether every crossing of the run was so. Rarely not; then the run is placed again by firstPast. (A finite
  // margin means n.u is clearly nonzero, so every estimate is finite; it lies in [umin, umax], so t is far inside
  // int32_t's range.)
  const double w_term = plane.n_w * (w - plane.a[2]);  // the part of the crossing's formula fixed by the row
  const double a_u = plane.a[0], a_v = plane.a[1], n_v = plane.n_v, inv_nu = plane.inv_nu;
  const double umin = plane.umin, umax = plane.umax;
  const double u0 = cu_[0], inv_h = inv_h_;
  const double delta = slack_u_ + 2.0 * plane.margin * inv_h;
  const int32_t last = length() - 1;
  bool clear = true;
#if defined(__SSE2__)
  const __m128d va_u = _mm_set1_pd(a_u), va_v = _mm_set1_pd(a_v), vn_v = _mm_set1_pd(n_v);
  const __m128d vw_term = _mm_set1_pd(w_term), vinv_nu = _mm_set1_pd(inv_nu);
  const __m128d vumin = _mm_set1_pd(umin), vumax = _mm_set1_pd(umax), vu0 = _mm_set1_pd(u0);
  const __m128d vinv_h = _mm_set1_pd(inv_h), vdelta = _mm_set1_pd(delta), vbelow = _mm_set1_pd(1.0 - delta);
  const __m128d vlast = _mm_set1_pd(double(last));
  const __m128i one = _mm_set1_epi32(1);
  // The crossings of the rays whose centres are the two lanes of v: their packed values in the two low lanes
  // (`rays`: the rays' bits and the sign bit), and in `ok`, all ones in each lane whose placement is clear.
  auto place = [&](__m128d v, __m128i rays, __m128d& ok) {
    const __m128d q = _mm_mul_pd(_mm_add_pd(_mm_mul_pd(vn_v, _mm_sub_pd(v, va_v)), vw_term), vinv_nu);
    const __m128d x = _mm_min_pd(_mm_max_pd(_mm_sub_pd(va_u, q), vumin), vumax);
    const __m128d t = _mm_mul_pd(_mm_sub_pd(x, vu0), vinv_h);
    // floor(t) where t >= 0; where t < 0, fr <= 0, and where t is NaN or beyond int32_t (INT32_MIN), fr and t fail
    // the tests too
    const __m128i f = _mm_cvttpd_epi32(t);
    const __m128d fr = _mm_sub_pd(t, _mm_cvtepi32_pd(f));
    ok = _mm_and_pd(_mm_and_pd(_mm_cmpgt_pd(fr, vdelta), _mm_cmplt_pd(fr, vbelow)), _mm_cmplt_pd(t, vlast));
    return _mm_or_si128(rays, _mm_slli_epi32(_mm_add_epi32(f, one), 1));
  };
  const uint32_t sign_bit = Crossing{0, 0, plane.sign}.packed();
  __m128i rays = _mm_set_epi32(0, 0, int32_t(uint32_t(j + 1) << 17 | sign_bit), int32_t(uint32_t(j) << 17 | sign_bit));
  const __m128i step = _mm_set1_epi32(2 << 17);
  __m128d all_ok = _mm_castsi128_pd(_mm_set1_epi32(-1)), ok;
  int32_t k = j;
  for (; k + 2 <= j_end; k += 2) {
    _mm_storel_epi64(reinterpret_cast<__m128i*>(o + (k - j)), place(_mm_loadu_pd(cv + k), rays, ok));
    all_ok = _mm_and_pd(all_ok, ok);
    rays = _mm_add_epi32(rays, step);
  }
  clear = _mm_movemask_pd(all_ok) == 3;
  if (k < j_end) {  // the last ray of an odd run, in lane 0 alone
    const uint32_t packed = uint32_t(_mm_cvtsi128_si32(place(_mm_load_sd(cv + k), rays, ok)));
    o[k - j] = Crossing::fromPacked(packed);
    clear &= (_mm_movemask_pd(ok) & 1) != 0;
  }
#else
  for (int32_t k = j; k < j_end; ++k) {
    const double x = std::min(std::max(a_u - (n_v * (cv[k] - a_v) + w_term) * inv_nu, umin), umax);
    int32_t f;
    clear &= clearOfCentres((x - u0) * inv_h, delta, f) & (f < last);
    o[k - j] = Crossing{k, f + 1, plane.sign};
  }
#endif
  if (!clear) placeCrossings(plane, row, j, j_end, o);
}

void RayCaster::exactCrossings(const Plane& plane, int32_t row, int32_t j, int32_t j_end, CrossingList& out) const {
  const double w = cw_[size_t(row)];
  const double w_term = plane.n_w * (w - plane.a[2]);
  const double av = plane.a[1], aw = plane.a[2], bv = plane.b[1], bw = plane.b[2], cv = plane.c[1], cw = plane.c[2];
  for (; j < j_end; ++j) {
    const double v = cv_[size_t(j)];
    if (edgeSide(av, aw, bv, bw, v, w) == plane.sign && edgeSide(bv, bw, cv, cw, v, w) == plane.sign &&
        edgeSide(cv, cw, av, aw, v, w) == plane.sign) {
      out.push_back(Crossing{j, firstPast(plane, w_term, v, w), plane.sign});
    }
  }
}

void RayCaster::placeCrossings(const Plane& plane, int32_t row, int32_t j, int32_t j_end, Crossing* out) const {
  const double w = cw_[size_t(row)];
  const double w_term = plane.n_w * (w - plane.a[2]);
  for (int32_t k = j; k < j_end; ++k) out[k - j] = Crossing{k, firstPast(plane, w_term, cv_[size_t(k)], w), plane.sign};
}

RayCaster::Plane::Plane(uint32_t triangle, int32_t end_row, const RayCaster& caster) : row_hi(end_row) {
  const Triangle& in = caster.mesh_.triangles[triangle];
  const RayAxes& axes = caster.axes_;
  double* const p[3] = {a, b, c};  // A, B, C in (u, v, w)
  for (int k = 0; k < 3; ++k) {
    const float* xyz = &in.v[k].x;  // x, y, z are contiguous; glm's operator[] would switch on the index
    p[k][0] = xyz[axes.u];
    p[k][1] = xyz[axes.v];
    p[k][2] = xyz[axes.w];
  }
  // As classify() found when the caster was built (the same computation): nonzero.
  sign = orient2d(a[1], a[2], b[1], b[2], c[1], c[2]);
  // Normal (B - A) x (C - A) in double, with a bound on each component's error: the differences, the products and
  // the difference of the products each round once (relative error u), so |error| <= (4u + O(u^2)) * (|first
  // product| + |second product|); 8u leaves room for the higher-order terms.
  const double d1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double d2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double prod[6] = {d1[1] * d2[2], d1[2] * d2[1], d1[2] * d2[0], d1[0] * d2[2], d1[0] * d2[1], d1[1] * d2[0]};
  double n[3], n_error[3];
  for (int k = 0; k < 3; ++k) {
    n[k] = prod[2 * k] - prod[2 * k + 1];
    n_error[k] = 8.0 * kUnitRoundoff * (std::abs(prod[2 * k]) + std::abs(prod[2 * k + 1]));
  }
  n_v = n[1];
  n_w = n[2];
  inv_nu = 1.0 / n[0];
  umin = std::min({a[0], b[0], c[0]});
  umax = std::max({a[0], b[0], c[0]});
  const double vmin = std::min({a[1], b[1], c[1]}), vmax = std::max({a[1], b[1], c[1]});
  const double wmin = std::min({a[2], b[2], c[2]}), wmax = std::max({a[2], b[2], c[2]});
  // The crossing of ray (v, w) lies at u = x_c = a.u - (n.v (v - a.v) + n.w (w - a.w)) / n.u, estimated in double
  // by firstPast. Its forward error bound: first-order error analysis of the formula, using the normal's error
  // bounds, with every rounding counted as 8 units (two to four times what the analysis needs) and a final factor
  // 1.01 for the higher-order terms and the rounding of the bound itself. The bound grows with |v - a.v|,
  // |w - a.w|, |q| and |x|, so it is taken once for the triangle at their largest over its extent (every crossing
  // lies in it): one bound for every crossing, larger than each crossing's own, which only sends a few more
  // centres to the exact test. Infinite (always exact) when n.u is not clearly nonzero.
  margin = std::numeric_limits<double>::infinity();
  if (std::isfinite(n[0]) && std::abs(n[0]) > 4.0 * n_error[0]) {
    const double u8 = 8.0 * kUnitRoundoff;
    const double rv = std::max(std::abs(vmin - a[1]), std::abs(vmax - a[1]));
    const double rw = std::max(std::abs(wmin - a[2]), std::abs(wmax - a[2]));
    const double num_error = (n_error[1] + u8 * std::abs(n[1])) * rv + (n_error[2] + u8 * std::abs(n[2])) * rw;
    const double q = (std::abs(n[1]) * rv + std::abs(n[2]) * rw) * std::abs(inv_nu);
    const double x = std::abs(a[0]) + q;
    const double q_error = (num_error + q * n_error[0]) / (std::abs(n[0]) - n_error[0]) + u8 * q;
    margin = (q_error + u8 * x) * 1.01;
    if (!std::isfinite(margin)) margin = std::numeric_limits<double>::infinity();
  }
  // Every crossing lies at some u in [umin, umax] (exactly: it is a point of the triangle), and its first centre
  // past is the first centre u_i >= that u. When no centre lies in [umin, umax) that is the same centre for every
  // ray: i0, the first centre >= umin (centres below i0 are < umin <= u, and u_i0 >= umax >= u). This covers the
  // planes u = const of CAD meshes and, at fine resolutions, every triangle narrower than a voxel along u.
  const int32_t i0 = firstAtOrAbove(caster.cu_, caster.origin_u_, caster.inv_h_, umin);
  fixed_first = i0 == caster.length() || caster.cu_[size_t(i0)] >= umax ? i0 : -1;
  // Rows lie in [wmin, wmax), so this bounds every coordinate a row's section involves.
  section_margin = 1e-12 * std::max({std::abs(vmin), std::abs(vmax), std::abs(wmin), std::abs(wmax)});
  // The section's edges: vertices sorted by w (P0.w < P2.w, since the triangle spans a row).
  const double* s[3] = {a, b, c};
  if (s[1][2] < s[0][2]) std::swap(s[0], s[1]);
  if (s[2][2] < s[1][2]) std::swap(s[1], s[2]);
  if (s[1][2] < s[0][2]) std::swap(s[0], s[1]);
  auto slope = [](const double* from, const double* to) {
    return to[2] != from[2] ? (to[1] - from[1]) / (to[2] - from[2]) : 0.0;
  };
  long_v = s[0][1];
  long_w = s[0][2];
  long_slope = slope(s[0], s[2]);
  low_v = s[0][1];
  low_w = s[0][2];
  low_slope = slope(s[0], s[1]);
  high_v = s[1][1];
  high_w = s[1][2];
  high_slope = slope(s[1], s[2]);
}

bool RayCaster::exactPast(const Plane& pl, int32_t i, double v, double w) const {
  const double p[3] = {cu_[size_t(i)], v, w};
  return orient3d(pl.a, pl.b, pl.c, p) != pl.sign;
}

}  // namespace vox::voxelize_detail
