#pragma once
// Sections at any angle (docs/conventions.md, "Sections at any angle"): the model cut by the plane through a point
// with a given normal, sampled on a square lattice of pixels in the plane, each sample filled when the voxel holding
// it is filled.
#include <cstdint>

#include <glm/vec3.hpp>

#include "vox/core/image.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

struct ObliqueSectionParams {
  glm::dvec3 normal{0.0, 0.0, 1.0};       // any length but zero
  bool point_given = false;               // else the centre of the grid's box
  glm::dvec3 point{0.0};                  // model units
  double offset = 0.0;                    // the plane moved this far along the normal from the point (model units)
  double pixel = 0.0;                     // model units; 0: the voxel size
  int64_t max_pixels = int64_t(1) << 28;  // a larger image is refused (kLimit)
};

struct ObliqueSection {
  glm::dvec3 normal{0.0, 0.0, 1.0};  // unit
  glm::dvec3 point{0.0};             // the plane's point (model units), the offset applied
  // The image's axes in the plane (unit vectors, right and up; u x v = normal; up is +Z laid into the plane, or +Y
  // for a plane near horizontal) and the centre of pixel (0, 0) of the bottom row: pixel (i, j) counted from the
  // bottom has its centre at origin + i pixel u + j pixel v.
  glm::dvec3 u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0};
  glm::dvec3 origin{0.0};
  double pixel = 0.0;
  int64_t filled = 0;  // filled samples
  double area = 0.0;   // filled x pixel^2, model units^2
  // 0 or 1; row 0 is the top (largest v), as the axis sections' images are.
  Image2D<uint8_t> mask;
};

// The image covers the grid's box projected into the plane. Fails (kInvalidArgument) for a zero or non-finite normal
// or point, a pixel that is not positive, and (kLimit) for an image of more than params.max_pixels samples.
Result<ObliqueSection> computeObliqueSection(const VoxelGrid& grid, const ObliqueSectionParams& params);

}  // namespace vox
