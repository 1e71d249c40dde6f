#pragma once
// Ray thickness (`voxmod thickness --method ray`): measured on the mesh's own surface, along its inward normal, to the
// opposite wall, with Embree's rays. From points spread over every triangle (about two per voxel face of area), a ray
// goes inward along the triangle's normal; where it leaves the material through a triangle facing back within
// `angle_deg` (the two sides face each other), the wall's thickness is the ray's length, and every filled voxel the
// ray crosses takes the least such length (a ray longer than paint_limit: the voxels at its ends only). Rays leaving
// through a side that does not face back (a convex edge, a grazing wall) measure nothing: an edge is no wall. Voxels no
// accepted ray crosses hold 0 (no reading).
#include <cstdint>

#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/scalar_field.h"
#include "vox/core/voxel_grid.h"

namespace vox {

struct RayThicknessParams {
  double angle_deg = 30.0;      // the most the opposite side's normal may turn from facing back
  double samples_per_face = 2;  // ray origins per voxel face of triangle area
  // A ray longer than this (model units; <= 0: no limit) runs along the part, not across a wall: only the voxels at
  // its two ends take its length, not those between (the workflow passes the thickest inscribed ball's diameter,
  // twice the deepest distance, plus two voxels).
  double paint_limit = 0.0;
};

struct RayThicknessResult {
  ScalarField field;               // model units, over the grid; 0 where no accepted ray crosses a filled voxel
  int64_t rays = 0, accepted = 0;  // rays cast, and those that met a facing side
  int64_t voxels = 0;              // filled voxels with a reading
  double min = 0.0, max = 0.0, mean = 0.0;  // over those voxels, model units
};

// The ray thickness of `mesh` (model units, the units of the grid's frame) on the voxels of `grid` (the mesh's
// voxelization). Memory: 4 bytes per grid voxel and Embree's scene (about 100 bytes per triangle).
Result<RayThicknessResult> computeRayThickness(const TriangleMesh& mesh, const VoxelGrid& grid,
                                               const RayThicknessParams& params = {}, const ProgressFn& progress = {});

}  // namespace vox
