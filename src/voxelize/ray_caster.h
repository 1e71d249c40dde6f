#pragma once
// Exact crossings of a family of axis-parallel rays with a triangle soup (the scan-line step of thesis 4.3.1-4.3.2,
// made exact with Simulation of Simplicity). Internal to the voxelize module.
//
// A ray family is given by three axes (u, v, w): the rays run along u through the voxel centres of the (v, w)
// plane. Rows are indexed by w and are the unit of parallel work; the rays of a row are indexed by v. Every
// centre (and so every ray) is displaced by (eps, eps^3, eps^2) in (u, v, w), eps -> 0+. For rays along X this is
// exactly the tie rule of docs/conventions.md, "Grid placement"; the Y and Z families used by vote mode apply the same
// displacement in their own (u, v, w) frame (see RayAxes), which is just as consistent, so every closed mesh stays
// crack-free along them too.
#include <cstdint>
#include <memory>
#include <vector>

#include "vox/core/grid_placement.h"
#include "vox/core/mesh.h"
#include "vox/core/prefetch.h"

namespace vox::voxelize_detail {

// Indices (0 = x, 1 = y, 2 = z) of the ray axis u, the in-row axis v and the row axis w.
struct RayAxes {
  int u, v, w;
};
inline constexpr RayAxes kRaysAlongX{0, 1, 2};  // rows are Z layers, rays within a row step along Y
inline constexpr RayAxes kRaysAlongY{1, 0, 2};  // rows are Z layers, rays within a row step along X
inline constexpr RayAxes kRaysAlongZ{2, 0, 1};  // rows are Y rows, rays within a row step along X

// One crossing of one ray with one triangle, packed into 32 bits (ray, then first voxel, then sign, from the high
// bits down) so that a row's crossings move and sort cheaply: comparing packed values orders them by ray, then along
// the ray. Needs rays < 2^15 per row and ray lengths <= 65535 (voxmod's grids are at most kMaxResolution = 16384).
class Crossing {
 public:
  static constexpr int32_t kMaxRays = int32_t(1) << 15;
  static constexpr int32_t kMaxLength = 0xFFFF;
  Crossing() = default;
  Crossing(int32_t ray, int32_t first, int32_t sign)
      : bits_(uint32_t(ray) << 17 | uint32_t(first) << 1 | (sign > 0 ? 1u : 0u)) {}
  // Ray index along v within the row.
  int32_t ray() const { return int32_t(bits_ >> 17); }
  // First voxel index along u whose centre lies past the crossing, 0..nu (nu: past every centre).
  int32_t first() const { return int32_t((bits_ >> 1) & 0xFFFF); }
  // Sign of the triangle normal's u component: -1 where an outward-oriented solid is entered.
  int32_t sign() const { return (bits_ & 1) != 0 ? 1 : -1; }
  uint32_t packed() const { return bits_; }
  static Crossing fromPacked(uint32_t bits) {
    Crossing c;
    c.bits_ = bits;
    return c;
  }

 private:
  uint32_t bits_ = 0;
};

// A row's crossings: a growable array whose growth writes nothing (the caster writes every slot it adds), so
// adding a triangle's run of crossings costs one capacity check.
class CrossingList {
 public:
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }
  const Crossing* begin() const { return data_.get(); }
  const Crossing* end() const { return data_.get() + size_; }
  const Crossing& operator[](size_t i) const { return data_[i]; }
  // Adds n slots at the end and returns the first of them; the caller writes all n.
  Crossing* append(size_t n) {
    if (size_ + n > capacity_) grow(size_ + n);
    Crossing* slots = data_.get() + size_;
    size_ += n;
    return slots;
  }
  void push_back(Crossing c) { *append(1) = c; }

 private:
  void grow(size_t needed);
  std::unique_ptr<Crossing[]> data_;
  size_t size_ = 0, capacity_ = 0;
};

class RayCaster {
 public:
  // Prepares the triangles for this ray family: the rows each can cross, sorted by first row (counting sort, on up
  // to `threads` threads). Triangles whose projection onto (v, w) has exactly zero area are dropped: no displaced
  // ray crosses them. Keeps a reference to `mesh`, which must outlive the caster. O(T + rows) time; 8 bytes per
  // triangle (its index and last row), the vertices being read from the mesh when a sweep reaches the triangle.
  RayCaster(const TriangleMesh& mesh, const GridPlacement& placement, RayAxes axes, int threads);

  int32_t rows() const { return int32_t(cw_.size()); }
  int32_t raysPerRow() const { return int32_t(cv_.size()); }
  int32_t length() const { return int32_t(cu_.size()); }
  const RayAxes& axes() const { return axes_; }
  // Triangles kept (with a projection of nonzero area that some ray may cross).
  size_t triangles() const { return entries_.size(); }

 private:
  // A kept triangle: its index in the mesh and one past its last row. Its first row is implied by the position
  // in entries_ (row_start_).
  struct Entry {
    uint32_t triangle;
    int32_t row_hi;
  };

  // A triangle in the ray frame: float32 vertices in (u, v, w) order, the rows and rays it can cross.
  struct Tri {
    float p[3][3];           // vertices A, B, C; each (u, v, w)
    int32_t row_lo, row_hi;  // rows with w_min <= w_k < w_max
    int32_t ray_lo, ray_hi;  // rays with v_min <= v_j < v_max
    int32_t sign;            // exact sign of the normal's u component (orientation of the projection), never 0
  };
  // Projects mesh triangle `i` into the ray frame and sets its sign and ranges; false when no displaced ray can
  // cross it.
  bool classify(size_t i, Tri& t) const;
  // Hints the cache to load the mesh triangle of entries_[e] (both lines it may straddle).
  void prefetch(size_t e) const { prefetchBytes(&mesh_.triangles[entries_[e].triangle], sizeof(Triangle)); }

