#pragma once
// The boundary of a voxel model as a closed, manifold triangle mesh (docs/accuracy.md, "Surface meshes").
//
// The faces between filled and empty voxels, with vertices on the voxel corners, oriented outward. Where voxels
// touch only along an edge or at a corner the surface would pinch; there the vertices are split (one per fan of
// faces around the corner, one per filled voxel at the middle of a checkerboard edge) and each copy is moved a
// 1/256 of a voxel towards its own material, so the mesh is manifold even for tools that weld by position. With
// `merge_coplanar`, the faces of each plane and facing are merged into rectangles and every vertex of a
// neighbouring rectangle on a rectangle's side is kept on it (no T-junctions): the mesh stays watertight. The
// enclosed volume is filled x h^3, but for the split vertices' moves (each at most h^3 / 256). The smooth option
// trades that exactness for a surface without steps (for printing a peeled core or a scan).
#include <cstdint>

#include "vox/core/indexed_mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

struct SurfaceMeshParams {
  bool merge_coplanar = true;  // rectangles instead of two triangles per voxel face
  // > 0: a smooth surface (constrained surface nets with Taubin's smoothing, which does not shrink): the voxel
  // faces' mesh with every vertex moved this many pairs of steps towards the mean of its neighbours, each at most
  // 0.45 voxel from its corner on any axis (so within half a voxel of the voxels' boundary, same topology: closed
  // and manifold). Implies no merging.
  int smooth_iterations = 0;
};

struct SurfaceMeshStats {
  int64_t voxel_faces = 0;     // faces between a filled and an empty voxel
  int64_t rectangles = 0;      // after merging (= voxel_faces without it)
  int64_t split_vertices = 0;  // vertex copies made where voxels touch along an edge or at a corner
};

// Fails only when cancelled or when the mesh would exceed 2^32 vertices.
Result<IndexedMesh> extractSurfaceMesh(const VoxelGrid& grid, const SurfaceMeshParams& params = {},
                                       const ProgressFn& progress = {}, SurfaceMeshStats* stats = nullptr);

}  // namespace vox
