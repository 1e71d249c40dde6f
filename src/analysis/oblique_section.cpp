#include "vox/analysis/oblique_section.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>

#include "vox/core/section_plane.h"

namespace vox {
namespace {

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Right and up in the plane: up is +Z laid into the plane (so a vertical cut shows Z up, as the X and Y sections do),
// or +Y for a plane near horizontal (as the Z section does); right = up x normal, so right x up = normal.
void planeAxes(const glm::dvec3& n, glm::dvec3& u, glm::dvec3& v) {
  const glm::dvec3 up = std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  v = glm::normalize(up - n * glm::dot(up, n));
  u = glm::cross(v, n);
}

}  // namespace

Result<ObliqueSection> computeObliqueSection(const VoxelGrid& grid, const ObliqueSectionParams& params) {
  const GridFrame& f = grid.frame();
  const double h = f.voxel_size;
  const glm::dvec3 box_min = f.origin;
  const glm::dvec3 box_max = f.origin + glm::dvec3(grid.nx(), grid.ny(), grid.nz()) * h;
  glm::dvec3 unit;
  if (!finite(params.normal) || !unitVector(params.normal, unit)) {
    return makeError(ErrorCode::kInvalidArgument, "the section's normal must be a non-zero vector");
  }
  const glm::dvec3 point = (params.point_given ? params.point : (box_min + box_max) * 0.5) + unit * params.offset;
  if (!finite(point)) {
    return makeError(ErrorCode::kInvalidArgument, "the section's point and offset must be finite");
  }
  const double pixel = params.pixel == 0.0 ? h : params.pixel;  // 0: the voxel size
  if (!std::isfinite(pixel) || !(pixel > 0.0)) {
    return makeError(ErrorCode::kInvalidArgument, "the section's pixel size must be a positive number");
  }
  if (pixel > glm::length(box_max - box_min)) {
    return makeError(ErrorCode::kInvalidArgument, "the section's pixel size is larger than the whole model");
  }
  ObliqueSection s;
  s.normal = unit;
  s.point = point;
  s.pixel = pixel;
  planeAxes(s.normal, s.u, s.v);
  // The box's corners in the plane's coordinates about the point: the image spans them.
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? box_max.x : box_min.x, (c & 2) ? box_max.y : box_min.y,
                       (c & 4) ? box_max.z : box_min.z);
    const double a = glm::dot(p - point, s.u), b = glm::dot(p - point, s.v);
    u0 = std::min(u0, a), u1 = std::max(u1, a), v0 = std::min(v0, b), v1 = std::max(v1, b);
  }
  const double wide = std::ceil((u1 - u0) / pixel), high = std::ceil((v1 - v0) / pixel);
  if (!(wide * high <= double(params.max_pixels)) || !(wide <= 1e9) || !(high <= 1e9)) {
    char size[64];
    std::snprintf(size, sizeof size, "%.3g x %.3g", wide, high);
    return makeError(ErrorCode::kLimit,
                     std::string("the section would be ") + size + " pixels: choose a larger pixel size");
  }
  const auto w = int32_t(std::max(1.0, wide)), ht = int32_t(std::max(1.0, high));
  s.origin = point + (u0 + 0.5 * pixel) * s.u + (v0 + 0.5 * pixel) * s.v;
  s.mask = Image2D<uint8_t>(w, ht, 0);
  const glm::dvec3 du = s.u * (pixel / h), dv = s.v * (pixel / h);
  const glm::dvec3 start = (s.origin - f.origin) / h;  // pixel (0, 0) in voxel units
  for (int32_t j = 0; j < ht; ++j) {
    const glm::dvec3 row = start + double(j) * dv;
    for (int32_t i = 0; i < w; ++i) {
      const glm::dvec3 p = row + double(i) * du;
      const double x = std::floor(p.x), y = std::floor(p.y), z = std::floor(p.z);
      // (written so that NaN is outside too)
      if (!(x >= 0 && y >= 0 && z >= 0 && x < grid.nx() && y < grid.ny() && z < grid.nz())) continue;
      if (!grid.get(int64_t(x), int64_t(y), int64_t(z))) continue;
      s.mask.at(i, ht - 1 - j) = 1;
      ++s.filled;
    }
  }
  s.area = double(s.filled) * pixel * pixel;
  return s;
}

}  // namespace vox
