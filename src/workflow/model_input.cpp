#include "vox/workflow/model_input.h"

#include <utility>

#include "vox/core/text.h"
#include "vox/io/voxel_file.h"

namespace vox::workflow {

Result<io::MeshFileLoad> readMeshFile(const std::filesystem::path& file, const io::MeshFileOptions& options,
                                      const InputMessages& messages) {
  auto mesh = io::loadMeshFile(file, options);
  if (!mesh || !messages) return mesh;
  for (const std::string& w : mesh->warnings) messages(InputMessage::kWarning, w);
  for (const std::string& n : mesh->notes) messages(InputMessage::kNote, n);
  return mesh;
}

Result<VoxelizeResult> voxelizeMesh(const TriangleMesh& mesh, const MeshTopology& topology,
                                    const VoxelizeParams& params, const ProgressFn& progress, const std::string& name) {
  auto result = voxelizeSolid(mesh, params, progress, &topology);
  if (!result && !name.empty()) return makeError(result.error().code, name + ": " + result.error().message);
  return result;
}

Result<ModelFile> readModelFile(const std::filesystem::path& file, const ModelFileOptions& options) {
  ModelFile m;
  const double t0 = nowSeconds();
  if (io::isVoxelFile(file)) {
    auto grid = io::loadVoxelFile(file);
    if (!grid) return grid.error();
    m.grid = std::move(grid).value();
    if (!options.units.empty()) m.grid.frame().units = options.units;
    m.load_s = nowSeconds() - t0;
    return m;
  }
  auto mesh = readMeshFile(file, options.reading, options.messages);
  if (!mesh) return mesh.error();
  m.load_s = nowSeconds() - t0;
  m.from_mesh = true;
  m.triangles = int64_t(mesh->mesh.triangles.size());
  m.topology = mesh->topology;
  m.format = mesh->format_detail;
  m.bodies = int64_t(mesh->bodies.size());
  m.file_units = mesh->file_units;
  m.deflection = mesh->deflection;
  VoxelizeParams params = options.params;
  params.units = mesh->units;
  const double t1 = nowSeconds();
  const std::string name = file.filename().string();
  auto result =
      voxelizeMesh(mesh->mesh, mesh->topology, params, options.voxelizing, options.name.empty() ? name : options.name);
  if (!result) return result.error();
  m.voxelize_s = nowSeconds() - t1;
  if (options.messages) {
    for (const std::string& w : result->warnings) options.messages(InputMessage::kWarning, w);
  }
  m.mode_used = fillModeName(result->mode_used);
  m.mode_reason = result->mode_reason;
  m.grid = std::move(result->grid);
  m.grid.frame().source = name;
  if (options.keep_mesh) m.mesh = std::move(mesh->mesh);
  return m;
}

}  // namespace vox::workflow
