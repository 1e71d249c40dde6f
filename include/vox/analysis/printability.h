#pragma once
// Printability for additive manufacturing (`voxmod printcheck`, the Print panel; docs/conventions.md,
// "Printability"):
//  - overhangs: surfaces facing down more steeply than the overhang angle (measured from the vertical: a vertical
//    wall is 0 degrees, a ceiling 90), except those lying on the build plate (the part's lowest voxel layer);
//  - support: the empty space straight below them, down to the part or the plate, measured along rays parallel to
//    the build direction, one per voxel face of the plate's area, cast with Embree against the part's surface;
//  - trapped cavities: empty regions (6-connected) with no path to the outside, each with the shortest straight
//    drain hole along one of 26 lattice directions;
//  - orientation: the same for a set of build directions, least support first.
// The surface is the mesh's own where there is a mesh. For a voxel file the rays cross the voxels' faces (exact
// intervals), and where a ray enters the part the slope is read from the ball of radius 4 voxels about the voxel
// entered (the centroid of its filled voxels lies along the normal), so that a slope is a slope and not a staircase
// of ceilings.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

struct PrintParams {
  glm::dvec3 up{0.0, 0.0, 1.0};      // the build direction: away from the plate (normalised by the callers)
  double overhang_angle_deg = 45.0;  // a downward surface tilted more than this from the vertical needs support
  double ray_spacing = 0.0;          // model units between rays; <= 0: the grid's voxel size
  bool fields = false;               // paint the overhang and support voxels (PrintSupport::overhang, support)
};

// One build direction's overhangs and support.
struct PrintSupport {
  glm::dvec3 direction{0.0, 0.0, 1.0};
  double overhang_area = 0.0;   // model units^2: each overhang side a ray enters, the ray's share over |cos|
  double support_volume = 0.0;  // model units^3, from the rays
  double height = 0.0;          // the part's extent along the direction (the build height), model units
  int64_t rays = 0;             // rays cast
  // With params.fields, on the grid: the filled voxels just above an overhang, and the empty voxels of the support
  // (clipped to the grid's box, which holds all of it for the six axis directions).
  std::optional<VoxelGrid> overhang, support;
};

// The part's surface made ready for rays: its mesh (model units), or the voxels' faces.
class PrintSurface {
 public:
  PrintSurface(PrintSurface&&) noexcept;
  PrintSurface& operator=(PrintSurface&&) noexcept;
  ~PrintSurface();
  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  friend Result<PrintSurface> makePrintSurface(const VoxelGrid&, const TriangleMesh*, const ProgressFn&);
  explicit PrintSurface(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// `mesh`: the part's own mesh in model units (the grid is its voxelization), or null to use the voxels.
Result<PrintSurface> makePrintSurface(const VoxelGrid& grid, const TriangleMesh* mesh, const ProgressFn& progress = {});

// Overhang area and support volume for params.up. Fails only when cancelled (or with kInvalidArgument for a zero
// direction or an angle outside [0, 90)).
Result<PrintSupport> computePrintSupport(const PrintSurface& surface, const VoxelGrid& grid, const PrintParams& params,
                                         const ProgressFn& progress = {});

// ---- Trapped cavities ----
struct DrainHole {
  glm::dvec3 from{0.0}, to{0.0};  // the cavity's wall and the outside surface, model units (voxel centres)
  glm::ivec3 step{0};             // the lattice direction drilled, each component -1, 0 or 1
  double length = 0.0;            // through the material, model units
};
struct TrappedCavity {
  int64_t voxels = 0;
  double volume = 0.0;                // model units^3
  glm::dvec3 centre{0.0};             // mean of its voxel centres, model units
  Box3d bbox;                         // the faces of its outermost voxels, model units
  glm::ivec3 box_min{0}, box_max{0};  // voxel indices, inclusive
  std::optional<DrainHole> drain;     // none when no straight lattice line reaches the outside
};
// Empty regions, 6-connected, that reach neither the grid's border nor, through empty voxels, anything that does;
// largest first. Memory: a second grid (the empty voxels) and about 24 bytes per run of empty voxels.
Result<std::vector<TrappedCavity>> findTrappedCavities(const VoxelGrid& grid, const ProgressFn& progress = {});
// The cavities' voxels as one grid (dims and frame of `grid`).
VoxelGrid trappedCavityGrid(const VoxelGrid& grid);

// ---- Orientation ----
// The six axis directions (+z first), then `sphere` directions spread evenly over the sphere (a Fibonacci lattice).
std::vector<glm::dvec3> printDirections(int sphere);
// computePrintSupport for each direction (no fields), least support first (ties: less overhang, then lower).
Result<std::vector<PrintSupport>> searchPrintOrientations(const PrintSurface& surface, const VoxelGrid& grid,
                                                          const std::vector<glm::dvec3>& directions,
                                                          const PrintParams& params, const ProgressFn& progress = {});

// "+z", "-x", ... for an axis direction, else "x, y, z" with 4 decimals.
std::string printDirectionName(glm::dvec3 d);
// Parses "+z|-z|+x|-x|+y|-y|X,Y,Z" into a unit vector; kInvalidArgument with the reason otherwise.
Result<glm::dvec3> parsePrintDirection(const std::string& text);

}  // namespace vox
