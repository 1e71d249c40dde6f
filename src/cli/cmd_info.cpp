// voxmod info FILE: describe a voxel file, or a mesh (and the grid it voxelizes to). Keys fixed by docs/conventions.md,
// "Command line": dims, voxel_size, origin, filled, volume, surface_voxels.
#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "cli/stream_readers.h"
#include "vox/core/surface.h"

namespace vox::cli {
namespace {

struct InfoOptions {
  std::string file;
  bool json = false;
  MeshOptions mesh;
};

int runInfo(const InfoOptions& o) {
  Output out(o.json);
  if (auto h = streamedVxm(o.file, o.mesh, out)) return streamedInfo(o.file, *h, o.mesh, out);
  auto model = loadModel(o.file, o.mesh, out);
  if (!model) return out.fail(model.error());
  const VoxelGrid& g = model->grid;
  const int64_t filled = g.filledCount();
  const int64_t surface = countSurfaceVoxels(g);
  const double h = g.voxelSize();
  auto& d = out.data();
  d["file"] = o.file;
  d["dims"] = {g.nx(), g.ny(), g.nz()};
  d["voxel_size"] = h;
  d["origin"] = jsonVec3(g.frame().origin);
  d["units"] = g.frame().units;
  d["filled"] = filled;
  d["volume"] = double(filled) * h * h * h;
  d["surface_voxels"] = surface;
  d["memory_bytes"] = g.memoryBytes();
  if (!g.frame().source.empty()) d["source"] = g.frame().source;
  if (model->from_mesh) {
    d["format"] = model->format;
    d["triangles"] = model->triangles;
    d["bodies"] = model->bodies;
    if (!model->file_units.empty()) d["file_units"] = model->file_units;
    if (model->deflection > 0) d["deflection"] = model->deflection;
    d["watertight"] = model->topology.watertight();
    d["boundary_edges"] = model->topology.boundary_edges;
    d["nonmanifold_edges"] = model->topology.nonmanifold_edges;
    d["degenerate_triangles"] = model->topology.degenerate_triangles;
    d["mode"] = model->mode_used;
  }
  if (!out.json()) {
    out.say(o.file + ":");
    if (model->from_mesh) {
      out.say("  format      " + model->format + (model->file_units.empty() ? "" : ", unit " + model->file_units));
      out.say("  bodies      " + std::to_string(model->bodies));
      out.say("  mesh        " + std::to_string(model->triangles) + " triangles, " +
              (model->topology.watertight()
                   ? std::string("watertight")
                   : "not watertight (" + std::to_string(model->topology.boundary_edges) + " boundary, " +
                         std::to_string(model->topology.nonmanifold_edges) + " non-manifold edges)"));
    }
    out.say("  dims        " + std::to_string(g.nx()) + " x " + std::to_string(g.ny()) + " x " +
            std::to_string(g.nz()));
    out.say("  voxel size  " + significant(h) + " " + g.frame().units);
    out.say("  filled      " + std::to_string(filled) + " voxels, volume " + significant(double(filled) * h * h * h));
    out.say("  surface     " + std::to_string(surface) + " voxels");
    out.say("  memory      " + std::to_string(g.memoryBytes() >> 10) + " KiB");
  }
  return out.finish();
}

}  // namespace

void addInfoCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<InfoOptions>();
  sub.add_option("FILE", o->file, kFileHelp)->required();
  sub.add_flag("--json", o->json, "Print one JSON object on stdout");
  addMeshOptions(sub, o->mesh);
  sub.callback([o, &ctx] { ctx.exit_code = runInfo(*o); });
}

}  // namespace vox::cli
