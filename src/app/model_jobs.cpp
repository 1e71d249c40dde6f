#include "app/model_jobs.h"

#include <algorithm>
#include <memory>
#include <string>
#include <utility>

#include "app/document.h"
#include "app/messages.h"
#include "vox/core/text.h"
#include "vox/io/cad.h"
#include "vox/workflow/model_input.h"

namespace vox::app {

Result<VoxelizePlan> planFor(const AppState& state, const VoxelizeParams& params) {
  if (!state.doc.mesh) return makeError(ErrorCode::kInvalidArgument, "no mesh is open");
  return planVoxelization(state.doc.mesh->mesh.bounds(), params);
}

uint64_t comfortableVoxelizeBytes() {
  const uint64_t physical = physicalMemoryBytes();
  return physical == 0 ? uint64_t(4) << 30 : std::min(uint64_t(4) << 30, physical / 4);
}

void proposeResolution(AppState& state) {
  VoxelizeDialog& d = state.voxelize;
  d.proposal_note.clear();
  if (!state.doc.mesh || d.by_voxel_size) return;
  const auto need = [&](int64_t r) {
    VoxelizeParams p = d.params;
    p.resolution = r;
    auto plan = planFor(state, p);
    return plan ? plan->bytes : UINT64_MAX;
  };
  const uint64_t last = need(d.params.resolution);
  if (last <= comfortableVoxelizeBytes()) return;
  for (int64_t r : {1000, 400, 200, 100}) {
    if (r < d.params.resolution && need(r) <= comfortableVoxelizeBytes()) {
      d.proposal_note = "Proposed R = " + std::to_string(r) + ": the last one used, " +
                        std::to_string(d.params.resolution) + ", would need " + formatBytes(last) + " for this part.";
      d.params.resolution = r;
      return;
    }
  }
}

namespace {

// The deflection the grid of `params` asks of a CAD file's tessellation, when the open mesh is coarser; 0 otherwise.
double finerDeflection(const MeshSource& mesh, const VoxelizeParams& params) {
  if (!mesh.cad) return 0.0;
  auto wanted = io::cadDeflectionFor(mesh.cad->bounds(), params.resolution, params.voxel_size);
  return wanted && *wanted < mesh.deflection * (1.0 - 1e-9) ? *wanted : 0.0;
}

// Tessellates again (progress [0, 0.4]) when the grid is finer than the open mesh was made for, then voxelizes.
Result<VoxelizeOutcome> voxelizeMesh(const std::shared_ptr<const MeshSource>& open, const VoxelizeParams& params,
                                     const ProgressFn& progress) {
  VoxelizeOutcome out;
  std::shared_ptr<const MeshSource> mesh = open;
  ProgressFn voxelizing = progress;
  if (const double deflection = finerDeflection(*open, params); deflection > 0.0) {
    const double t0 = nowSeconds();
    auto load = io::tessellateCad(*open->cad, deflection, [&](double f) { return !progress || progress(0.4 * f); });
    if (!load) return load.error();
    load->cad = open->cad;
    auto fresh = makeMeshSource(open->path, std::move(load).value());
    fresh->load_s = open->load_s + (nowSeconds() - t0);
    mesh = out.mesh = std::move(fresh);
    voxelizing = [&](double f) { return !progress || progress(0.4 + 0.6 * f); };
  }
  auto result = workflow::voxelizeMesh(mesh->mesh, mesh->topology, params, voxelizing);
  if (!result) return result.error();
  out.result = std::move(result).value();
  return out;
}

}  // namespace

void startVoxelize(AppState& state, const VoxelizeParams& params) {
  if (!state.doc.mesh) {
    reportError(state, "there is no mesh to voxelize: open a mesh or CAD file first", state.doc.path);
    return;
  }
  state.settings.resolution = params.resolution;
  state.settings.fill_mode = fillModeName(params.mode);
  if (state.doc.mesh->file_units.empty()) {  // the units the user gave a file that names none, for next time
    rememberFileUnits(state.settings, absoluteName(state.doc.mesh->path), params.units);
  }
  state.voxelize_job_params = params;
  state.job_started = nowSeconds();
  auto mesh = state.doc.mesh;
  const char* verb = finerDeflection(*mesh, params) > 0.0 ? "Tessellating and voxelizing " : "Voxelizing ";
  state.voxelize_job.start(verb + mesh->path.filename().string(),
                           [mesh, params](const ProgressFn& progress) { return voxelizeMesh(mesh, params, progress); });
}

void cancelJobs(AppState& state) {
  state.load_job.cancel();
  state.voxelize_job.cancel();
}

bool modelBusy(const AppState& state) { return state.load_job.active() || state.voxelize_job.active(); }

void applyVoxelized(AppState& state, VoxelizeOutcome outcome, const VoxelizeParams& params, double seconds) {
  if (outcome.mesh) state.doc.mesh = std::move(outcome.mesh);
  VoxelizeResult& result = outcome.result;
  auto origin = std::make_shared<ModelOrigin>();
  origin->mode_used = fillModeName(result.mode_used);
  origin->mode_reason = result.mode_reason;
  origin->resolution = std::max({result.grid.nx(), result.grid.ny(), result.grid.nz()});
  origin->voxelize_s = seconds;
  origin->load_s = state.doc.mesh ? state.doc.mesh->load_s : 0.0;
  origin->warnings = result.warnings;
  origin->disputed_count = result.disputed_count;
  if (result.disputed) origin->disputed = std::make_shared<const SparseVoxels>(std::move(*result.disputed));
  const std::string res_text =
      params.voxel_size > 0 ? "h=" + std::to_string(params.voxel_size) : "R=" + std::to_string(params.resolution);
  origin->what = "voxelized at " + res_text + " (" + origin->mode_used + ")";
  VoxelGrid grid = std::move(result.grid);
  if (state.doc.mesh) grid.frame().source = state.doc.mesh->path.filename().string();
  // Voxelizing alone loses nothing the user could not redo in a moment: when nothing was unsaved before, nothing
  // is after (a peel, later, is a change worth a prompt).
  const bool nothing_to_lose = !hasUnsavedChanges(state);
  setModel(state, newBase(state, std::move(grid), std::move(origin), "voxelize " + res_text), true);
  if (nothing_to_lose) state.doc.saved_version = state.doc.model->version;
}

}  // namespace vox::app
