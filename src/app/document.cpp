#include "app/document.h"

#include <cmath>
#include <optional>
#include <utility>

#include "app/autosave.h"
#include "app/file_browsing.h"
#include "app/full_section.h"
#include "app/measure.h"
#include "app/messages.h"
#include "app/project.h"
#include "app/model_jobs.h"
#include "app/parts.h"
#include "app/update.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/mesh_file.h"
#include "vox/io/voxel_file.h"
#include "vox/io/vxm_stream.h"
#include "vox/workflow/model_input.h"

namespace vox::app {
namespace {

// A new grid (re-voxelized, or undo / redo across a voxelization) may lie on another lattice; the camera lives in
// voxel-index space, so it is carried over to the new lattice to keep showing the same part of the model. A first
// model is fitted instead.
void keepTheView(AppState& state, const GridFrame& before, bool had_model) {
  const GridFrame& now = state.model.frame();
  // Picked voxels mean nothing on another lattice.
  if (!had_model || now.voxel_size != before.voxel_size || now.origin != before.origin) clearMeasure(state.measure);
  if (!had_model) {
    state.view.fit_pending = true;
  } else if (now.voxel_size != before.voxel_size || now.origin != before.origin) {
    if (before.voxel_size > 0 && now.voxel_size > 0) {
      state.view.camera =
          render::reframed(state.view.camera, before.origin, before.voxel_size, now.origin, now.voxel_size);
    } else {
      state.view.fit_pending = true;
    }
  }
}

// The section stays at the same place in the part: on another lattice, the index whose plane lies nearest the old
// plane; when that is outside the new grid (or there was no model), the middle.
void keepTheSection(AppState& state, const GridFrame& before, bool had_model) {
  const GridFrame& now = state.model.frame();
  const int a = int(state.section.axis);
  const int32_t n = axisLength(state, state.section.axis);
  int32_t& index = state.section.index;
  if (had_model && index >= 0 && before.voxel_size > 0 && now.voxel_size > 0 &&
      (now.voxel_size != before.voxel_size || now.origin != before.origin)) {
    const double plane = before.origin[a] + (double(index) + 0.5) * before.voxel_size;
    index = int32_t(std::lround((plane - now.origin[a]) / now.voxel_size - 0.5));
  }
  if (index < 0 || index >= n) index = n / 2;
}

}  // namespace

void setModel(AppState& state, ModelSnapshot snapshot, bool undoable) {
  const bool had_model = state.doc.model.has_value();
  const GridFrame before = state.model.frame();
  if (undoable && state.doc.model) {
    state.doc.undo_stack.push_back(std::move(*state.doc.model));
    state.doc.redo_stack.clear();
  }
  state.doc.model = std::move(snapshot);
  state.model = state.doc.model->grid;
  state.model_version = state.doc.model->version;
  applyPartsScope(state);  // a scene of parts: the selected part, when the Parts panel says so
  state.viewport.dirty = true;
  keepTheView(state, before, had_model);
  keepTheSection(state, before, had_model);
}

uint64_t takeId(AppState& state) { return state.next_id++; }

ModelSnapshot newBase(AppState& state, VoxelGrid grid, std::shared_ptr<const ModelOrigin> origin, std::string label) {
  ModelSnapshot s;
  s.base_id = takeId(state);
  s.version = takeId(state);
  s.base = grid;
  s.grid = std::move(grid);
  s.peeled = 0;
  s.origin = std::move(origin);
  s.label = std::move(label);
  return s;
}

void applyLoaded(AppState& state, LoadedFile loaded) {
  Document& doc = state.doc;
  doc = Document{};
  state.voxelize_job.abandon();  // a voxelization of the previous document's mesh must not land in this one
  state.parts_job.abandon();
  state.interference_job.abandon();
  state.clearance_job.abandon();
  state.parts_ui = PartsUi{};
  // Results derived from the previous document can never be asked for again: free them now.
  state.depth.clear();
  state.surface_stats.clear();
  state.mass.clear();
  state.xray_result.clear();
  state.skin.pending_peel.reset();
  state.thickness.clear();
  state.thin_walls.clear();
  state.thickness_ui.min_wall = -1.0;  // another part: a quarter of its own thickest wall until the user chooses
  state.thickness_ui.cancelled_version = 0;
  state.rays.clear();
  state.thickness_ui.rays_cancelled = 0;
  // another part: printed upright until the user turns it; the overhang angle is the printer's and stays
  state.print.clear();
  state.print_ui.up = glm::dvec3(0.0, 0.0, 1.0);
  state.print_ui.orient = state.print_ui.lay_face = state.print_ui.was_cancelled = false;
  state.print_ui.selected_cavity = -1;
  // another part (its feeders are its parts): the metal, mould and temperatures stay
  state.casting.clear();
  state.casting_ui.asked = state.casting_ui.placing_feeder = state.casting_ui.playing = false;
  state.casting_ui.time_shown = -1.0;
  state.casting_ui.selected_spot = -1;
  state.model = VoxelGrid{};
  state.model_version = 0;
  state.section.index = -1;
  state.section.zoom = 1.0;  // a new model's section shown whole
  state.section.centre = glm::dvec2(0.5);
  state.section.playing = false;
  state.view.fit_pending = true;
  state.viewport.dirty = true;
  state.release_memory = true;
  clearMeasure(state.measure);
  clearFullSection(state);
  doc.path = loaded.path;
  if (loaded.recovered) {  // an autosave: the document is the file it was made from, unsaved
    const std::string source = loaded.project->source;
    applyProject(state, std::move(*loaded.project), loaded.path, true);
    if (!source.empty()) doc.path = source;
    adoptRecovered(state, loaded.path);
    state.status_message = "Recovered the unsaved work on " + documentName(state) + ": save it to keep it";
    state.status_since = nowSeconds();
    state.voxelize_after_load = false;
    return;
  }
  addRecentFile(state.settings, std::filesystem::absolute(loaded.path).lexically_normal().string());
  state.settings.last_directory = std::filesystem::absolute(loaded.path).parent_path().string();
  if (loaded.project) {
    applyProject(state, std::move(*loaded.project), loaded.path, false);
  } else if (loaded.grid) {
    auto origin = std::make_shared<ModelOrigin>();
    origin->what = "loaded " + loaded.path.filename().string();
    doc.coarse_level = loaded.coarse_level;
    doc.full_dims = loaded.full_dims;
    if (loaded.coarse_level > 1) {
      const int32_t n = loaded.coarse_level;
      origin->what = "coarse view of " + loaded.path.filename().string() + " (" + dimsText(loaded.full_dims) +
                     ", too large for memory) at level " + std::to_string(n) + ": each " + std::to_string(n) + " x " +
                     std::to_string(n) + " x " + std::to_string(n) +
                     " block is one voxel, filled when any of its voxels is; "
                     "the Section panel reads full-resolution sections from the file";
    }
    origin->load_s = loaded.load_s;
    VoxelGrid grid = std::move(*loaded.grid);
    if (grid.frame().source.empty()) grid.frame().source = loaded.path.filename().string();
    if (grid.frame().units == "model")
      grid.frame().units = rememberedFileUnits(state.settings, absoluteName(loaded.path));
    setModel(state, newBase(state, std::move(grid), std::move(origin), "open " + loaded.path.filename().string()),
             false);
    if (loaded.coarse_level == 1) doc.save_path = loaded.path;  // a coarse view never overwrites its file
    doc.saved_version = doc.model->version;
    state.panel = Panel::kModel;
    state.panel_change_requested = true;
  } else {
    doc.mesh = std::move(loaded.mesh);
    // A file that states its unit (3MF, glTF, every CAD file) sets the dialog's; one that names none (STL, OBJ, PLY,
    // OFF) takes what the user last gave that file, else none: never the previous file's.
    state.voxelize.params.units =
        doc.mesh->units != "model" ? doc.mesh->units : rememberedFileUnits(state.settings, absoluteName(loaded.path));
    doc.saved_version = 0;
    state.panel = Panel::kModel;
    state.panel_change_requested = true;
    if (state.voxelize_after_load) {
      // Voxelized without being asked (the bundled part at start-up).
      startVoxelize(state, state.voxelize.params);
    } else if (state.voxelize_dialog_on_open) {
      // A mesh is voxelized at the resolution the user picks: show the plan first (a script voxelizes itself).
      state.voxelize.open_requested = true;
    }
  }
  state.voxelize_after_load = false;
}

// ---- Files ----

void requestOpen(AppState& state, const std::filesystem::path& path) {
  guardUnsaved(state, [path](AppState& s) { startOpen(s, path); });
}

std::shared_ptr<MeshSource> makeMeshSource(const std::filesystem::path& path, io::MeshFileLoad&& load) {
  auto mesh = std::make_shared<MeshSource>();
  mesh->path = path;
  mesh->mesh = std::move(load.mesh);
  mesh->topology = load.topology;
  mesh->format = std::move(load.format_detail);
  mesh->bodies = std::move(load.bodies);
  mesh->units = std::move(load.units);
  mesh->file_units = std::move(load.file_units);
  mesh->warnings = std::move(load.warnings);
  mesh->notes = std::move(load.notes);
  mesh->volume = signedVolume(mesh->mesh);
  mesh->cad = std::move(load.cad);
  mesh->deflection = load.deflection;
  return mesh;
}

namespace {

// The level a .vxm file opens at, and its dims, when its grid does not fit in a quarter of the memory limit (the
// rest is for the view, undo and the analyses); nullopt when it fits (or cannot be read: loadVoxelFile says why).
std::optional<std::pair<int32_t, Dims>> coarseViewOf(const std::filesystem::path& path) {
  if (io::lowerExtension(path) != ".vxm") return std::nullopt;
  auto h = io::readVxmHeader(path);
  const uint64_t budget = defaultMemoryLimitBytes() / 4;
  if (!h || estimateGridBytes(h->dims) <= budget) return std::nullopt;
  return std::pair{io::coarseLevelFor(h->dims, budget), h->dims};
}

}  // namespace

void startRecover(AppState& state, const std::filesystem::path& autosave) {
  guardUnsaved(state, [autosave](AppState& s) { startOpen(s, autosave, true); });
}

void startOpen(AppState& state, const std::filesystem::path& path, bool recovered) {
  state.voxelize_job.abandon();
  state.job_started = nowSeconds();
  // A CAD file is tessellated for the resolution the Voxelize dialog holds; voxelizing finer tessellates it again.
  const int64_t resolution = state.voxelize.params.resolution;
  state.load_job.start("Opening " + path.filename().string(),
                       [path, resolution, recovered](const ProgressFn& progress) -> Result<LoadedFile> {
                         const double t0 = nowSeconds();
                         LoadedFile out;
                         out.path = path;
                         out.recovered = recovered;
                         if (io::isProjectFile(path)) {
                           auto project = io::loadProject(path);
                           if (!project) return project.error();
                           out.project = std::move(project).value();
                         } else if (const auto coarse = coarseViewOf(path)) {
                           auto grid = io::readVxmCoarse(path, coarse->first, progress);
                           if (!grid) return grid.error();
                           out.grid = std::move(grid).value();
                           out.coarse_level = coarse->first;
                           out.full_dims = coarse->second;
                         } else if (io::isVoxelFile(path)) {
                           auto grid = io::loadVoxelFile(path);
                           if (!grid) return grid.error();
                           out.grid = std::move(grid).value();
                         } else {
                           io::MeshFileOptions options;
                           options.resolution = resolution;
                           options.progress = progress;
                           auto load = workflow::readMeshFile(path, options);
                           if (!load) return load.error();
                           auto mesh = makeMeshSource(path, std::move(load).value());
                           mesh->load_s = nowSeconds() - t0;
                           out.mesh = std::move(mesh);
                         }
                         out.load_s = nowSeconds() - t0;
                         return out;
                       });
}

bool saveModel(AppState& state, const std::filesystem::path& path) {
  if (!state.doc.model) {
    reportError(state, "there is no model to save yet: voxelize the mesh first", path);
    return false;
  }
  const std::string ext = io::lowerExtension(path);
  if (ext != ".vxp" && ext != ".vxm" && ext != ".binvox") {
    reportError(state,
                "models are saved as .vxp (a voxmod project: the parts with their names, colours and placements), "
                ".vxm (voxmod's voxel file) or .binvox; choose one of those extensions",
                path);
    return false;
  }
  const Status s = ext == ".vxp" ? io::saveProject(projectOf(state), path) : io::saveVoxelFile(state.model, path);
  if (!s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  state.doc.save_path = path;
  state.doc.saved_version = state.doc.model->version;
  addRecentFile(state.settings, std::filesystem::absolute(path).lexically_normal().string());
  return true;
}

void saveOrAsk(AppState& state) {
  if (!state.doc.save_path.empty()) {
    saveModel(state, state.doc.save_path);
  } else {
    openBrowser(state, saveModelBrowsing(state));
  }
}

// ---- Unsaved changes ----

bool hasUnsavedChanges(const AppState& state) {
  return state.doc.model && state.doc.model->version != state.doc.saved_version;
}

void guardUnsaved(AppState& state, std::function<void(AppState&)> then) {
  if (!hasUnsavedChanges(state)) {
    then(state);
    return;
  }
  state.after_unsaved_prompt = std::move(then);
  state.unsaved_prompt_requested = true;
}

void saveThen(AppState& state, std::function<void(AppState&)> then) {
  if (!state.doc.save_path.empty()) {
    if (saveModel(state, state.doc.save_path) && then) then(state);
    return;
  }
  openBrowser(state, saveModelBrowsing(state));
  state.browser.then = std::move(then);  // runs only if a save from this browser succeeds
}

void requestQuit(AppState& state) {
  guardUnsaved(state, [](AppState& s) { s.quit_requested = true; });
}

std::string documentName(const AppState& state) {
  const std::filesystem::path& p = state.doc.save_path.empty() ? state.doc.path : state.doc.save_path;
  return p.filename().string();
}

std::string windowTitle(const AppState& state) {
  std::string t = "voxmod";
  if (!state.doc.path.empty()) {
    t += " - " + documentName(state);
    if (hasUnsavedChanges(state)) t += " *";
  }
  return t;
}

// ---- Model ----

std::string absoluteName(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path a = std::filesystem::absolute(path, ec);
  return (ec ? path : a).lexically_normal().string();
}

bool fileNamesNoUnits(const AppState& state) {
  if (state.doc.mesh) return state.doc.mesh->file_units.empty();
  return io::lowerExtension(state.doc.path) == ".binvox";
}

void setModelUnits(AppState& state, const std::string& units) {
  if (state.doc.model && !state.doc.path.empty() && fileNamesNoUnits(state)) {
    rememberFileUnits(state.settings, absoluteName(state.doc.path), units);
  }
  if (!state.doc.model || state.model.frame().units == units) return;
  // A statement about what the numbers mean, for the whole document: every snapshot shares it.
  const auto set = [&](ModelSnapshot& s) {
    s.grid.frame().units = units;
    s.base.frame().units = units;
  };
  set(*state.doc.model);
  for (ModelSnapshot& s : state.doc.undo_stack) set(s);
  for (ModelSnapshot& s : state.doc.redo_stack) set(s);
  state.model.frame().units = units;
  state.doc.saved_version = 0;  // the file on disk says otherwise now: worth saving
}

bool canUndo(const AppState& state) { return !state.doc.undo_stack.empty() && !modelBusy(state); }
bool canRedo(const AppState& state) { return !state.doc.redo_stack.empty() && !modelBusy(state); }

void undo(AppState& state) {
  if (!canUndo(state)) return;
  ModelSnapshot prev = std::move(state.doc.undo_stack.back());
  state.doc.undo_stack.pop_back();
  state.doc.redo_stack.push_back(std::move(*state.doc.model));
  setModel(state, std::move(prev), false);
}

void redo(AppState& state) {
  if (!canRedo(state)) return;
  ModelSnapshot next = std::move(state.doc.redo_stack.back());
  state.doc.redo_stack.pop_back();
  state.doc.undo_stack.push_back(std::move(*state.doc.model));
  setModel(state, std::move(next), false);
}

}  // namespace vox::app
