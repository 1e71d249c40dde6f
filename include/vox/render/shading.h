#pragma once
// Intensity tables indexed by the 6-bit face-neighbour code (thesis 5.1, SPEC sections 2 and 3) and the point-size
// rule of thesis 6.2. Pure CPU; the point shader receives the table as `uniform float u_intensity[64]`.
#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

namespace vox::render {

// Which table shades the surface points.
//  - kClassic: the thesis's Table 5.2 (SPEC section 3), intensity I/20, fixed light "from the top right" of a
//    screen that is the z = 0 plane; the reference in tests.
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

// Point diameter in pixels that keeps a surface closed, from the projected size of one voxel edge in pixels
// (`pixels_per_voxel`, see camera.h pixelsPerVoxel). The centres of the points of a flat voxel face form a 2D
// lattice whose basis vectors are at most pixels_per_voxel long on screen; the largest empty circle of such a lattice
// has radius pixels_per_voxel / sqrt(2) (square lattice, e.g. a face seen from above with the camera yawed 45
// degrees). Both square and round points therefore get a diameter of sqrt(2) * pixels_per_voxel, at least 1 pixel.
double closedPointSize(double pixels_per_voxel);
inline constexpr double kPointClosingFactor = 1.41421356237;

}  // namespace vox::render
