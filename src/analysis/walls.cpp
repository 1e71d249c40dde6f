// Walls, not edges: the wall stops on the distance field's ridge, and the thin walls as the union of their inscribed
// balls. See vox/analysis/walls.h.
#include "vox/analysis/walls.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <new>
#include <numbers>

#include <glm/common.hpp>

#include "analysis/mask_regions.h"
#include "analysis/progress_gate.h"
#include "vox/core/parallel.h"

namespace vox {
namespace {

struct Offset {
  int32_t dx, dy, dz;
  int64_t delta;  // index step in the box
  double length;
};

// Offsets within `reach` voxels (Euclidean), nearest first: a voxel off a ridge is rejected at its first face
// neighbour, one step up the distance.
std::vector<Offset> reachOffsets(int32_t reach, int64_t nx, int64_t plane) {
  std::vector<Offset> out;
  for (int32_t dz = -reach; dz <= reach; ++dz)
    for (int32_t dy = -reach; dy <= reach; ++dy)
      for (int32_t dx = -reach; dx <= reach; ++dx) {
        const int32_t q = dx * dx + dy * dy + dz * dz;
        if (q == 0 || q > reach * reach) continue;
        out.push_back({dx, dy, dz, dx + nx * dy + plane * dz, std::sqrt(double(q))});
      }
  std::stable_sort(out.begin(), out.end(), [](const Offset& a, const Offset& b) { return a.length < b.length; });
  return out;
}

// Whether voxel (x, y, z) of value `a` is a wall stop: no voxel within reach rises by slope * its distance or more.
bool isStop(const uint32_t* data, int64_t i, int64_t x, int64_t y, int64_t z, const Dims& d,
            const std::vector<Offset>& offsets, double slope) {
  const uint32_t a = data[i];
  const double r = std::sqrt(double(a));
  for (const Offset& o : offsets) {
    const int64_t qx = x + o.dx, qy = y + o.dy, qz = z + o.dz;
    if (qx < 0 || qy < 0 || qz < 0 || qx >= d.nx || qy >= d.ny || qz >= d.nz) continue;
    const uint32_t b = data[i + o.delta];
    if (b <= a) continue;
    const double need = r + slope * o.length;
    if (double(b) >= need * need - 1e-9) return false;
  }
  return true;
}

// The centres of the inscribed ball of squared radius a (|o|^2 < a), as index steps in the box.
std::vector<int64_t> ballSteps(uint32_t a, int64_t nx, int64_t plane) {
  std::vector<int64_t> out;
  const int32_t r = int32_t(std::ceil(std::sqrt(double(a))));
  for (int32_t dz = -r; dz <= r; ++dz)
    for (int32_t dy = -r; dy <= r; ++dy)
      for (int32_t dx = -r; dx <= r; ++dx)
        if (uint32_t(dx * dx + dy * dy + dz * dz) < a) out.push_back(dx + nx * dy + plane * dz);
  return out;
}

// A wall's mid-surface is a sheet of stops at about the same distance (a thin pin's axis a line of them). A stop
// with fewer than two others within `reach` on each axis and within a voxel of its own distance, itself within
// `reach` of the surface, is the tip of a sampled corner or edge, where the voxels leave no room to climb (a lone stop
// deeper in is a ball's centre).
void dropLoneStops(WallRidge& ridge, int32_t reach) {
  const Dims d = ridge.box_dims;
  const int64_t nx = d.nx, ny = d.ny, nz = d.nz;
  std::vector<uint64_t> at(size_t((d.count() + 63) / 64), 0);
  for (const WallRidge::Stop& s : ridge.stops) at[size_t(s.index >> 6)] |= uint64_t(1) << (s.index & 63);
  std::vector<WallRidge::Stop> by_index = ridge.stops;
  std::sort(by_index.begin(), by_index.end(),
            [](const WallRidge::Stop& a, const WallRidge::Stop& b) { return a.index < b.index; });
  const auto squaredAt = [&](int64_t j) {
    auto it = std::lower_bound(by_index.begin(), by_index.end(), j,
                               [](const WallRidge::Stop& s, int64_t v) { return s.index < v; });
    return it->squared;
  };
  std::vector<uint8_t> keep(ridge.stops.size(), 0);
  const auto alike = [](uint32_t a, uint32_t b) { return std::abs(std::sqrt(double(a)) - std::sqrt(double(b))) < 1.0; };
  parallelChunks(0, int64_t(ridge.stops.size()), 4096, threadsFor(int64_t(ridge.stops.size()) * 64),
                 [&](int, int64_t b, int64_t e) {
                   for (int64_t k = b; k < e; ++k) {
                     const WallRidge::Stop s = ridge.stops[size_t(k)];
                     if (s.squared > uint32_t(reach * reach)) {
                       keep[size_t(k)] = 1;
                       continue;
                     }
                     const int64_t i = s.index, x = i % nx, y = (i / nx) % ny, z = i / (nx * ny);
                     int found = 0;
                     for (int64_t qz = std::max<int64_t>(0, z - reach); qz <= std::min(nz - 1, z + reach); ++qz)
                       for (int64_t qy = std::max<int64_t>(0, y - reach); qy <= std::min(ny - 1, y + reach); ++qy)
                         for (int64_t qx = std::max<int64_t>(0, x - reach); qx <= std::min(nx - 1, x + reach); ++qx) {
                           const int64_t j = qx + nx * (qy + ny * qz);
                           if ((at[size_t(j >> 6)] >> (j & 63)) & 1) found += int(alike(squaredAt(j), s.squared));
                         }
                     keep[size_t(k)] = found >= 3;
                   }
                 });
  size_t n = 0;
  for (size_t k = 0; k < ridge.stops.size(); ++k)
    if (keep[k]) ridge.stops[n++] = ridge.stops[k];
  if (n == 0) return;  // a part a few voxels across: its stops are all it has
  ridge.stops.resize(n);
}

}  // namespace

Result<WallRidge> findWallRidge(const DistanceField& distance, const WallRidgeParams& params,
                                const ProgressFn& progress) {
  if (!(params.angle_deg > 0.0 && params.angle_deg < 180.0)) {
    return makeError(ErrorCode::kInvalidArgument, "walls: the wall angle must lie between 0 and 180 degrees");
  }
  if (params.reach < 1 || params.reach > 8) {
    return makeError(ErrorCode::kInvalidArgument, "walls: the ridge reach must be 1 to 8 voxels");
  }
  WallRidge out;
  out.box_dims = distance.boxDims();
  out.box_min = distance.boxMin();
  out.frame = distance.frame();
  const Dims d = out.box_dims;
  if (d.count() == 0) return out;
  DistanceField dense_copy;
  const DistanceField* f = &distance;
  if (!distance.isDense()) {
    dense_copy = distance.denseCopy();
    if (!dense_copy.data()) return makeError(ErrorCode::kLimit, "walls: no memory for a dense distance field");
    f = &dense_copy;
  }
  const uint32_t* data = f->data();
  const int64_t nx = d.nx, plane = int64_t(d.nx) * d.ny;
  const std::vector<Offset> offsets = reachOffsets(params.reach, nx, plane);
  const double slope = std::sin(params.angle_deg * std::numbers::pi / 360.0);
  analysis_detail::ProgressGate gate(progress);
  const int threads = threadsFor(d.count() / 8);
  std::vector<std::vector<WallRidge::Stop>> found(static_cast<size_t>(threads));
  std::atomic<int64_t> layers_done{0};
  parallelChunks(0, d.nz, 1, threads, [&](int t, int64_t z0, int64_t z1) {
    for (int64_t z = z0; z < z1 && !gate.cancelled(); ++z) {
      for (int64_t y = 0; y < d.ny; ++y) {
        const int64_t row = nx * y + plane * z;
        for (int64_t x = 0; x < nx; ++x) {
          if (data[row + x] != 0 && isStop(data, row + x, x, y, z, d, offsets, slope)) {
            found[size_t(t)].push_back({row + x, data[row + x]});
          }
        }
      }
      gate.report(double(++layers_done) / double(d.nz));
    }
  });
  if (gate.cancelled() || !gate.report(1.0)) return makeError(ErrorCode::kCancelled, "walls cancelled");
  for (auto& v : found) out.stops.insert(out.stops.end(), v.begin(), v.end());
  dropLoneStops(out, params.reach);
  std::sort(out.stops.begin(), out.stops.end(), [](const WallRidge::Stop& a, const WallRidge::Stop& b) {
    return a.squared != b.squared ? a.squared < b.squared : a.index < b.index;
  });
  return out;
}

bool Walls::inWall(int64_t x, int64_t y, int64_t z) const {
  const int64_t bx = x - box_min.x, by = y - box_min.y, bz = z - box_min.z;
  if (bx < 0 || by < 0 || bz < 0 || bx >= box_dims.nx || by >= box_dims.ny || bz >= box_dims.nz) return false;
  const int64_t i = bx + int64_t(box_dims.nx) * (by + int64_t(box_dims.ny) * bz);
  return (mask[size_t(i >> 6)] >> (i & 63)) & 1;
}

namespace {

// The thin stops by box index, for the regions to read each one's distance.
struct ThinStops {
  std::vector<uint64_t> bits;             // one per box voxel
  std::vector<WallRidge::Stop> by_index;  // sorted by index
  uint32_t at(int64_t i) const {          // the squared distance of the stop at i, UINT32_MAX when none
    if (!((bits[size_t(i >> 6)] >> (i & 63)) & 1)) return UINT32_MAX;
    auto it = std::lower_bound(by_index.begin(), by_index.end(), i,
                               [](const WallRidge::Stop& s, int64_t v) { return s.index < v; });
    return it->squared;
  }
};

// The 26-connected regions of the painted walls: their voxels, exposed faces, box and thinnest stop; regions under
// the speck area are counted and cleared from the mask.
void collectRegions(const WallRidge& ridge, const uint32_t* filled, const ThinStops& thin_stops, Walls& out) {
  const Dims d = ridge.box_dims;
  const double h = ridge.frame.voxel_size;
  analysis_detail::forEachRegion(
      out.mask, d.nx, d.ny, d.nz, [&](int64_t i) { return filled[i] != 0; },
      [&](const analysis_detail::MaskRegion& m) {
        ThinWallRegion r;
        r.voxels = int64_t(m.voxels->size());
        r.exposed_faces = m.exposed_faces;
        r.area = double(r.exposed_faces) * h * h;
        if (r.area < out.min_area) {
          ++out.specks;
          for (int64_t i : *m.voxels) out.mask[size_t(i >> 6)] &= ~(uint64_t(1) << (i & 63));
          return true;
        }
        uint32_t min_a = UINT32_MAX;
        for (int64_t i : *m.voxels) min_a = std::min(min_a, thin_stops.at(i));
        r.bbox_min_ijk = m.min + ridge.box_min;
        r.bbox_max_ijk = m.max + ridge.box_min;
        r.bbox.min = ridge.frame.origin + glm::dvec3(r.bbox_min_ijk) * h;
        r.bbox.max = ridge.frame.origin + glm::dvec3(r.bbox_max_ijk + 1) * h;
        r.min = 2.0 * std::sqrt(double(min_a)) * h;
        out.voxels += r.voxels;
        out.regions.push_back(r);
        return true;
      });
  std::stable_sort(out.regions.begin(), out.regions.end(),
                   [](const ThinWallRegion& a, const ThinWallRegion& b) { return a.voxels > b.voxels; });
}

// Sets the mask bit of every voxel centre strictly inside the ball of a stop, ball by ball: cheap while the balls
// are small.
void paintBalls(const WallRidge& ridge, size_t stops, std::vector<uint64_t>& mask,
                analysis_detail::ProgressGate& gate) {
  const int64_t nx = ridge.box_dims.nx, plane = nx * int64_t(ridge.box_dims.ny);
  std::vector<int64_t> ball;
  uint32_t ball_a = 0;
  for (size_t k = 0; k < stops; ++k) {
    if (k % 4096 == 0 && !gate.report(0.7 * double(k) / double(stops))) return;  // cancelled: stops at once
    const WallRidge::Stop& s = ridge.stops[k];
    if (s.squared != ball_a) ball = ballSteps(ball_a = s.squared, nx, plane);
    for (int64_t step : ball) {
      const int64_t j = s.index + step;  // the ball holds filled voxels only, all inside the box
      mask[size_t(j >> 6)] |= uint64_t(1) << (j & 63);
    }
  }
}

// The lower envelope of the parabolas (q - i)^2 + f[i] over one line of n values (Felzenszwalb and Huttenlocher),
// in place; v and z are scratch of n and n + 1.
void lowerEnvelope(float* f, int64_t n, int64_t stride, std::vector<int64_t>& v, std::vector<double>& z,
                   std::vector<float>& line) {
  line.resize(size_t(n));
  for (int64_t i = 0; i < n; ++i) line[size_t(i)] = f[i * stride];
  int64_t k = -1;
  for (int64_t q = 0; q < n; ++q) {
    if (!std::isfinite(line[size_t(q)])) continue;
    double s = -INFINITY;
    while (k >= 0) {
      const int64_t p = v[size_t(k)];
      s = ((double(line[size_t(q)]) + double(q * q)) - (double(line[size_t(p)]) + double(p * p))) / double(2 * (q - p));
      if (s > z[size_t(k)]) break;
      --k;
    }
    ++k;
    v[size_t(k)] = q;
    z[size_t(k)] = k == 0 ? -INFINITY : s;
    z[size_t(k) + 1] = INFINITY;
  }
  if (k < 0) return;  // nothing finite on the line
  int64_t j = 0;
  for (int64_t q = 0; q < n; ++q) {
    while (z[size_t(j) + 1] < double(q)) ++j;
    const int64_t p = v[size_t(j)];
    f[q * stride] = float(double((q - p) * (q - p)) + double(line[size_t(p)]));
  }
}

// The same union of balls for any number and size of them, in time linear in the box: F(p) = min over the stops c
// of |p - c|^2 - r(c)^2, a distance transform of the stops' -r^2 (exact in floats: integers under 2^24); p is in a
// ball where F(p) < 0.
void paintEnvelope(const WallRidge& ridge, size_t stops, std::vector<uint64_t>& mask,
                   analysis_detail::ProgressGate& gate) {
  const Dims d = ridge.box_dims;
  const int64_t nx = d.nx, ny = d.ny, nz = d.nz, plane = nx * ny;
  std::vector<float> f(size_t(d.count()), INFINITY);
  for (size_t k = 0; k < stops; ++k) f[size_t(ridge.stops[k].index)] = -float(ridge.stops[k].squared);
  const int threads = threadsFor(d.count() / 8);
  int done_passes = 0;
  const auto pass = [&](int64_t lines, int64_t n, int64_t stride, auto first) {
    parallelChunks(0, lines, 64, threads, [&](int, int64_t b, int64_t e) {
      if (gate.cancelled()) return;
      std::vector<int64_t> v(static_cast<size_t>(n));
      std::vector<double> z(static_cast<size_t>(n) + 1);
      std::vector<float> line;
      for (int64_t l = b; l < e; ++l) lowerEnvelope(f.data() + first(l), n, stride, v, z, line);
    });
    return gate.report(0.7 * double(++done_passes) / 3.0);
  };
  if (!pass(ny * nz, nx, 1, [&](int64_t l) { return l * nx; })) return;
  if (!pass(nx * nz, ny, nx, [&](int64_t l) { return (l % nx) + plane * (l / nx); })) return;
  if (!pass(nx * ny, nz, plane, [&](int64_t l) { return l; })) return;
  for (int64_t i = 0; i < d.count(); ++i)
    if (f[size_t(i)] < 0.0f) mask[size_t(i >> 6)] |= uint64_t(1) << (i & 63);
}

}  // namespace

static Result<Walls> findWallsIn(const WallRidge& ridge, const DistanceField& filled, const WallParams& params,
                                 const ProgressFn& progress) {
  if (!(params.min_wall >= 0) || !std::isfinite(params.min_wall)) {
    return makeError(ErrorCode::kInvalidArgument, "walls: the minimum wall must be a number >= 0");
  }
  const Dims fd = filled.boxDims(), rd = ridge.box_dims;
  if (fd.nx != rd.nx || fd.ny != rd.ny || fd.nz != rd.nz || filled.boxMin() != ridge.box_min ||
      (ridge.box_dims.count() > 0 && !filled.isDense())) {
    return makeError(ErrorCode::kInvalidArgument, "walls: the field does not cover the ridge's box densely");
  }
  Walls out;
  out.min_wall = params.min_wall;
  out.box_dims = ridge.box_dims;
  out.box_min = ridge.box_min;
  const double h = ridge.frame.voxel_size;
  out.min_area = params.min_area >= 0.0 ? params.min_area : params.min_wall * params.min_wall;
  const Dims d = ridge.box_dims;
  out.mask.assign(size_t((d.count() + 63) / 64), 0);
  if (d.count() == 0 || ridge.stops.empty()) return out;
  analysis_detail::ProgressGate gate(progress);
  // thin: 2 r h < min_wall, r^2 = squared
  const double limit = params.min_wall / (2.0 * h);
  ThinStops thin;
  thin.bits.assign(out.mask.size(), 0);
  double ball_volume = 0.0;
  size_t k = 0;
  for (; k < ridge.stops.size() && double(ridge.stops[k].squared) < limit * limit; ++k) {
    const WallRidge::Stop& s = ridge.stops[k];
    thin.bits[size_t(s.index >> 6)] |= uint64_t(1) << (s.index & 63);
    ball_volume += 4.2 * std::pow(double(s.squared), 1.5) + 1.0;
  }
  thin.by_index.assign(ridge.stops.begin(), ridge.stops.begin() + std::ptrdiff_t(k));
  std::sort(thin.by_index.begin(), thin.by_index.end(),
            [](const WallRidge::Stop& a, const WallRidge::Stop& b) { return a.index < b.index; });
  // ball by ball while that is cheaper than a few passes over the box
  const bool balls = params.paint == WallParams::Paint::kAuto ? ball_volume < 4.0 * double(d.count())
                                                              : params.paint == WallParams::Paint::kBalls;
  if (balls) {
    paintBalls(ridge, k, out.mask, gate);
  } else {
    paintEnvelope(ridge, k, out.mask, gate);
  }
  if (!gate.report(0.7)) return makeError(ErrorCode::kCancelled, "walls cancelled");
  collectRegions(ridge, filled.data(), thin, out);
  // the thinnest stop, whatever the minimum wall and the speck area: the part's thinnest wall
  out.wall_min = 2.0 * std::sqrt(double(ridge.stops.front().squared)) * h;
  if (!gate.report(1.0)) return makeError(ErrorCode::kCancelled, "walls cancelled");
  return out;
}

Result<Walls> findWalls(const WallRidge& ridge, const DistanceField& filled, const WallParams& params,
                        const ProgressFn& progress) {
  try {
    return findWallsIn(ridge, filled, params, progress);
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimit, "walls: not enough memory for the walls' mask and regions");
  }
}

}  // namespace vox
