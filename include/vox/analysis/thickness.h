#pragma once
// Local thickness (Hildebrand and Rüegsegger 1997), thin walls and hot spots, all from the exact distance field
// (vox/analysis/distance.h). Definitions in docs/accuracy.md ("Distance and thickness"):
//  - the inscribed ball of a filled voxel c: the voxel centres p with |p - c| < r(c), r(c) its distance (so the ball
//    holds only filled voxels);
//  - local thickness of a filled voxel p: 2 R(p), R(p) the largest r(c) over the inscribed balls that contain p,
//    in model units;
//  - thin walls: filled voxels thinner than a minimum wall, in 26-connected regions;
//  - hot spots: regional maxima of the distance field that stand out by at least a voxel.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/analysis/distance.h"
#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/scalar_field.h"
#include "vox/core/voxel_grid.h"

namespace vox {

struct ThicknessParams {
  int32_t histogram_bins = 32;  // equal bins over [0, max]
  // The instructions the painting may use: kAuto takes AVX-512 where the processor has it, else AVX2 where it has
  // that, kSse2 only what every x86-64 processor has. The result is the same (the tests check each walk against a
  // brute force).
  enum class Simd { kAuto, kSse2 };
  Simd simd = Simd::kAuto;
};

struct ThicknessStats {
  int64_t voxels = 0;                       // filled voxels
  double min = 0.0, max = 0.0, mean = 0.0;  // model units
  std::vector<double> edges;                // histogram_bins + 1 edges, model units
  std::vector<int64_t> counts;              // voxels per bin; a value equal to an inner edge goes to the bin above it
};

struct Thickness {
  // Squared radius R^2 (voxel units^2) of the largest inscribed ball containing each filled voxel, over the distance
  // field's box (dense layout); 0 in empty voxels. Thickness = 2 R h.
  DistanceField radius;
  ThicknessStats stats;
  int64_t ball_centres = 0;  // balls painted (the distance ridge left by the containment test)

  // Local thickness of a voxel in model units (0 for empty voxels) and in voxels.
  double model(int64_t x, int64_t y, int64_t z) const { return voxels(x, y, z) * radius.voxelSize(); }
  double voxels(int64_t x, int64_t y, int64_t z) const { return 2.0 * radius.voxels(x, y, z); }
};

// Local thickness of every filled voxel from its distance field. A ball that lies inside the larger ball of a voxel
// within nine voxels on each axis (tested exactly on the voxel centres) is skipped; the rest are painted largest
// first, each voxel once, threads owning layers of 64-voxel blocks, with AVX-512 or AVX2 where the processor has it.
// Cost: about the open voxels' bricks along each kept ball's boundary, which on bulky parts at high resolution is large
// (docs/performance.md); memory: a dense copy of the field, about 1 bit per voxel of the box rounded up to 64 voxels on
// each axis, 12 bytes per kept ball and a table of 438 bytes per squared radius up to the
// largest (the rvalue overload reuses a dense field: pass std::move(field) when it is not needed afterwards; it is
// lost on error; a packed one is copied dense and released).
Result<Thickness> computeThickness(const DistanceField& distance, const ThicknessParams& params = {},
                                   const ProgressFn& progress = {});
Result<Thickness> computeThickness(DistanceField&& distance, const ThicknessParams& params = {},
                                   const ProgressFn& progress = {});

// ---- Thin walls ----
struct ThinWallRegion {
  int64_t voxels = 0;
  int64_t exposed_faces = 0;                     // faces of the region's voxels whose face neighbour is empty
  double area = 0.0;                             // exposed_faces * h^2, model units^2
  glm::ivec3 bbox_min_ijk{0}, bbox_max_ijk{-1};  // inclusive voxel indices
  Box3d bbox;                                    // outer faces of those voxels, model units
  double min = 0.0;                              // thinnest local thickness in the region, model units
};
struct ThinWalls {
  double min_wall = 0.0;                // model units
  int64_t voxels = 0;                   // filled voxels with thickness < min_wall
  std::vector<ThinWallRegion> regions;  // 26-connected, largest (voxels) first
};
// Filled voxels whose local thickness is below min_wall (model units), grouped in 26-connected regions.
Result<ThinWalls> findThinWalls(const Thickness& thickness, double min_wall, const ProgressFn& progress = {});

// ---- Hot spots ----
struct HotSpotParams {
  // A regional maximum is reported when its dynamic (its radius minus the radius of the lowest saddle on the best
  // path to a higher maximum) is at least this many voxels; smaller ones are discretisation noise.
  double min_dynamic_voxels = 1.0;
  // ... and isolated when the dynamic is at least this many voxels (a neck clearly thinner than the spot).
  double isolation_voxels = 2.0;
  // Both also as fractions of the spot's own radius: a bump on one thick region is that region's, not a spot of its
  // own, at any resolution (reported: dynamic >= 10% of the radius; isolated: the neck 20% thinner than the spot).
  double min_dynamic_fraction = 0.1;
  double isolation_fraction = 0.2;
};
struct HotSpot {
  glm::dvec3 centre{0.0};  // model units: the mean of the plateau's voxel centres (the grid's placement)
  glm::ivec3 voxel{0};     // the plateau voxel nearest that mean
  int64_t plateau_voxels = 1;
  double radius = 0.0;  // inscribed radius (the distance at the maximum), model units
  // The geometric (Chvorinov) modulus V/A of the region this spot feeds (the basins of the maxima merged into it),
  // model units: radius x mean depth / (radius - mean depth), which is half a plate's thickness, a quarter of a
  // square bar's side, a sixth of a cube's side or a sphere's diameter (docs/accuracy.md, "Hot spots").
  double modulus = 0.0;
  double dynamic = 0.0;  // radius minus saddle radius, model units (the global maximum: its radius)
  double saddle = 0.0;   // radius at the saddle where it merges into a higher maximum, model units (0: never)
  bool isolated = false;
};
// Regional maxima of the distance field (26-connected plateaus), largest radius first; the first is the global
// maximum, the orientation-free core. Memory: 2 bytes per voxel of the field's box (with 32768 summits
// or more 4, and 6 while the labels widen), and a dense copy of a packed field (pass a dense one where there is).
Result<std::vector<HotSpot>> findHotSpots(const DistanceField& distance, const HotSpotParams& params = {},
                                          const ProgressFn& progress = {});

// ---- The geometric (Chvorinov) modulus ----
// Every filled voxel's modulus V/A (model units; 0 in empty voxels) over the grid: the modulus of the hot spot whose
// region holds it (the region its distance ridge climbs to, as findHotSpots reports), at most half its local
// thickness where `radius` is given (Thickness::radius): a thin fin on a thick boss reads as the fin it is, not as the
// boss. Plates read half their thickness, bars a quarter of their side, cubes and spheres a sixth of their side or
// diameter (docs/accuracy.md, "Hot spots"). Memory: findHotSpots' labels kept to the end (2 or 4 bytes per voxel of
// the box), the field over the box and then over the grid (4 bytes per voxel of each).
Result<ScalarField> computeModulusField(const DistanceField& distance, const DistanceField* radius,
                                        const HotSpotParams& params = {}, const ProgressFn& progress = {});

}  // namespace vox
