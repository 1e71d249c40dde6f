// Overhangs and support along a build direction, with Embree's rays against the part's surface. See
// vox/analysis/printability.h.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "analysis/embree_scene.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/printability.h"
#include "vox/analysis/surface_mesh.h"
#include "vox/core/parallel.h"

namespace vox {

struct PrintSurface::Impl {
  analysis_detail::EmbreeScene scene;  // offset: the grid's origin
  std::vector<glm::dvec3> corners;     // three per triangle, relative to the offset
  std::vector<glm::dvec3> normal;      // per triangle, unit, outward (the mesh turned if it encloses a negative volume)
  // Without a mesh: the voxels, whose faces are the triangles (exact intervals along every ray) and whose ball of
  // neighbours about a voxel gives the surface's normal there (a slope is a slope, not a staircase of ceilings).
  std::optional<VoxelGrid> voxels;
};

PrintSurface::PrintSurface(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PrintSurface::PrintSurface(PrintSurface&&) noexcept = default;
PrintSurface& PrintSurface::operator=(PrintSurface&&) noexcept = default;
PrintSurface::~PrintSurface() = default;

Result<PrintSurface> makePrintSurface(const VoxelGrid& grid, const TriangleMesh* mesh, const ProgressFn& progress) {
  TriangleMesh own;
  auto impl = std::make_unique<PrintSurface::Impl>();
  if (!mesh) {
    // the voxels' faces, merged into rectangles
    auto surface = extractSurfaceMesh(grid, SurfaceMeshParams{}, progress);
    if (!surface) return surface.error();
    own = surface->toTriangleMesh();
    mesh = &own;
    impl->voxels = grid;
  }
  const glm::dvec3 offset = grid.frame().origin;
  const size_t n = mesh->triangles.size();
  impl->corners.resize(3 * n);
  impl->normal.resize(n);
  double volume6 = 0.0;  // six times the signed volume enclosed
  for (size_t t = 0; t < n; ++t) {
    glm::dvec3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = glm::dvec3(mesh->triangles[t].v[k]) - offset;
    for (int k = 0; k < 3; ++k) impl->corners[3 * t + size_t(k)] = p[k];
    const glm::dvec3 c = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double len = glm::length(c);
    impl->normal[t] = len > 0.0 ? c / len : glm::dvec3(0.0);
    volume6 += glm::dot(p[0], glm::cross(p[1], p[2]));
  }
  if (volume6 < 0.0) {
    for (glm::dvec3& nn : impl->normal) nn = -nn;
  }
  // a model without voxels has no surface: no rays, nothing to support
  if (!mesh->triangles.empty()) {
    if (Status st = analysis_detail::buildEmbreeScene(*mesh, offset, "printability", impl->scene, true); !st) {
      return st.error();
    }
  }
  return PrintSurface(std::move(impl));
}

namespace {

// Two unit vectors completing `d` to a right-handed frame; for an axis direction they are axes too, so that rays at
// (a + 0.5) * h fall on voxel centres.
void frameOf(glm::dvec3 d, glm::dvec3& u, glm::dvec3& v) {
  const glm::dvec3 helper = std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  u = glm::normalize(helper - glm::dot(helper, d) * d);
  v = glm::cross(d, u);
}

// The grid's layers made writable (each its own) for painting from many threads with atomic word operations.
struct AtomicMask {
  VoxelGrid grid;
  std::vector<uint64_t*> layers;
  explicit AtomicMask(const VoxelGrid& like) : grid(like.dims(), like.frame()) {
    layers.resize(size_t(like.nz()));
    for (int32_t z = 0; z < like.nz(); ++z) layers[size_t(z)] = grid.mutableLayerWords(z);
  }
  void set(int32_t x, int32_t y, int32_t z) {
    uint64_t* word = layers[size_t(z)] + (int64_t(y) + 1) * grid.wordsPerRow() + ((int64_t(x) + 1) >> 6);
    std::atomic_ref<uint64_t>(*word).fetch_or(uint64_t(1) << ((x + 1) & 63), std::memory_order_relaxed);
  }
  VoxelGrid done() {
    grid.releaseEmptyLayers();
    return std::move(grid);
  }
};

// The voxel holding point p (relative to the grid's origin), or false outside the grid.
bool voxelAt(const VoxelGrid& grid, glm::dvec3 p, glm::ivec3& v) {
  const glm::dvec3 q = p / grid.voxelSize();
  const double x = std::floor(q.x), y = std::floor(q.y), z = std::floor(q.z);
  if (x < 0 || y < 0 || z < 0 || x >= grid.nx() || y >= grid.ny() || z >= grid.nz()) return false;
  v = glm::ivec3(int(x), int(y), int(z));
  return true;
}

// The outward normal of the voxels' surface at voxel v: away from the centroid of the filled voxels of the ball of
// radius 4 about it (a half-ball's centroid lies along its flat side's normal). Only where the ball is about half
// filled, as on a flat side or a slope (0.52 to 0.59 of it); about a convex edge (0.35) or a concave one (0.76) the
// centroid tilts, and zero is returned.
glm::dvec3 ballNormal(const VoxelGrid& g, glm::ivec3 v) {
  static const std::vector<glm::ivec3> ball = [] {
    std::vector<glm::ivec3> out;
    constexpr int r = 4;
    for (int z = -r; z <= r; ++z)
      for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x)
          if (x * x + y * y + z * z <= r * r && (x | y | z) != 0) out.emplace_back(x, y, z);
    return out;
  }();
  glm::dvec3 inward(0.0);
  size_t filled = 0;
  for (const glm::ivec3& o : ball) {
    const glm::ivec3 q = v + o;
    if (g.inBounds(q.x, q.y, q.z) && g.get(q.x, q.y, q.z)) inward += glm::dvec3(o), ++filled;
  }
  const double fraction = double(filled) / double(ball.size()), n = glm::length(inward);
  if (fraction < 0.48 || fraction > 0.62 || n < 1e-9) return glm::dvec3(0.0);
  return -inward / n;
}

bool filledVoxel(const VoxelGrid& g, glm::ivec3 q) { return g.inBounds(q.x, q.y, q.z) && g.get(q.x, q.y, q.z); }

// The slope of the underside at voxel v, entered from below along `down` (a lattice step): its ball's normal, or at an
// edge the mean of those of the underside's voxels within two voxels of it (filled, nothing below them), so that the
// rim of a ceiling reads as the ceiling and the rim of a slope as the slope, not as the edge's bisector. Zero when none
// of them reads.
glm::dvec3 undersideNormal(const VoxelGrid& g, glm::ivec3 v, glm::ivec3 down) {
  if (const glm::dvec3 n = ballNormal(g, v); n != glm::dvec3(0.0)) return n;
  glm::dvec3 sum(0.0);
  for (int z = -2; z <= 2; ++z)
    for (int y = -2; y <= 2; ++y)
      for (int x = -2; x <= 2; ++x) {
        const glm::ivec3 q = v + glm::ivec3(x, y, z);
        if ((x | y | z) == 0 || !filledVoxel(g, q) || filledVoxel(g, q + down)) continue;
        sum += ballNormal(g, q);
      }
  const double n = glm::length(sum);
  return n > 1e-9 ? sum / n : glm::dvec3(0.0);
}

struct RayJob {
  const PrintSurface::Impl& s;
  const VoxelGrid& grid;
  glm::dvec3 d, u, v;
  glm::ivec3 down;  // the lattice step nearest -d
  double spacing, plate, layer, sin_angle, extent;
  AtomicMask *overhang = nullptr, *support = nullptr;
};

// One ray up through the part at (a, b) of the plate's lattice: the support below each bottom face steep enough to
// need it, and the overhang area those sides hold per unit of the plate's area. The part is where the winding number of
// the sides crossed is positive (sides facing down enter it, sides facing up leave it), so overlapping shells count
// once. Sides crossed at one place (within a thousandth of a voxel) count together, +1 if any faces down and -1 if any
// faces up: a ray through an edge shared by two triangles of one side counts it once, and where two bodies touch,
// the one's top and the other's bottom cancel.
struct RayReading {
  double support = 0.0;   // length of support, model units
  double overhang = 0.0;  // overhang area per unit of the plate's area: 1 / |cos| of each overhang side entered
};

RayReading supportAlong(const RayJob& job, double a, double b, std::vector<std::pair<float, unsigned>>& hits) {
  const glm::dvec3 foot = job.u * a + job.v * b + job.d * (job.plate - job.spacing);
  analysis_detail::allEmbreeHits(job.s.scene.scene, foot, job.d, hits);
  const double eps = std::max(1e-3 * job.layer, 1e-6 * job.extent);
  RayReading r;
  double top = job.plate;
  int winding = 0;
  for (size_t g = 0; g < hits.size();) {
    // the sides crossed at this place: the steepest facing down among them, and whether any faces up
    const float t = hits[g].first;
    double facing = 0.0;
    bool up = false;
    for (; g < hits.size() && double(hits[g].first) - double(t) <= eps; ++g) {
      const double f = glm::dot(job.s.normal[hits[g].second], job.d);
      facing = std::min(facing, f);
      up = up || f > 0.0;
    }
    const double height = job.plate - job.spacing + double(t);
    const int before = winding;
    winding += (facing < 0.0 ? 1 : 0) - (up ? 1 : 0);
    if (before <= 0 && winding > 0) {
      glm::ivec3 above;
      if (job.s.voxels && voxelAt(job.grid, foot + job.d * (double(t) + 0.5 * job.layer), above)) {
        // the voxels' own surface: its slope from the ball about the voxel entered, not the face's (a step of a
        // near-vertical wall faces down, the wall does not)
        const glm::dvec3 n = undersideNormal(*job.s.voxels, above, job.down);
        if (n != glm::dvec3(0.0)) facing = std::min(glm::dot(n, job.d), 0.0);
      }
      const bool needs = height - job.plate >= job.layer && facing < 0.0 && -facing > job.sin_angle;
      if (needs) {
        r.support += height - top;
        r.overhang += 1.0 / -facing;
        glm::ivec3 vox;
        if (job.overhang && voxelAt(job.grid, foot + job.d * (double(t) + 0.5 * job.layer), vox)) {
          job.overhang->set(vox.x, vox.y, vox.z);
        }
        for (double h = top + 0.5 * job.layer; job.support && h < height - 0.25 * job.layer; h += 0.5 * job.layer) {
          if (voxelAt(job.grid, foot + job.d * (h - job.plate + job.spacing), vox) &&
              !job.grid.get(vox.x, vox.y, vox.z)) {
            job.support->set(vox.x, vox.y, vox.z);
          }
        }
      }
    } else if (before > 0 && winding <= 0) {
      top = height;
    }
  }
  return r;
}

}  // namespace

Result<PrintSupport> computePrintSupport(const PrintSurface& surface, const VoxelGrid& grid, const PrintParams& params,
                                         const ProgressFn& progress) {
  const double norm = glm::length(params.up);
  if (!(norm > 0.0) || !std::isfinite(norm))
    return makeError(ErrorCode::kInvalidArgument, "the build direction is zero");
  if (!(params.overhang_angle_deg >= 0.0 && params.overhang_angle_deg < 90.0)) {
    return makeError(ErrorCode::kInvalidArgument, "the overhang angle must lie in [0, 90) degrees");
  }
  const PrintSurface::Impl& s = surface.impl();
  PrintSupport out;
  const glm::dvec3 d = params.up / norm;
  out.direction = d;
  glm::dvec3 u, v;
  frameOf(d, u, v);
  const double h = grid.voxelSize();
  const double spacing = params.ray_spacing > 0.0 ? params.ray_spacing : h;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const glm::dvec3& p : s.corners) {
    const double c[3] = {glm::dot(p, u), glm::dot(p, v), glm::dot(p, d)};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  if (s.corners.empty()) return out;
  out.height = hi[2] - lo[2];
  const double sin_angle = std::sin(params.overhang_angle_deg * std::numbers::pi / 180.0);
  std::optional<AtomicMask> overhang, support;
  if (params.fields) overhang.emplace(grid), support.emplace(grid);
  const glm::ivec3 down(-int(std::lround(d.x)), -int(std::lround(d.y)), -int(std::lround(d.z)));
  const RayJob job{s,
                   grid,
                   d,
                   u,
                   v,
                   down,
                   spacing,
                   lo[2],
                   h,
                   sin_angle,
                   std::max({hi[0] - lo[0], hi[1] - lo[1], out.height}),
                   overhang ? &*overhang : nullptr,
                   support ? &*support : nullptr};
  const int64_t a0 = int64_t(std::floor(lo[0] / spacing)), a1 = int64_t(std::ceil(hi[0] / spacing));
  const int64_t b0 = int64_t(std::floor(lo[1] / spacing)), b1 = int64_t(std::ceil(hi[1] / spacing));
  const int threads = threadsFor((a1 - a0) * (b1 - b0) * 64);
  std::vector<RayReading> sums(static_cast<size_t>(threads));
  std::atomic<int64_t> rows_done{0};
  analysis_detail::ProgressGate gate(progress);
  parallelChunks(b0, b1, 4, threads, [&](int th, int64_t begin, int64_t end) {
    std::vector<std::pair<float, unsigned>> hits;
    for (int64_t b = begin; b < end && !gate.cancelled(); ++b) {
      for (int64_t a = a0; a < a1; ++a) {
        const RayReading r = supportAlong(job, (double(a) + 0.5) * spacing, (double(b) + 0.5) * spacing, hits);
        sums[size_t(th)].support += r.support;
        sums[size_t(th)].overhang += r.overhang;
      }
      gate.report(double(rows_done.fetch_add(1) + 1) / double(b1 - b0));
    }
  });
  if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "printability cancelled");
  for (const RayReading& r : sums) {
    out.support_volume += r.support * spacing * spacing;
    out.overhang_area += r.overhang * spacing * spacing;
  }
  out.rays = (a1 - a0) * (b1 - b0);
  if (overhang) out.overhang = overhang->done(), out.support = support->done();
  return out;
}

}  // namespace vox
