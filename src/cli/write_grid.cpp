#include "cli/write_grid.h"

#include "vox/analysis/surface_mesh.h"
#include "vox/io/mesh_export.h"
#include "vox/io/volume_export.h"
#include "vox/io/voxel_file.h"

namespace vox::cli {

bool isGridOutput(const std::filesystem::path& out) {
  return io::isVoxelFile(out) || io::isVolumeFile(out) || io::isMeshExportFile(out);
}

std::string gridOutputFormats(const std::filesystem::path& out) {
  return out.string() + ": unknown output format (voxels: .vxm, .binvox; volumes: " + io::volumeExtensionList() +
         "; surface: " + io::meshExportExtensions() + ")";
}

Status writeGridAs(const VoxelGrid& grid, const std::filesystem::path& out, const std::string& source) {
  if (io::isVoxelFile(out)) return io::saveVoxelFile(grid, out);
  if (io::isVolumeFile(out)) return io::saveVolume(io::voxelsOnly(grid), out);
  if (!io::isMeshExportFile(out)) return makeError(ErrorCode::kUnsupported, gridOutputFormats(out));
  if (grid.filledCount() == 0) {
    return makeError(ErrorCode::kInvalidArgument, source + ": the model has no filled voxels: no surface to write");
  }
  auto mesh = extractSurfaceMesh(grid, SurfaceMeshParams{});
  if (!mesh) return mesh.error();
  mesh->name = std::filesystem::path(source).stem().string();  // as convert names it
  return io::saveMesh(*mesh, out, grid.frame().units);
}

}  // namespace vox::cli
