// voxmod convert IN OUT: between voxel formats by extension (.vxm, .binvox). A mesh IN is voxelized first.
#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "vox/io/voxel_file.h"

namespace vox::cli {
namespace {

struct ConvertOptions {
  std::string in, out;
  bool json = false;
  MeshOptions mesh;
};

int runConvert(const ConvertOptions& o) {
  Output out(o.json);
  if (!io::isVoxelFile(o.out)) {
    return out.fail(kExitUsage, o.out + ": unknown output format (use .vxm or .binvox)");
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
  sub.add_option("OUT", o->out, "Output voxel file (.vxm, .binvox)")->required();
  sub.add_flag("--json", o->json, "Print one JSON object on stdout");
  addMeshOptions(sub, o->mesh);
  sub.callback([o, &ctx] { ctx.exit_code = runConvert(*o); });
}

}  // namespace vox::cli
