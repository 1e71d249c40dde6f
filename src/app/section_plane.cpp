#include "app/section_plane.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "app/action_functions.h"
#include "vox/core/text.h"

namespace vox::app {

Result<glm::dvec3> planeNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a;
  const glm::dvec3 n = glm::cross(ab, ac);
  const double scale = glm::length(ab) * glm::length(ac);
  if (!(scale > 0.0) || !(glm::length(n) > 1e-9 * scale)) {
    return makeError(ErrorCode::kInvalidArgument, "the three points lie on one line; pick three that span a plane");
  }
  glm::dvec3 unit;
  if (!unitVector(n, unit)) {
    return makeError(ErrorCode::kInvalidArgument, "the three points are too close together to give a plane");
  }
  if (unit[dominantAxis(unit)] < 0.0) unit = -unit;
  return unit;
}

Status placeSectionPlane(SectionUi& section, const GridFrame& frame, const Dims& dims,
                         const std::vector<glm::ivec3>& voxels) {
  if (voxels.size() != 1 && voxels.size() != 3) {
    return makeError(ErrorCode::kInvalidArgument, "a section's plane goes through one picked voxel or three");
  }
  std::vector<glm::dvec3> points;
  for (const glm::ivec3& v : voxels) {
    if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= dims.nx || v.y >= dims.ny || v.z >= dims.nz) {
      return makeError(ErrorCode::kInvalidArgument, "voxel (" + std::to_string(v.x) + ", " + std::to_string(v.y) +
                                                        ", " + std::to_string(v.z) + ") is outside the model's grid");
    }
    points.push_back(frame.voxelCentre(v.x, v.y, v.z));
  }
  glm::dvec3 normal = section.normal;
  if (points.size() == 3) {
    auto n = planeNormal(points[0], points[1], points[2]);
    if (!n) return n.error();
    normal = *n;
  }
  glm::dvec3 unit;
  if (!unitVector(normal, unit)) return makeError(ErrorCode::kInvalidArgument, "the section's normal is zero");
  const glm::dvec3 centre = frame.origin + 0.5 * frame.voxel_size * glm::dvec3(dims.nx, dims.ny, dims.nz);
  section.normal = normal;
  section.offset = glm::dot(unit, points[0] - centre);
  section.oblique = true;
  return Ok{};
}

render::CutAway obliqueCutAway(const GridFrame& frame, const Dims& dims, const SectionUi& section) {
  render::CutAway cut;
  glm::dvec3 n;
  if (!unitVector(section.normal, n) || !(frame.voxel_size > 0.0)) return cut;  // no cut
  const glm::dvec3 centre = 0.5 * glm::dvec3(dims.nx, dims.ny, dims.nz);
  const double offset = glm::dot(n, centre) + section.offset / frame.voxel_size + kPlaneNudge;
  if (!std::isfinite(offset)) return cut;
  cut.axis = render::SectionAxis::kPlane;
  cut.normal = glm::vec3(n);
  cut.offset = float(offset);
  return cut;
}

}  // namespace vox::app

namespace vox::app::actions {

// I J K, or I1 J1 K1 I2 J2 K2 I3 J3 K3: the section at an angle through those voxels (as placeSectionPlane).
Status sectionPlaneThrough(AppState& s, const ActionArgs& a) {
  if (a.words.size() != 3 && a.words.size() != 9) {
    return badValues("section-plane-through takes I J K (one voxel, the normal kept) or three voxels' I J K");
  }
  std::vector<glm::ivec3> voxels(a.words.size() / 3);
  for (size_t i = 0; i < a.words.size(); ++i) {
    if (!parseNumber(a.words[i], voxels[i / 3][int(i % 3)])) {
      return badValues("section-plane-through: '" + a.words[i] + "' is not a voxel index");
    }
  }
  if (Status st = placeSectionPlane(s.section, s.model.frame(), s.model.dims(), voxels); !st) {
    return badValues("section-plane-through: " + st.error().message);
  }
  showPanel(s, Panel::kSection);
  return Ok{};
}

}  // namespace vox::app::actions
