#pragma once
// Intensity tables indexed by the 6-bit face-neighbour code (thesis 5.1; docs/conventions.md, "Face-neighbour code" and
// "Classic intensity table") and the point-size rule of thesis 6.2. Pure CPU; the point shader receives the table as
// `uniform float u_intensity[64]`.
#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

#include "vox/render/camera.h"

namespace vox::render {

// Which table shades the surface points.
//  - kClassic: the thesis's Table 5.2 (docs/conventions.md, "Classic intensity table"), intensity I/20, fixed
//    light "from the top right" of a screen that is the z = 0 plane; the reference in tests.
//  - kLit: recomputed each frame from a light direction given in view space, so the light moves with the camera.
enum class Lut { kClassic, kLit };

using IntensityTable = std::array<float, 64>;

// Classic table as 0..1 intensities (I / 20). Code 63 (interior, never drawn) is 0.
IntensityTable classicTable();

// Sum of the outward unit normals of a code's free faces (the faces whose neighbour is empty), in voxel space.
// Zero for code 63 and for codes whose free faces cancel (e.g. only x-1 and x+1 free).
glm::dvec3 freeFaceNormalSum(uint8_t code);

// The `lit` table: for each code, n = normalize(freeFaceNormalSum(code)), and
//   intensity = ambient + (1 - ambient) * max(0, dot(n, light)),
// `light` being the unit direction towards the light in voxel (world) space. When the free-face normals cancel
// (a one-voxel-thick wall or rod), n is the free face most facing the light, so thin features are not left dark.
// Code 63 is 0. `ambient` in [0, 1].
IntensityTable litTable(const glm::dvec3& light_dir_world, double ambient);

// Default light for kLit, in view space (x right, y up, z towards the viewer): from the upper right, in front,
// like the thesis's fixed light, and mostly frontal so faces turned to the viewer are well lit.
inline constexpr glm::dvec3 kDefaultLightView{0.35, 0.5, 0.8};
inline constexpr double kDefaultAmbient = 0.25;

// ---- Point size (thesis 6.2: the point size S follows the zoom and the resolution) ----
//
// Every pixel inside the silhouette of a solid sees, first, a surface voxel: the ray enters that voxel's cube through
// a face whose neighbour is empty, a face turned towards the eye, so the voxel's code group is drawn. The pixel lies
// inside that cube's projection. A point drawn at the cube's centre that covers the cube's whole projection
// therefore leaves no pixel of the silhouette uncovered. With p = pixels per voxel edge (camera.h
// pixelsPerVoxel), the projection of a unit cube reaches, from its centre,
//  - along the screen's x axis: p/2 * (|r.x| + |r.y| + |r.z|), r = the camera's right axis, and likewise along y
//    with the up axis; a square point of side p * max of the two sums covers it (1 in axis views, sqrt 2 for a face
//    turned 45 degrees on screen, at most sqrt 3);
//  - in any direction: p/2 * the longest projected cube diagonal; a round point of that diameter covers it
//    (sqrt 2 in axis views, at most sqrt 3).
// Under perspective, a cube off the view axis at angle t projects larger by up to 1 / cos t; the factor includes
// that for the corners of the view. A 2% margin keeps pixel centres lying exactly on a point's edge covered.
// Returns the diameter of a point in units of p.
double pointCoverageFactor(const Camera& camera, bool round_points, double aspect);

// Point diameter in pixels for `pixels_per_voxel` and a coverage factor: at least 1 pixel.
double closedPointSize(double pixels_per_voxel, double coverage_factor);

}  // namespace vox::render
