// voxmod convert IN OUT: formats by extension (docs/file-format.md). A mesh IN is voxelized first; a voxel OUT (.vxm,
// .binvox) is written as it is, a volume OUT (.nrrd, .vti, .vdb, .vox) holds the voxels with their placement, and a
// mesh OUT (.stl, .ply, .obj, .3mf) is the model's surface (vox/analysis/surface_mesh.h).
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "cli/stream_readers.h"
#include "vox/analysis/surface_mesh.h"
#include "vox/io/mesh_export.h"
#include "vox/io/magicavoxel.h"
#include "vox/io/volume_export.h"
#include "vox/io/voxel_file.h"
#include "vox/io/vxm_stream.h"
#include "vox/voxelize/stream.h"

namespace vox::cli {
namespace {

struct ConvertOptions {
  std::string in, out;
  bool json = false;
  bool voxel_faces = false;  // --voxel-faces: two triangles per voxel face, no merging
  bool smooth = false;       // --smooth: surface nets (SurfaceMeshParams::smooth_iterations)
  int smooth_iterations = 10;
  MeshOptions mesh;
};

// The model's surface into a mesh file; fills the JSON keys of the surface.
Status writeSurface(const ConvertOptions& o, const VoxelGrid& grid, Output& out) {
  const double t0 = nowSeconds();
  SurfaceMeshStats stats;
  const SurfaceMeshParams params{!o.voxel_faces, o.smooth ? o.smooth_iterations : 0};
  auto mesh = extractSurfaceMesh(grid, params, terminalProgress("surface"), &stats);
  if (!mesh) return mesh.error();
  mesh->name = std::filesystem::path(o.in).stem().string();
  auto& d = out.data();
  d["surface_s"] = nowSeconds() - t0;
  d["voxel_faces"] = stats.voxel_faces;
  d["rectangles"] = stats.rectangles;
  d["split_vertices"] = stats.split_vertices;
  d["vertices"] = mesh->vertices.size();
  d["triangles"] = mesh->triangles.size();
  const double h = grid.voxelSize();
  d["volume"] = double(grid.filledCount()) * h * h * h;  // of the voxels (a smooth surface encloses a little less)
  d["smooth_iterations"] = params.smooth_iterations;
  return io::saveMesh(*mesh, o.out, grid.frame().units);
}

// A volume OUT (.nrrd, .vti, .vdb, .vox: io/volume_export.h): the model's voxels with their placement.
int convertToVolume(const ConvertOptions& o, Output& out) {
  auto model = loadModel(o.in, o.mesh, out);
  if (!model) return out.fail(model.error());
  const double t0 = nowSeconds();
  if (auto s = io::saveVolume(io::voxelsOnly(model->grid), o.out, terminalProgress("writing")); !s) {
    return out.fail(s.error());
  }
  auto& d = out.data();
  d["input"] = o.in;
  d["output"] = o.out;
  d["format"] = std::string(io::volumeExtension(*io::volumeFormatOf(o.out))).substr(1);  // "vti"
  d["dims"] = {model->grid.nx(), model->grid.ny(), model->grid.nz()};
  d["filled"] = model->grid.filledCount();
  if (io::volumeFormatOf(o.out) == io::VolumeFormat::kVox) {
    d["models"] = io::planMagicaVoxel(model->grid).size();  // 256^3 blocks holding voxels
  }
  d["write_s"] = nowSeconds() - t0;
  out.say("wrote " + o.out);
  return out.finish();
}

// A .vxm IN too large for memory to a .binvox OUT, without the grid (io::convertVxmToBinvox).
int convertStreamedToBinvox(const ConvertOptions& o, const io::VxmHeaderInfo& h, Output& out) {
  const double t0 = nowSeconds();
  const uint64_t limit = o.mesh.memory_limit_bytes > 0 ? o.mesh.memory_limit_bytes : defaultMemoryLimitBytes();
  if (auto s = io::convertVxmToBinvox(o.in, o.out, limit / 2, windowLayers(h.dims, o.mesh)); !s) {
    return out.fail(s.error());
  }
  auto& d = out.data();
  d["input"] = o.in;
  d["output"] = o.out;
  d["dims"] = {h.dims.nx, h.dims.ny, h.dims.nz};
  d["filled"] = h.filled;
  d["write_s"] = nowSeconds() - t0;
  d["streamed"] = true;
  out.say("wrote " + o.out);
  return out.finish();
}

int runConvert(const ConvertOptions& o) {
  Output out(o.json);
  if (io::isVolumeFile(o.out)) {
    if (o.voxel_faces || o.smooth)
      return out.fail(kExitUsage, "--voxel-faces and --smooth apply to a surface mesh OUT");
    return convertToVolume(o, out);
  }
  const bool surface = io::isMeshExportFile(o.out);
  if (!io::isVoxelFile(o.out) && !surface) {
    return out.fail(kExitUsage, o.out + ": unknown output format (voxels: .vxm, .binvox; volumes: " +
                                    io::volumeExtensionList() + "; surface: " + io::meshExportExtensions() + ")");
  }
  if ((o.voxel_faces || o.smooth) && !surface) {
    return out.fail(kExitUsage, "--voxel-faces and --smooth apply to a surface mesh OUT");
  }
  if (o.smooth && o.smooth_iterations < 1) return out.fail(kExitUsage, "--smooth-iterations must be at least 1");
  if (io::lowerExtension(o.out) == ".binvox") {
    if (auto h = streamedVxm(o.in, o.mesh, out)) return convertStreamedToBinvox(o, *h, out);
  }
  auto model = loadModel(o.in, o.mesh, out);
  if (!model) return out.fail(model.error());
  if (model->grid.filledCount() == 0 && surface) {
    return out.fail(Error{ErrorCode::kInvalidArgument, o.in + ": the model has no filled voxels: no surface to write"});
  }
  const double t0 = nowSeconds();
  if (auto s = surface ? writeSurface(o, model->grid, out) : io::saveVoxelFile(model->grid, o.out); !s) {
    return out.fail(s.error());
  }
  auto& d = out.data();
  d["input"] = o.in;
  d["output"] = o.out;
  d["dims"] = {model->grid.nx(), model->grid.ny(), model->grid.nz()};
  d["filled"] = model->grid.filledCount();
  d["write_s"] = nowSeconds() - t0;
  out.say("wrote " + o.out);
  return out.finish();
}

}  // namespace

void addConvertCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<ConvertOptions>();
  sub.add_option("IN", o->in, "Voxel file (.vxm, .binvox), mesh or CAD file")->required();
  sub.add_option("OUT", o->out,
                 "Output: voxel file (.vxm, .binvox), volume (.nrrd, .vti, .vdb, .vox) or the surface as a mesh (.stl, "
                 ".ply, .obj, .3mf)")
      ->required();
  sub.add_flag("--voxel-faces", o->voxel_faces, "Surface mesh: two triangles per voxel face (no merging)");
  sub.add_flag("--smooth", o->smooth, "Surface mesh: smooth (surface nets), within half a voxel of the voxels");
  sub.add_option("--smooth-iterations", o->smooth_iterations, "Smoothing passes (default 10)");
  sub.add_flag("--json", o->json, "Print one JSON object on stdout");
  addMeshOptions(sub, o->mesh);
  sub.callback([o, &ctx] { ctx.exit_code = runConvert(*o); });
}

}  // namespace vox::cli
