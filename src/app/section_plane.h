#pragma once
// The Section panel's plane at any angle placed through picked voxels: through one, keeping its normal, or through
// three, whose plane it becomes. No GL or ImGui here.
#include <vector>

#include <glm/vec3.hpp>

#include "app/app_state.h"
#include "vox/core/result.h"
#include "vox/render/point_cloud.h"

namespace vox::app {

// The unit normal of the plane through three points, its largest component made positive; kInvalidArgument when
// they lie on one line (or two coincide).
Result<glm::dvec3> planeNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Sets `section` to the plane at an angle through the centres of `voxels` (1 or 3, inside `dims`) of the lattice
// `frame`: through one with the section's normal, or through three. Leaves it as it was on an error.
Status placeSectionPlane(SectionUi& section, const GridFrame& frame, const Dims& dims,
                         const std::vector<glm::ivec3>& voxels);

// How far (voxels) the cut's plane is moved along its normal from where the section says: a plane through voxel
// centres (as one through picked voxels is) with a whole-number normal puts centres exactly on the faces of its slab,
// where the GPU's and the CPU's rounding could part; moved a 64th of a voxel, none lies there.
inline constexpr double kPlaneNudge = 1.0 / 64.0;

// The section's plane at an angle as the 3D view cuts it (and its export keeps), in the renderer's voxel coordinates:
// through the centre of the model's box moved `offset` model units along the unit normal, as computeObliqueSection
// places it, then kPlaneNudge voxels further. No cut (SectionAxis::kNone) for a normal that gives no direction.
render::CutAway obliqueCutAway(const GridFrame& frame, const Dims& dims, const SectionUi& section);

}  // namespace vox::app
