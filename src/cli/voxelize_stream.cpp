// voxmod voxelize in slabs (cli/voxelize_stream.h): each slab is encoded into the output's temporary file as soon as
// it is voxelized, and freed; the file replaces OUT only when every slab is written (io::saveVxmInSlabs).
#include "cli/voxelize_stream.h"

#include <sys/resource.h>

#include <filesystem>
#include <optional>

#include "cli/model_input.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/vxm_stream.h"
#include "vox/voxelize/stream.h"

namespace vox::cli {

int64_t peakRssBytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return int64_t(u.ru_maxrss) * 1024;  // Linux reports KiB
}

int runStreamedVoxelize(const StreamedVoxelizeJob& job, io::MeshFileLoad& mesh, const VoxelizeParams& params,
                        Output& out) {
  if (io::lowerExtension(job.out_path) != ".vxm") {
    return out.fail(Error{ErrorCode::kLimit, job.out_path +
                                                 ": the grid does not fit under the memory limit, so it is streamed "
                                                 "in slabs, which only a .vxm output takes (voxmod convert turns "
                                                 "the .vxm into .binvox)"});
  }
  auto plan = planVoxelization(mesh.mesh.bounds(), params);
  if (!plan) return out.fail(plan.error());
  GridFrame frame = plan->placement.frame;
  frame.units = params.units;
  frame.source = std::filesystem::path(job.mesh_path).filename().string();
  std::optional<StreamedVoxelization> done;
  const Status written = io::saveVxmInSlabs(job.out_path, plan->placement.dims, frame, [&](io::VxmLayerWriter& w) {
    auto r = voxelizeInSlabs(
        mesh.mesh, params, job.slab_layers,
        [&](const VoxelGrid& slab, int32_t z0, int32_t z1) { return w.append(slab, 0, z1 - z0); },
        terminalProgress("voxelizing"), &mesh.topology);
    if (!r) return Status(Error{r.error().code, job.mesh_path + ": " + r.error().message});
    done = std::move(r).value();
    return Status(Ok{});
  });
  if (!written) return out.fail(written.error());
  return reportStreamedVoxelize(job, mesh, frame, *done, nowSeconds(), out);
}

int reportStreamedVoxelize(const StreamedVoxelizeJob& job, const io::MeshFileLoad& mesh, const GridFrame& frame,
                           const StreamedVoxelization& done_in, double t_written, Output& out) {
  const StreamedVoxelization* done = &done_in;
  for (const std::string& w : done->warnings) out.warn(w);
  const Dims dims = done->dims;
  const double h = frame.voxel_size;
  auto& d = out.data();
  d["mesh"] = job.mesh_path;
  d["output"] = job.out_path;
  d["format"] = mesh.format_detail;
  d["triangles"] = mesh.mesh.triangles.size();
  d["bodies"] = mesh.bodies.size();
  d["dims"] = {dims.nx, dims.ny, dims.nz};
  d["voxel_size"] = h;
  d["origin"] = jsonVec3(frame.origin);
  d["filled"] = done->filled;
  d["volume"] = double(done->filled) * h * h * h;
  d["units"] = frame.units;
  if (!mesh.file_units.empty()) d["file_units"] = mesh.file_units;
  if (mesh.deflection > 0) d["deflection"] = mesh.deflection;
  d["mode"] = fillModeName(done->mode_used);
  d["mode_reason"] = done->mode_reason;
  d["disputed_voxels"] = 0;
  d["strays_removed"] = 0;
  d["load_s"] = job.t_loaded - job.t0;
  // Voxelizing and writing overlap (each slab is written as soon as it is made): voxelize_s holds both.
  d["voxelize_s"] = t_written - job.t_loaded;
  d["write_s"] = 0.0;
  d["total_s"] = t_written - job.t0;
  d["grid_bytes"] = done->largest_slab_bytes;
  d["peak_rss_bytes"] = peakRssBytes();
  d["streamed"] = true;
  d["slabs"] = done->slabs;
  d["slab_layers"] = done->slab_layers;
  out.say("voxelized " + job.mesh_path + " (" + std::to_string(mesh.mesh.triangles.size()) + " triangles) to " +
          dimsText(dims) + " in " + std::to_string(done->slabs) + " slabs of " + std::to_string(done->slab_layers) +
          " layers (" + job.reason + "), " + std::to_string(done->filled) + " filled voxels, mode " +
          fillModeName(done->mode_used) + " (" + done->mode_reason + ")");
  out.say("wrote " + job.out_path + " in " + significant(t_written - job.t0, 3) + " s");
  return out.finish();
}

}  // namespace vox::cli
