#pragma once
// Orbit camera for the voxel views (thesis 6.2: display size set by the zoom, views rotated about the model).
// Pure CPU maths on GLM, no GL: the GUI and the headless renderer share it.
//
// World space is voxel-index space: voxel (i, j, k) occupies [i, i+1) x [j, j+1) x [k, k+1), so its centre is
// (i + 0.5, j + 0.5, k + 0.5). Rendering does not need the grid's model units (voxels are cubes).
//
// Orientation follows the thesis, whose screen is the z = 0 plane with X to the right and Y up: yaw = pitch = 0 looks
// along -Z from the +Z side. Yaw (degrees) turns the camera about the world Y axis, positive towards +X; pitch
// (degrees, clamped to [-90, 90]) raises it towards +Y. The direction from the target to the eye is
//   (sin(yaw) cos(pitch), sin(pitch), cos(yaw) cos(pitch)).
// The view matrix is built from yaw and pitch directly (not lookAt), so straight-down and straight-up views work.
#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vox::render {

enum class Projection { kPerspective, kOrthographic };

// Views from a side of the model: kPosX puts the camera on the +X side looking towards -X, and so on. kIso looks
// from the (+X, +Y, +Z) octant along the (-1, -1, -1) diagonal.
enum class StandardView { kPosX, kNegX, kPosY, kNegY, kPosZ, kNegZ, kIso };

// An axis-aligned box in voxel-index space (corners, not voxel centres).
struct Box3 {
  glm::dvec3 min{0.0};
  glm::dvec3 max{0.0};
  glm::dvec3 centre() const { return (min + max) * 0.5; }
  double radius() const;  // half the diagonal: the bounding sphere about centre()
};

struct Camera {
  Projection projection = Projection::kPerspective;
  glm::dvec3 target{0.0};  // orbit centre, voxel units
  double distance = 10.0;  // eye to target, voxel units (> 0)
  double yaw_deg = 0.0;
  double pitch_deg = 0.0;
  double fov_y_deg = 30.0;  // vertical field of view of the perspective projection
  // The orthographic projection shows the same extent at the target as the perspective one does: its half height
  // is distance * tan(fov_y / 2). Zooming (changing distance) therefore works the same in both projections.

  // Unit vector from the target towards the eye.
  glm::dvec3 eyeDirection() const;
  glm::dvec3 eyePosition() const { return target + eyeDirection() * distance; }
  // Camera axes in world space (right-handed: right x up = towards the eye).
  glm::dvec3 rightAxis() const;
  glm::dvec3 upAxis() const;
  // Half the visible height at the target's depth, voxel units.
  double halfHeightAtTarget() const;

  // World to view: the eye at the origin looking along -Z, Y up.
  glm::dmat4 viewMatrix() const;
  // View to clip for this aspect (width / height) and depth range (near > 0 for perspective).
  glm::dmat4 projectionMatrix(double aspect, double near_plane, double far_plane) const;
  // A near/far pair that encloses `box` with a margin (for projectionMatrix).
  glm::dvec2 depthRange(const Box3& box) const;
  // projectionMatrix(aspect, depthRange(box)) * viewMatrix().
  glm::dmat4 viewProjection(double aspect, const Box3& box) const;

  // ---- Interaction (the GUI maps mouse drags to these) ----
  // Turn about the target by these angles (degrees); pitch stays within [-90, 90], yaw wraps to (-180, 180].
  void orbit(double delta_yaw_deg, double delta_pitch_deg);
  // Move the target in the view plane by a drag of (dx, dy) pixels (x right, y down) in a viewport of this height,
  // so the point under the cursor follows it at the target's depth.
  void pan(double dx_px, double dy_px, double viewport_height_px);
  // Multiply the apparent size by `factor` (> 1 zooms in): distance /= factor.
  void zoom(double factor);
  // Look at the box's centre from the current direction, from the smallest distance at which all eight corners of
  // the box, scaled by `margin` about its centre (1 = touching the edges), lie inside the view of this aspect
  // (width / height). Exact for both projections; the box is projected, not its bounding sphere.
  void fitToBox(const Box3& box, double aspect, double margin = 1.05);
  // Set yaw and pitch for a standard view (target and distance unchanged).
  void setStandardView(StandardView view);
};

// Yaw and pitch (degrees) of a standard view.
glm::dvec2 standardViewAngles(StandardView view);

// The same view of the same part in another grid's voxel-index space, for a model re-voxelized at another
// resolution (or an undo back to one): a point p of grid A is the model point from_origin + p * from_voxel, and in
// grid B it is (that - to_origin) / to_voxel. Target and distance move with it; the angles stay.
Camera reframed(const Camera& camera, const glm::dvec3& from_origin, double from_voxel, const glm::dvec3& to_origin,
                double to_voxel);

// Pixels covered by one voxel edge at view-space depth `depth` (distance along the view axis; ignored for
// orthographic) in a viewport `viewport_height_px` tall. The thesis's "point size S" (section 6.2).
double pixelsPerVoxel(const Camera& camera, double viewport_height_px, double depth);

}  // namespace vox::render
