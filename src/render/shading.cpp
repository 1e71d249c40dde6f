// Intensity tables over the 64 face-neighbour codes (thesis 5.1, Table 5.2; docs/conventions.md, "Face-neighbour code"
// and "Classic intensity table") and the point size rule (thesis 6.2).
#include "vox/render/shading.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "vox/core/neighbour_code.h"
#include "vox/render/point_cloud.h"

namespace vox::render {

IntensityTable classicTable() {
  IntensityTable t{};
  for (int c = 0; c < 64; ++c) t[size_t(c)] = float(classicIntensity(uint8_t(c))) / float(kClassicIntensityMax);
  return t;
}

glm::dvec3 freeFaceNormalSum(uint8_t code) {
  glm::dvec3 sum(0.0);
  for (size_t f = 0; f < 6; ++f) {
    if (code & kFaceBits[f]) continue;  // neighbour filled: this face is hidden
    sum += glm::dvec3(kFaceNormals[f][0], kFaceNormals[f][1], kFaceNormals[f][2]);
  }
  return sum;
}

IntensityTable litTable(const glm::dvec3& light_dir_world, double ambient) {
  IntensityTable t{};
  const double len = glm::length(light_dir_world);
  const glm::dvec3 light = len > 0.0 ? light_dir_world / len : glm::dvec3(0.0, 0.0, 1.0);
  ambient = std::clamp(ambient, 0.0, 1.0);
  for (int c = 0; c < 63; ++c) {
    const glm::dvec3 sum = freeFaceNormalSum(uint8_t(c));
    double facing = 0.0;
    if (glm::length(sum) > 1e-9) {
      facing = glm::dot(glm::normalize(sum), light);
    } else {
      // Free faces cancel in pairs (x-1 and x+1, ...): a wall or rod one voxel thick. Light it by its best face.
      facing = -1.0;
      for (size_t f = 0; f < 6; ++f) {
        if (uint8_t(c) & kFaceBits[f]) continue;
        facing =
            std::max(facing, glm::dot(glm::dvec3(kFaceNormals[f][0], kFaceNormals[f][1], kFaceNormals[f][2]), light));
      }
    }
    t[size_t(c)] = float(ambient + (1.0 - ambient) * std::max(0.0, facing));
  }
  t[63] = 0.0f;
  return t;
}

double pointCoverageFactor(const Camera& camera, bool round_points, double aspect) {
  const glm::dvec3 r = camera.rightAxis(), u = camera.upAxis();
  double factor = 0.0;
  if (round_points) {
    // The longest of the four cube diagonals projected onto the screen plane.
    for (const glm::dvec3 d : {glm::dvec3(1, 1, 1), glm::dvec3(1, 1, -1), glm::dvec3(1, -1, 1), glm::dvec3(-1, 1, 1)}) {
      factor = std::max(factor, std::hypot(glm::dot(d, r), glm::dot(d, u)));
    }
  } else {
    const auto l1 = [](const glm::dvec3& a) { return std::abs(a.x) + std::abs(a.y) + std::abs(a.z); };
    factor = std::max(l1(r), l1(u));
  }
  if (camera.projection == Projection::kPerspective) {
    const double tan_half = std::tan(camera.fov_y_deg * (3.14159265358979323846 / 360.0));
    const double tan_corner = tan_half * std::sqrt(1.0 + aspect * aspect);
    factor *= std::sqrt(1.0 + tan_corner * tan_corner);  // 1 / cos of the corner angle
  }
  return factor * 1.02;
}

double closedPointSize(double pixels_per_voxel, double coverage_factor) {
  return std::max(1.0, pixels_per_voxel * coverage_factor);
}

}  // namespace vox::render
