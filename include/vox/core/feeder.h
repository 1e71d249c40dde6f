#pragma once
// A casting's feeder (riser): a cylinder of metal standing on the part, which feeds the part's last metal to freeze
// (vox/analysis/casting.h simulates it; the window keeps each feeder as a part of the scene, vox/core/assembly.h).
#include <string_view>

#include <glm/vec3.hpp>

#include "vox/core/lattice.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

// A cylinder of diameter D and height H standing on the point `base` of the part, along +Z (model units): the
// voxels whose centres lie within D / 2 of the axis and between base.z and base.z + H.
struct Feeder {
  glm::dvec3 base{0.0};
  double diameter = 0.0, height = 0.0;
  bool operator==(const Feeder&) const = default;
};
// The feeder's Chvorinov modulus V/A, its foot (where it stands on the part) not counted as cooling surface:
// D H / (4 H + D).
double feederModulus(const Feeder& feeder);
// "cylinder:X,Y,Z,D,H" (model units), D and H positive.
Result<Feeder> parseFeeder(std::string_view text);
// The cylinder's voxels on the lattice of `frame` (any index, inside the grid or not), inclusive index box; false
// when it lies too far out (2^28 voxels) for indices to hold.
bool feederBox(const Feeder& feeder, const GridFrame& frame, glm::ivec3& lo, glm::ivec3& hi);
bool inFeeder(const Feeder& feeder, const GridFrame& frame, glm::ivec3 voxel);
// The cylinder's voxels on `lattice` as a grid over their box (the same voxels the simulation makes metal).
// kInvalidArgument when it holds no voxel (thinner or shorter than a voxel), kLimit when its box is more than a grid
// holds or lies too far out.
Result<LatticeGrid> feederVoxels(const Feeder& feeder, const Lattice& lattice);

}  // namespace vox
