// Orbit camera maths (thesis 6.2: zoom and rotated views of the voxel display). See camera.h for the conventions.
#include "vox/render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace vox::render {

double Box3::radius() const { return glm::length(max - min) * 0.5; }

glm::dvec3 Camera::eyeDirection() const {
  const double yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
  return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

glm::dvec3 Camera::rightAxis() const {
  const double yaw = glm::radians(yaw_deg);
  return {std::cos(yaw), 0.0, -std::sin(yaw)};  // the view's +X: world +X turned by yaw about Y; pitch keeps it
}

glm::dvec3 Camera::upAxis() const { return glm::cross(eyeDirection(), rightAxis()); }

double Camera::halfHeightAtTarget() const { return distance * std::tan(glm::radians(fov_y_deg) * 0.5); }

glm::dmat4 Camera::viewMatrix() const {
  // Inverse of: eye = target + R * (0, 0, distance), R = Ry(yaw) * Rx(-pitch).
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -distance));
  m = glm::rotate(m, glm::radians(pitch_deg), glm::dvec3(1.0, 0.0, 0.0));
  m = glm::rotate(m, -glm::radians(yaw_deg), glm::dvec3(0.0, 1.0, 0.0));
  return glm::translate(m, -target);
}

glm::dmat4 Camera::projectionMatrix(double aspect, double near_plane, double far_plane) const {
  if (projection == Projection::kPerspective) {
    return glm::perspective(glm::radians(fov_y_deg), aspect, near_plane, far_plane);
  }
  const double h = halfHeightAtTarget();
  return glm::ortho(-h * aspect, h * aspect, -h, h, near_plane, far_plane);
}

glm::dvec2 Camera::depthRange(const Box3& box) const {
  // Depth of the box's bounding sphere along the view axis, padded so points on it are not clipped.
  const double r = std::max(box.radius(), 0.5) * 1.05 + 1.0;
  const double centre_depth = glm::dot(eyePosition() - box.centre(), eyeDirection());
  double near_plane = centre_depth - r, far_plane = centre_depth + r;
  if (projection == Projection::kPerspective) {
    // A near plane too close to the eye wastes depth precision; 1/1000 of the far plane keeps 24-bit depth useful.
    near_plane = std::max(near_plane, far_plane * 1e-3);
    far_plane = std::max(far_plane, near_plane * 2.0);
  }
  return {near_plane, far_plane};
}

glm::dmat4 Camera::viewProjection(double aspect, const Box3& box) const {
  const glm::dvec2 range = depthRange(box);
  return projectionMatrix(aspect, range.x, range.y) * viewMatrix();
}

void Camera::orbit(double delta_yaw_deg, double delta_pitch_deg) {
  yaw_deg = std::remainder(yaw_deg + delta_yaw_deg, 360.0);
  if (yaw_deg <= -180.0) yaw_deg += 360.0;
  pitch_deg = std::clamp(pitch_deg + delta_pitch_deg, -90.0, 90.0);
}

void Camera::pan(double dx_px, double dy_px, double viewport_height_px) {
  if (viewport_height_px <= 0.0) return;
  const double units_per_px = 2.0 * halfHeightAtTarget() / viewport_height_px;
  // Dragging right moves the model right, i.e. the target (the view centre) left.
  target -= rightAxis() * (dx_px * units_per_px);
  target += upAxis() * (dy_px * units_per_px);
}

void Camera::zoom(double factor) {
  if (factor > 0.0 && std::isfinite(factor)) distance /= factor;
}

void Camera::fitToBox(const Box3& box, double aspect, double margin) {
  target = box.centre();
  const double tan_y = std::tan(glm::radians(fov_y_deg) * 0.5);
  const double tan_x = tan_y * aspect;
  const glm::dvec3 right = rightAxis(), up = upAxis(), back = eyeDirection();
  // Each corner in view axes relative to the target, grown by the margin; a degenerate box still gets a size.
  const glm::dvec3 half = glm::max((box.max - box.min) * 0.5, glm::dvec3(0.5));
  double needed = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner =
        glm::dvec3((i & 1) ? half.x : -half.x, (i & 2) ? half.y : -half.y, (i & 4) ? half.z : -half.z) * margin;
    const double x = std::abs(glm::dot(corner, right)), y = std::abs(glm::dot(corner, up));
    if (projection == Projection::kPerspective) {
      // The corner lies at depth distance - z; it is inside when |x| <= depth * tan_x and |y| <= depth * tan_y.
      const double z = glm::dot(corner, back);
      needed = std::max({needed, z + x / tan_x, z + y / tan_y});
    } else {
      // The visible half extents at any depth are distance * tan_x and distance * tan_y.
      needed = std::max({needed, x / tan_x, y / tan_y});
    }
  }
  distance = needed;
}

glm::dvec2 standardViewAngles(StandardView view) {
  switch (view) {
    case StandardView::kPosX:
      return {90.0, 0.0};
    case StandardView::kNegX:
      return {-90.0, 0.0};
    case StandardView::kPosY:
      return {0.0, 90.0};
    case StandardView::kNegY:
      return {0.0, -90.0};
    case StandardView::kPosZ:
      return {0.0, 0.0};
    case StandardView::kNegZ:
      return {180.0, 0.0};
    case StandardView::kIso:
      return {45.0, glm::degrees(std::atan(1.0 / std::sqrt(2.0)))};  // 35.26 degrees
  }
  return {0.0, 0.0};
}

void Camera::setStandardView(StandardView view) {
  const glm::dvec2 a = standardViewAngles(view);
  yaw_deg = a.x;
  pitch_deg = a.y;
}

double pixelsPerVoxel(const Camera& camera, double viewport_height_px, double depth) {
  const double half_height = camera.projection == Projection::kPerspective
                                 ? std::max(depth, 1e-9) * std::tan(glm::radians(camera.fov_y_deg) * 0.5)
                                 : camera.halfHeightAtTarget();
  return viewport_height_px / (2.0 * half_height);
}

Camera reframed(const Camera& camera, const glm::dvec3& from_origin, double from_voxel, const glm::dvec3& to_origin,
                double to_voxel) {
  Camera out = camera;
  out.target = (from_origin + camera.target * from_voxel - to_origin) / to_voxel;
  out.distance = camera.distance * from_voxel / to_voxel;
  return out;
}

}  // namespace vox::render
