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

// Every filled voxel along the segment from p, length t along d (unit), takes t where t is less than what it holds;
// with [from, to], only those along that part. A 3D DDA (Amanatides and Woo): one step per voxel crossed.
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
  for (double s = 0.0; s <= length;) {
    if (c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < n[0] && c[1] < n[1] && c[2] < n[2] &&
        grid.get(c[0], c[1], c[2])) {
      std::atomic_ref<float> cell(field[size_t(c[0] + n[0] * (c[1] + n[1] * c[2]))]);
      float cur = cell.load(std::memory_order_relaxed);
      while (value < cur && !cell.compare_exchange_weak(cur, value, std::memory_order_relaxed)) {
      }
    }
    const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
    s = next[a];
    next[a] += delta[a];
    c[a] += step[a];
  }
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
  parallelChunks(0, int64_t(n), 1024, threads, [&](int th, int64_t b, int64_t e) {
    for (int64_t t = b; t < e && !gate.cancelled(); ++t) {
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
  double sum = 0.0;
  out.min = std::numeric_limits<double>::infinity();
  for (float& value : out.field.values) {
    if (!std::isfinite(value)) {
      value = 0.0f;
      continue;
    }
    ++out.voxels;
    sum += value;
    out.min = std::min(out.min, double(value));
    out.max = std::max(out.max, double(value));
  }
  if (out.voxels == 0) out.min = 0.0;
  out.mean = out.voxels > 0 ? sum / double(out.voxels) : 0.0;
  if (!gate.report(1.0)) return makeError(ErrorCode::kCancelled, "ray thickness cancelled");
  return out;
}

}  // namespace vox
