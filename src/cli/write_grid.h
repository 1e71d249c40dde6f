#pragma once
// A grid written in the format its output's extension names, as `voxmod convert` writes that format: a voxel file
// (.vxm, .binvox), a volume of the voxels (.vti, .vdb, .nrrd, .vox) or the surface of the voxels as a mesh (.stl,
// .ply, .obj, .3mf). Used by `voxmod batch` (one output per input) and `voxmod boolean`.
#include <filesystem>
#include <string>

#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox::cli {

// True for every extension writeGridAs takes.
bool isGridOutput(const std::filesystem::path& out);
// "OUT: unknown output format (voxels: .vxm, .binvox; volumes: ...; surface: ...)" for one it does not.
std::string gridOutputFormats(const std::filesystem::path& out);
// Writes `grid` to `out` atomically, by extension. `source` names what it came from: the surface mesh's name is its
// stem, and a grid without voxels, which has no surface, is refused naming it.
Status writeGridAs(const VoxelGrid& grid, const std::filesystem::path& out, const std::string& source);

}  // namespace vox::cli
