// voxmod convert IN OUT: between voxel formats by extension (.vxm, .binvox), or to a volume format (.nrrd, .vti,
// .vdb, .vox). A mesh IN is voxelized first.
#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "vox/io/magicavoxel.h"
#include "vox/io/volume_export.h"
#include "vox/io/voxel_file.h"

namespace vox::cli {
namespace {

struct ConvertOptions {
  std::string in, out;
  bool json = false;
  MeshOptions mesh;
};

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

int runConvert(const ConvertOptions& o) {
  Output out(o.json);
  if (io::isVolumeFile(o.out)) return convertToVolume(o, out);
  if (!io::isVoxelFile(o.out)) {
    return out.fail(kExitUsage,
                    o.out + ": unknown output format (use .vxm, .binvox, " + io::volumeExtensionList() + ")");
  }
  auto model = loadModel(o.in, o.mesh, out);
  if (!model) return out.fail(model.error());
  const double t0 = nowSeconds();
  if (auto s = io::saveVoxelFile(model->grid, o.out); !s) return out.fail(s.error());
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
  sub.add_option("IN", o->in, "Voxel file (.vxm, .binvox) or mesh (.stl)")->required();
  sub.add_option("OUT", o->out, "Output voxel file (.vxm, .binvox) or volume (.nrrd, .vti, .vdb, .vox)")->required();
  sub.add_flag("--json", o->json, "Print one JSON object on stdout");
  addMeshOptions(sub, o->mesh);
  sub.callback([o, &ctx] { ctx.exit_code = runConvert(*o); });
}

}  // namespace vox::cli
