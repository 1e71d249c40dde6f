// Ray thickness with Embree: rays from the mesh's surface along its inward normal to the opposite wall. See
// vox/analysis/ray_thickness.h.
#include "vox/analysis/ray_thickness.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "analysis/embree_scene.h"
#include "analysis/huge_array.h"
#include "analysis/morton.h"
#include "analysis/progress_gate.h"
#include "vox/core/parallel.h"

namespace vox {
namespace {

using analysis_detail::castEmbreeRay;
using analysis_detail::EmbreeScene;

// Whether the voxel holding point p (model units) is filled; outside the grid nothing is.
bool filledAt(const VoxelGrid& grid, glm::dvec3 p) {
  const glm::dvec3 q = (p - grid.frame().origin) / grid.voxelSize();
  const double x = std::floor(q.x), y = std::floor(q.y), z = std::floor(q.z);
  if (x < 0 || y < 0 || z < 0 || x >= grid.nx() || y >= grid.ny() || z >= grid.nz()) return false;
  return grid.get(int32_t(x), int32_t(y), int32_t(z));
}

// The distance from p along d to where the material ends, and the triangle it leaves through: sides inside the
// material (overlapping shells, the foot of a part inside another) are passed through, as the voxels show them.
bool exitOf(RTCScene scene, const VoxelGrid& grid, glm::dvec3 p, glm::dvec3 d, float t_near, double& t,
            unsigned& triangle) {
  const glm::dvec3 origin = grid.frame().origin;
  t = 0.0;
  for (int crossings = 0; crossings < 16; ++crossings) {
    float dist = 0.0f;
    if (!castEmbreeRay(scene, p - origin + d * t, d, t_near, dist, triangle)) return false;
    t += double(dist);
    if (!filledAt(grid, p + d * (t + 0.75 * grid.voxelSize()))) return true;
  }
  return false;
}

// Every voxel along the segment from p, length t along d (unit), takes t where t is less than what it holds; with
// [from, to], only those along that part. A 3D DDA (Amanatides and Woo): one step per voxel crossed. The empty voxels
// a segment grazes are cleared afterwards, row by row (a test of the grid at every step costs a second cache miss).
void paintSegment(const VoxelGrid& grid, glm::dvec3 p, glm::dvec3 d, double t, std::vector<float>& field,
                  double from = 0.0, double to = -1.0) {
  const GridFrame& f = grid.frame();
  const double inv_h = 1.0 / f.voxel_size;
  const double length = ((to < 0.0 ? t : to) - from) * inv_h;  // voxel units
  const glm::dvec3 q = (p + d * from - f.origin) * inv_h;
  const int64_t n[3] = {grid.nx(), grid.ny(), grid.nz()};
  int64_t c[3], step[3];
  double next[3], delta[3];
  for (int a = 0; a < 3; ++a) {
    c[a] = int64_t(std::floor(q[a]));
    step[a] = d[a] > 0.0 ? 1 : -1;
    delta[a] = d[a] != 0.0 ? 1.0 / std::abs(d[a]) : INFINITY;
    const double boundary = d[a] > 0.0 ? double(c[a] + 1) - q[a] : q[a] - double(c[a]);
    next[a] = d[a] != 0.0 ? boundary * delta[a] : INFINITY;
  }
  const float value = float(t);
  const int64_t stride[3] = {step[0], step[1] * n[0], step[2] * n[0] * n[1]};
  int64_t at = c[0] + n[0] * (c[1] + n[1] * c[2]);
  for (double s = 0.0; s <= length;) {
    if (uint64_t(c[0]) < uint64_t(n[0]) && uint64_t(c[1]) < uint64_t(n[1]) && uint64_t(c[2]) < uint64_t(n[2])) {
      std::atomic_ref<float> cell(field[size_t(at)]);
      float cur = cell.load(std::memory_order_relaxed);
      while (value < cur && !cell.compare_exchange_weak(cur, value, std::memory_order_relaxed)) {
      }
    }
    int a = next[1] < next[0] ? 1 : 0;  // the axis whose boundary comes first
    a = next[2] < next[a] ? 2 : a;
    s = next[a];
    next[a] += delta[a];
    c[a] += step[a];
    at += stride[a];
  }
}

// The triangles in the Morton order of their centroids' voxels: neighbouring rays paint neighbouring voxels while
// they are cached.
std::vector<uint32_t> spatialOrder(const TriangleMesh& mesh, const GridFrame& f) {
  std::vector<std::pair<uint64_t, uint32_t>> keyed(mesh.triangles.size());
  for (size_t t = 0; t < keyed.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    const glm::dvec3 q = ((glm::dvec3(v[0]) + glm::dvec3(v[1]) + glm::dvec3(v[2])) / 3.0 - f.origin) / f.voxel_size;
    auto cell = [](double c) { return uint32_t(std::clamp(c, 0.0, 65535.0)); };
    keyed[t] = {analysis_detail::mortonCode(cell(q.x), cell(q.y), cell(q.z)), uint32_t(t)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> order(keyed.size());
  for (size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

// Empty voxels and voxels no ray reached to 0; the statistics of the rest (summed per layer, then the layers in
// order: the same mean whichever thread took a layer).
void finishField(const VoxelGrid& grid, RayThicknessResult& out) {
  const int64_t nx = grid.nx(), ny = grid.ny();
  struct Sums {
    int64_t voxels = 0;
    double sum = 0.0, min = std::numeric_limits<double>::infinity(), max = 0.0;
  };
  std::vector<Sums> layers(static_cast<size_t>(grid.nz()));
  parallelChunks(0, int64_t(grid.nz()), 1, threadsFor(grid.dims().count()), [&](int, int64_t zb, int64_t ze) {
    for (int64_t z = zb; z < ze; ++z) {
      Sums& s = layers[size_t(z)];
      for (int64_t y = 0; y < ny; ++y) {
        const uint64_t* row = grid.rowWords(int32_t(y), int32_t(z));
        float* values = out.field.values.data() + nx * (y + ny * z);
        for (int64_t x = 0; x < nx; ++x) {
          const bool filled = (row[(x + 1) >> 6] >> ((x + 1) & 63)) & 1u;
          if (!filled || !std::isfinite(values[x])) {
            values[x] = 0.0f;
            continue;
          }
          ++s.voxels;
          s.sum += values[x];
          s.min = std::min(s.min, double(values[x]));
          s.max = std::max(s.max, double(values[x]));
        }
      }
    }
  });
  Sums all;
  for (const Sums& s : layers) {
    all.voxels += s.voxels, all.sum += s.sum;
    all.min = std::min(all.min, s.min), all.max = std::max(all.max, s.max);
  }
  out.voxels = all.voxels;
  out.min = all.voxels > 0 ? all.min : 0.0;
  out.max = all.max;
  out.mean = all.voxels > 0 ? all.sum / double(all.voxels) : 0.0;
}

}  // namespace

Result<RayThicknessResult> computeRayThickness(const TriangleMesh& mesh, const VoxelGrid& grid,
                                               const RayThicknessParams& params, const ProgressFn& progress) {
  if (!(params.angle_deg > 0.0 && params.angle_deg < 90.0)) {
    return makeError(ErrorCode::kInvalidArgument, "ray thickness: the angle must lie between 0 and 90 degrees");
  }
  if (!(params.samples_per_face > 0.0 && params.samples_per_face <= 64.0)) {
    return makeError(ErrorCode::kInvalidArgument, "ray thickness: 0 to 64 samples per voxel face");
  }
  if (mesh.triangles.size() >= (size_t(1) << 30)) {
    return makeError(ErrorCode::kLimit, "ray thickness: more than 2^30 triangles");
  }
  RayThicknessResult out;
  // rays write all over the field: on 2 MiB pages most writes keep their address translation cached
  out.field.dims = grid.dims();
  out.field.frame = grid.frame();
  out.field.values.reserve(size_t(grid.dims().count()));
  analysis_detail::adviseHugePages(out.field.values.data(), size_t(grid.dims().count()) * sizeof(float));
  out.field.values.assign(size_t(grid.dims().count()), std::numeric_limits<float>::infinity());
  EmbreeScene scene;
  if (Status st = analysis_detail::buildEmbreeScene(mesh, grid.frame().origin, "ray thickness", scene); !st)
    return st.error();
  const size_t n = mesh.triangles.size();
  std::vector<glm::dvec3> normals(n);
  for (size_t t = 0; t < n; ++t) {
    const auto& v = mesh.triangles[t].v;
    const glm::dvec3 c = glm::cross(glm::dvec3(v[1] - v[0]), glm::dvec3(v[2] - v[0]));
    const double len = glm::length(c);
    normals[t] = len > 0.0 ? c / len : glm::dvec3(0.0);
  }
  const double h = grid.voxelSize(), facing = std::cos(params.angle_deg * std::numbers::pi / 180.0);
  const float t_near = float(1e-3 * h);  // past the side it starts on: floats over a grid of ~10^4 voxels
  analysis_detail::ProgressGate gate(progress);
  const int threads = threadsFor(int64_t(n) * 64);
  std::vector<int64_t> rays(size_t(threads), 0), accepted(size_t(threads), 0);
  std::atomic<int64_t> done{0};
  const std::vector<uint32_t> order = spatialOrder(mesh, grid.frame());
  parallelChunks(0, int64_t(n), 1024, threads, [&](int th, int64_t b, int64_t e) {
    for (int64_t i = b; i < e && !gate.cancelled(); ++i) {
      const uint32_t t = order[size_t(i)];
      const glm::dvec3 nrm = normals[size_t(t)];
      if (nrm == glm::dvec3(0.0)) continue;  // degenerate: no side to measure from
      const auto& v = mesh.triangles[size_t(t)].v;
      const glm::dvec3 v0(v[0]), e1 = glm::dvec3(v[1]) - v0, e2 = glm::dvec3(v[2]) - v0;
      const double area = 0.5 * glm::length(glm::cross(e1, e2));
      const int64_t samples = std::max<int64_t>(1, std::llround(params.samples_per_face * area / (h * h)));
      for (int64_t k = 0; k < samples; ++k) {
        // a low-discrepancy point of the unit square (Roberts' R2) from the centroid, folded into the triangle
        double a = std::fmod(1.0 / 3.0 + 0.7548776662466927 * double(k), 1.0);
        double c = std::fmod(1.0 / 3.0 + 0.5698402909980532 * double(k), 1.0);
        if (a + c > 1.0) a = 1.0 - a, c = 1.0 - c;
        const glm::dvec3 p = v0 + a * e1 + c * e2;
        // a side inside the material (overlapping shells) is no surface to measure from
        if (filledAt(grid, p + nrm * (0.75 * h))) continue;
        double dist = 0.0;
        unsigned hit = 0;
        ++rays[size_t(th)];
        if (!exitOf(scene.scene, grid, p, -nrm, t_near, dist, hit) || hit >= n) continue;
        // the side left through faces back: its outward normal within the angle of the opposite of ours
        if (glm::dot(normals[hit], nrm) > -facing) continue;
        ++accepted[size_t(th)];
        if (params.paint_limit <= 0.0 || dist <= params.paint_limit) {
          paintSegment(grid, p, -nrm, dist, out.field.values);
        } else {
          paintSegment(grid, p, -nrm, dist, out.field.values, 0.0, 0.5 * h);
          paintSegment(grid, p, -nrm, dist, out.field.values, dist - 0.5 * h, dist);
        }
      }
      if ((++done & 1023) == 0) gate.report(0.95 * double(done) / double(n));
    }
  });
  if (gate.cancelled()) return makeError(ErrorCode::kCancelled, "ray thickness cancelled");
  for (int k = 0; k < threads; ++k) out.rays += rays[size_t(k)], out.accepted += accepted[size_t(k)];
  finishField(grid, out);
  if (!gate.report(1.0)) return makeError(ErrorCode::kCancelled, "ray thickness cancelled");
  return out;
}

}  // namespace vox