  // A triangle's vertices in double and what its crossings need, set up once per sweep when it becomes active.
  struct Plane {
    Plane() = default;
    // From mesh triangle `triangle`, kept by the caster (so crossable), whose last row is end_row - 1.
    Plane(uint32_t triangle, int32_t end_row, const RayCaster& caster);
    // What every row reads comes first, so it shares few cache lines. The section with the row's line: the
    // vertices sorted by w are P0, P1, P2; the long edge P0->P2 spans every row, the short edges P0->P1 (w < P1.w)
    // and P1->P2 (w >= P1.w) the rows below and above P1. Each edge as its lower end (v, w) and dv/dw.
    double long_v, long_w, long_slope;
    double low_v, low_w, low_slope;
    double high_v, high_w, high_slope;
    double section_margin;  // bound on the rounding error of the section's ends (see rowCrossings)
    int32_t fixed_first;    // >= 0: no centre lies in [umin, umax); the first voxel past every crossing
    int32_t sign;           // exact sign of the normal's u component (orientation of the projection), never 0
    int32_t row_hi;         // one past the triangle's last row
    double a[3];            // vertex A (u, v, w)
    double n_v, n_w;        // v and w components of the normal (B - A) x (C - A), in double
    double inv_nu;          // 1 / n.u
    double umin, umax;      // the vertices' u range, which holds every crossing
    double margin;          // bound on the error of firstPast's estimate of any crossing (infinite: always exact)
    double b[3], c[3];      // vertices B and C, for the exact tests
  };

 public:
  // Walks the rows from `row_begin` upwards, keeping the set of triangles whose W range covers the current row.
  // Setting up costs O(triangles starting below row_begin); each row then costs O(active triangles + crossings).
  class RowSweep {
   public:
    // A sweep meant for rows [row_begin, row_end): its storage is reserved for the most triangles any of them
    // crosses, so it never grows there (next() past row_end still works, growing it as needed).
    RowSweep(const RayCaster& caster, int32_t row_begin, int32_t row_end);
    int32_t row() const { return row_; }
    // Appends the crossings of every ray of the current row (grouped by triangle, not sorted), then moves on to the
    // next row.
    void next(CrossingList& out);

   private:
    const RayCaster& caster_;
    int32_t row_;
    std::vector<Plane> planes_;  // the triangles with row_lo <= row_ < row_hi, set up once per sweep
  };

 private:
  // Appends the crossings of `plane` with the rays of `row` (the triangle spans the row). Inlined into the sweep:
  // called once per active triangle and row.
  [[gnu::always_inline]] inline void rowCrossings(const Plane& plane, int32_t row, CrossingList& out) const;
  // Writes the crossings of rays [j, j_end) of `row` (all crossed) to o[0..j_end - j), in straight-line code (two
  // rays at a time with SSE2); falls back to placeCrossings when a crossing lies too near a centre to place so.
  [[gnu::always_inline]] inline void placeRun(const Plane& plane, int32_t row, int32_t j, int32_t j_end,
                                              Crossing* o) const;
  // The crossed rays of `row` among [j, j_end), each decided by the exact edge tests. Out of line: needed only where
  // a ray passes within rounding distance of an end of the triangle's section.
  [[gnu::noinline]] void exactCrossings(const Plane& plane, int32_t row, int32_t j, int32_t j_end,
                                        CrossingList& out) const;
  // Writes the crossings of rays [j, j_end) (all crossed) to out[0..j_end - j), each placed by firstPast. Out of
  // line: the fallback of rowCrossings' straight-line placement.
  [[gnu::noinline]] void placeCrossings(const Plane& plane, int32_t row, int32_t j, int32_t j_end, Crossing* out) const;
  // First centre past the crossing of ray (v, w); w_term = n.w (w - a.w).
  int32_t firstPast(const Plane& plane, double w_term, double v, double w) const;
  // Exact: is centre i of ray (v, w) past the triangle's plane? Out of line: the rare slow path of firstPast.
  [[gnu::noinline]] bool exactPast(const Plane& plane, int32_t i, double v, double w) const;

  const TriangleMesh& mesh_;
  RayAxes axes_;
  double inv_h_ = 1.0;
  // In voxels, along u and v: how far from an integer t = (x - c[0]) / h must lie, beyond an estimate's error / h,
  // for the centres c[floor(t)] and c[floor(t) + 1] to lie on either side of x (gridSlack in ray_caster.cpp).
  double slack_u_ = 0.0, slack_v_ = 0.0;
  double origin_u_ = 0.0, origin_v_ = 0.0, origin_w_ = 0.0;
  std::vector<double> cu_, cv_, cw_;  // voxel centres along u, v, w (docs/conventions.md, "Grid placement")
  std::vector<Entry> entries_;        // kept triangles, sorted by first row (then mesh order)
  std::vector<size_t> row_start_;     // entries_ of first row r: [row_start_[r], row_start_[r + 1])
  std::vector<int32_t> active_;       // by row: the triangles whose rows include it (a sweep's planes there)
};

}  // namespace vox::voxelize_detail
