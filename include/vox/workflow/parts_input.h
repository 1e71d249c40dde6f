#pragma once
// Parts of a scene from files and models (vox/core/assembly.h; the window's Parts panel): a mesh split into its
// bodies, a voxel model into its connected components, and a mesh or voxel file added as a part on the scene's
// lattice. Each returns the new scene, or why not (nothing is changed).
#include <cstddef>
#include <filesystem>
#include <span>

#include "vox/analysis/assembly.h"
#include "vox/core/assembly.h"
#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/io/mesh_file.h"
#include "vox/voxelize/voxelize.h"

namespace vox::workflow {

// A voxel model with more components than this keeps the largest ones as parts and gathers the rest (loose islands,
// stray voxels) into one part, so a noisy scan does not become thousands of parts.
inline constexpr size_t kMaxComponentParts = 200;

// The bodies of a mesh, each voxelized on the lattice of `model` (the mesh's own grid, as shown): the file's own
// bodies (`file_bodies`, from its reader), named as the file names them (a CAD file's solids, the objects of a file
// with several), else its shells.
Result<Assembly> splitMeshIntoBodies(const TriangleMesh& mesh, std::span<const io::MeshBody> file_bodies, bool cad,
                                     VoxelizeParams params, const VoxelGrid& model, const ProgressFn& progress);
// The connected components of a voxel model, largest first.
Result<Assembly> splitIntoComponents(const VoxelGrid& model, Connectivity connectivity);
// `scene` with the file added as a part: a voxel file on the scene's lattice, a mesh or CAD file voxelized on it (a
// CAD file tessellated for its voxel size). A scene without a lattice takes the file's.
Result<Assembly> addFileAsPart(Assembly scene, const std::filesystem::path& path, VoxelizeParams params,
                               const ProgressFn& progress);

}  // namespace vox::workflow
