// voxmod voxelize MESH --res R | --voxel-size H [--mode M] [--threads N] -o OUT (docs/conventions.md, "Command line").
// JSON keys: triangles, dims, voxel_size, origin, filled, volume, load_s, voxelize_s, write_s, total_s, warnings;
// also format, bodies, units, file_units, deflection, mode, mode_reason, disputed_voxels, strays_removed, grid_bytes
// peak_rss_bytes and streamed (true: written in slabs, cli/voxelize_stream.h).
#include <new>

#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/batch.h"
#include "cli/model_input.h"
#include "cli/voxelize_mpi.h"
#include "cli/voxelize_stream.h"
#include "vox/io/voxel_file.h"
#include "vox/voxelize/stream.h"
#include "vox/workflow/model_input.h"

namespace vox::cli {
namespace {

struct VoxelizeOptions {
  std::string mesh, out, disputed_out;
  bool json = false;
  MeshOptions mesh_options;
};

int runVoxelizeHere(const VoxelizeOptions& o) {
  Output out(o.json);
  const double t0 = nowSeconds();
  if (!io::isVoxelFile(o.out)) return out.fail(kExitUsage, o.out + ": unknown output format (use .vxm or .binvox)");
  auto mesh = loadMesh(o.mesh, o.mesh_options, out);
  if (!mesh) return out.fail(mesh.error());
  const double t_loaded = nowSeconds();

  auto params = voxelizeParams(o.mesh_options);
  if (!params) return out.fail(params.error());
  params->units = mesh->units;
  // A grid that does not fit under the memory limit is voxelized in Z slabs straight into the .vxm file.
  const FillMode mode = params->mode == FillMode::kAuto ? resolveAutoMode(mesh->topology).mode : params->mode;
  auto slab_layers = streamSlabLayers(mesh->mesh.bounds(), *params, mode, meshHeldBytes(mesh->mesh));
  if (!slab_layers) return out.fail(Error{slab_layers.error().code, o.mesh + ": " + slab_layers.error().message});
  if (*slab_layers > 0 && o.mesh_options.params.remove_strays) {
    return out.fail(Error{ErrorCode::kLimit, o.mesh + ": the grid does not fit under the memory limit and " +
                                                 "--remove-strays needs it whole; leave it out or lower --res"});
  }
  if (*slab_layers > 0) return runStreamedVoxelize({o.mesh, o.out, *slab_layers, t0, t_loaded}, *mesh, *params, out);
  auto result = workflow::voxelizeMesh(mesh->mesh, mesh->topology, *params, terminalProgress("voxelizing"), o.mesh);
  if (!result) return out.fail(result.error());
  const double t_voxelized = nowSeconds();
  for (const std::string& w : result->warnings) out.warn(w);
  // The mesh is no longer needed: release it before the file is encoded, so writing never adds to the peak.
  const int64_t triangles = int64_t(mesh->mesh.triangles.size());
  std::vector<Triangle>().swap(mesh->mesh.triangles);
  VoxelGrid& g = result->grid;
  g.frame().source = std::filesystem::path(o.mesh).filename().string();

  if (auto s = io::saveVoxelFile(g, o.out); !s) return out.fail(s.error());
  if (!o.disputed_out.empty()) {
    if (!result->disputed) {
      out.warn("no disputed-voxel mask: only --mode vote (or auto on a broken mesh) produces one");
    } else {
      VoxelGrid disputed;
      try {
        disputed = result->disputed->toGrid();
      } catch (const std::bad_alloc&) {
        return out.fail(Error{ErrorCode::kLimit, o.disputed_out + ": not enough memory for the grid of " +
                                                     std::to_string(result->disputed_count) + " disputed voxels"});
      }
      if (auto s = io::saveVoxelFile(disputed, o.disputed_out); !s) return out.fail(s.error());
    }
  }
  const double t_written = nowSeconds();

  const int64_t filled = g.filledCount();
  const double h = g.voxelSize();
  auto& d = out.data();
  d["mesh"] = o.mesh;
  d["output"] = o.out;
  d["format"] = mesh->format_detail;
  d["triangles"] = triangles;
  d["bodies"] = mesh->bodies.size();
  d["dims"] = {g.nx(), g.ny(), g.nz()};
  d["voxel_size"] = h;
  d["origin"] = jsonVec3(g.frame().origin);
  d["filled"] = filled;
  d["volume"] = double(filled) * h * h * h;
  d["units"] = g.frame().units;
  if (!mesh->file_units.empty()) d["file_units"] = mesh->file_units;
  if (mesh->deflection > 0) d["deflection"] = mesh->deflection;
  d["mode"] = fillModeName(result->mode_used);
  d["mode_reason"] = result->mode_reason;
  d["disputed_voxels"] = result->disputed_count;
  d["strays_removed"] = result->strays_removed;
  d["load_s"] = t_loaded - t0;
  d["voxelize_s"] = t_voxelized - t_loaded;
  d["write_s"] = t_written - t_voxelized;
  d["total_s"] = t_written - t0;
  d["grid_bytes"] = g.memoryBytes();
  d["peak_rss_bytes"] = peakRssBytes();
  d["streamed"] = false;
  out.say("voxelized " + o.mesh + " (" + std::to_string(triangles) + " triangles) to " + std::to_string(g.nx()) +
          " x " + std::to_string(g.ny()) + " x " + std::to_string(g.nz()) + ", " + std::to_string(filled) +
          " filled voxels, mode " + fillModeName(result->mode_used) + " (" + result->mode_reason + ")");
  if (result->mode_used == FillMode::kVote) {
    out.say(std::to_string(result->disputed_count) + " voxels in dispute between the three ray directions");
  }
  out.say("wrote " + o.out + " in " + significant(t_written - t0, 3) + " s");
  return out.finish();
}

// Under mpirun or srun the slabs are spread over the ranks (cli/voxelize_mpi.h).
int runVoxelize(const VoxelizeOptions& o) {
  if (!launchedByMpi()) return runVoxelizeHere(o);
  if (!mpiBuilt()) {
    if (mpiWorldSizeFromEnvironment() > 1) {
      Output out(o.json);
      return out.fail(kExitUsage, "this voxmod was built without MPI: run 'voxmod voxelize' without mpirun or srun");
    }
    return runVoxelizeHere(o);
  }
  const MpiVoxelizeJob job{o.mesh, o.out, o.json, o.mesh_options.params.remove_strays || !o.disputed_out.empty(),
                           o.mesh_options};
  return voxelizeOverMpiRanks(job, [&] { return runVoxelizeHere(o); });
}

}  // namespace

void addVoxelizeCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<VoxelizeOptions>();
  sub.add_option("MESH", o->mesh, "Input mesh or CAD file: .stl .obj .ply .3mf .gltf .glb .off .step .stp .iges .igs")
      ->required();
  sub.add_option("-o,--output", o->out, "Output voxel file (.vxm or .binvox)")->required();
  sub.add_flag("--remove-strays", o->mesh_options.params.remove_strays,
               "Remove one- and two-dimensional stray voxels (four or five free faces)");
  sub.add_option("--disputed", o->disputed_out,
                 "vote mode: also write the voxels the three ray directions disagreed on to this voxel file");
  sub.add_flag("--json", o->json, "Print one JSON object on stdout");
  addMeshOptions(sub, o->mesh_options);
  sub.callback([o, &ctx] { ctx.exit_code = runVoxelize(*o); });
}

}  // namespace vox::cli
