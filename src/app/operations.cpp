#include "app/operations.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <system_error>

#include "app/viewport.h"
#include "vox/core/text.h"
#include "vox/io/figure.h"
#include "vox/io/file_util.h"
#include "vox/io/image_io.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"

namespace vox::app {

double nowSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

const char* panelName(Panel p) {
  switch (p) {
    case Panel::kModel:
      return "model";
    case Panel::kSection:
      return "section";
    case Panel::kSkin:
      return "skin";
    case Panel::kXray:
      return "xray";
    case Panel::kMass:
      return "mass";
  }
  return "model";
}

namespace {

std::string lowerExtension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// Makes `snapshot` the current model. The previous one goes on the undo stack when `undoable`.
// A new grid (re-voxelized, or undo / redo across a voxelization) may lie on another lattice; the camera lives in
// voxel-index space, so it is carried over to the new lattice to keep showing the same part of the model. A first
// model is fitted instead.
void keepTheView(AppState& state, const GridFrame& before, bool had_model) {
  const GridFrame& now = state.model.frame();
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
  state.viewport.dirty = true;
  keepTheView(state, before, had_model);
  // Keep the section where it was when it still fits; start in the middle otherwise.
  const int32_t n = axisLength(state, state.section.axis);
  if (state.section.index < 0 || state.section.index >= n) state.section.index = n / 2;
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
  // Results derived from the previous document can never be asked for again: free them now.
  state.depth.clear();
  state.surface_stats.clear();
  state.mass.clear();
  state.xray_result.clear();
  state.skin.pending_peel.reset();
  state.model = VoxelGrid{};
  state.model_version = 0;
  state.section.index = -1;
  state.section.playing = false;
  state.view.fit_pending = true;
  state.viewport.dirty = true;
  state.release_memory = true;
  doc.path = loaded.path;
  addRecentFile(state.settings, std::filesystem::absolute(loaded.path).lexically_normal().string());
  state.settings.last_directory = std::filesystem::absolute(loaded.path).parent_path().string();
  if (loaded.grid) {
    auto origin = std::make_shared<ModelOrigin>();
    origin->what = "loaded " + loaded.path.filename().string();
    origin->load_s = loaded.load_s;
    VoxelGrid grid = std::move(*loaded.grid);
    if (grid.frame().source.empty()) grid.frame().source = loaded.path.filename().string();
    setModel(state, newBase(state, std::move(grid), std::move(origin), "open " + loaded.path.filename().string()),
             false);
    doc.save_path = loaded.path;
    doc.saved_version = doc.model->version;
    state.panel = Panel::kModel;
    state.panel_change_requested = true;
  } else {
    doc.mesh = std::move(loaded.mesh);
    doc.saved_version = 0;
    state.panel = Panel::kModel;
    state.panel_change_requested = true;
    if (state.voxelize_after_load || !state.screenshot_on_idle.empty()) {
      // Voxelized without being asked (the bundled part at start-up).
      startVoxelize(state, state.voxelize.params);
    } else if (!state.script) {
      // A mesh is voxelized at the resolution the user picks: show the plan first (a script voxelizes itself).
      state.voxelize.open_requested = true;
    }
  }
  state.voxelize_after_load = false;
}

void applyVoxelized(AppState& state, VoxelizeResult result, const VoxelizeParams& params, double seconds) {
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

std::string describe(const Error& e, const std::filesystem::path& file) {
  return file.empty() || e.message.find(file.filename().string()) != std::string::npos
             ? e.message
             : file.filename().string() + ": " + e.message;
}

}  // namespace

int32_t axisLength(const AppState& state, Axis axis) {
  if (state.model.empty()) return 0;
  switch (axis) {
    case Axis::kX:
      return state.model.nx();
    case Axis::kY:
      return state.model.ny();
    case Axis::kZ:
      return state.model.nz();
  }
  return 0;
}

void reportError(AppState& state, const std::string& message, const std::filesystem::path& file) {
  std::string text = message;
  if (!file.empty() && message.find(file.filename().string()) == std::string::npos) {
    text = file.filename().string() + ": " + message;
  }
  // A script has nobody to click OK: it fails, and says why on stderr.
  if (state.script) {
    std::fprintf(stderr, "voxmod: %s\n", text.c_str());
    state.script->failed = true;
    state.script->last_error = text;
  }
  state.errors.messages.push_back(std::move(text));
}

// ---- Files ----

void requestOpen(AppState& state, const std::filesystem::path& path) {
  guardUnsaved(state, [path](AppState& s) { startOpen(s, path); });
}

void startOpen(AppState& state, const std::filesystem::path& path) {
  state.voxelize_job.abandon();
  state.job_started = nowSeconds();
  state.load_job.start("Opening " + path.filename().string(), [path](const ProgressFn&) -> Result<LoadedFile> {
    const double t0 = nowSeconds();
    LoadedFile out;
    out.path = path;
    if (io::isVoxelFile(path)) {
      auto grid = io::loadVoxelFile(path);
      if (!grid) return grid.error();
      out.grid = std::move(grid).value();
    } else {
      auto stl = io::loadStl(path);
      if (!stl) return stl.error();
      auto mesh = std::make_shared<MeshSource>();
      mesh->path = path;
      mesh->mesh = std::move(stl->mesh);
      mesh->topology = stl->topology;
      mesh->ascii = stl->ascii;
      mesh->warnings = std::move(stl->warnings);
      mesh->notes = std::move(stl->notes);
      mesh->volume = signedVolume(mesh->mesh);
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
  const std::string ext = lowerExtension(path);
  if (ext != ".vxm" && ext != ".binvox") {
    reportError(state, "models are saved as .vxm (voxmod) or .binvox; choose one of those extensions", path);
    return false;
  }
  if (Status s = io::saveVoxelFile(state.model, path); !s) {
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
    openBrowser(state, BrowserPurpose::kSaveModel);
  }
}

bool exportBinvox(AppState& state, const std::filesystem::path& path) {
  if (state.model.empty()) {
    reportError(state, "there is no model to export", path);
    return false;
  }
  if (Status s = io::saveBinvox(state.model, path); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

bool exportSectionPng(AppState& state, const std::filesystem::path& path) {
  const Section* section = currentSection(state);
  if (!section) {
    reportError(state, "there is no section to export", path);
    return false;
  }
  if (Status s = io::savePng(renderSection(*section, 1), path); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

const XrayResult* currentXray(const AppState& state) {
  const XrayKey key{state.model_version, state.xray.params.axis, state.xray.params.mode};
  const auto* x = state.xray_result.get(key);
  return x ? x->get() : nullptr;
}

bool exportXrayPng(AppState& state, const std::filesystem::path& path) {
  const XrayResult* x = currentXray(state);
  if (!x) {
    reportError(state, "there is no X-ray image to export (open the X-ray panel first)", path);
    return false;
  }
  // Independent of the window: about 512 pixels across the longer side of the map.
  const int32_t longest = std::max({x->thickness.width, x->thickness.height, 1});
  const int32_t scale = std::clamp((512 + longest - 1) / longest, 1, 8);
  if (Status s = io::savePng(io::drawScalarMapFigure(x->thickness, x->max, xrayLegend(*x), scale).image, path); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

bool exportXrayCsv(AppState& state, const std::filesystem::path& path) {
  const XrayResult* x = currentXray(state);
  if (!x) {
    reportError(state, "there is no X-ray to export (open the X-ray panel first)", path);
    return false;
  }
  if (Status s = io::writeFileAtomic(path, xrayCsv(*x)); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

std::vector<std::string> browserExtensions(BrowserPurpose purpose) {
  switch (purpose) {
    case BrowserPurpose::kOpen:
      return {".stl", ".vxm", ".binvox"};
    case BrowserPurpose::kSaveModel:
      return {".vxm", ".binvox"};
    case BrowserPurpose::kExportBinvox:
      return {".binvox"};
    case BrowserPurpose::kExportViewPng:
    case BrowserPurpose::kExportSectionPng:
    case BrowserPurpose::kExportXrayPng:
      return {".png"};
    case BrowserPurpose::kExportXrayCsv:
      return {".csv"};
  }
  return {};
}

const char* browserTitle(BrowserPurpose purpose) {
  switch (purpose) {
    case BrowserPurpose::kOpen:
      return "Open a mesh or voxel file";
    case BrowserPurpose::kSaveModel:
      return "Save the model as";
    case BrowserPurpose::kExportBinvox:
      return "Export binvox";
    case BrowserPurpose::kExportViewPng:
      return "Export the 3D view as PNG";
    case BrowserPurpose::kExportSectionPng:
      return "Export the section image as PNG";
    case BrowserPurpose::kExportXrayPng:
      return "Export the X-ray image as PNG";
    case BrowserPurpose::kExportXrayCsv:
      return "Export the X-ray thickness as CSV";
  }
  return "";
}

void openBrowser(AppState& state, BrowserPurpose purpose) {
  FileBrowser& b = state.browser;
  b.open_requested = true;
  b.then = nullptr;  // a continuation belongs to the browsing that set it (saveThen), never to a later one
  b.purpose = purpose;
  b.error.clear();
  std::error_code ec;
  std::filesystem::path dir = state.settings.last_directory;
  if (dir.empty() || !std::filesystem::is_directory(dir, ec)) dir = std::filesystem::current_path(ec);
  b.directory = dir;
  const std::string stem = state.doc.path.empty() ? std::string("model") : state.doc.path.stem().string();
  switch (purpose) {
    case BrowserPurpose::kOpen:
      b.file_name.clear();
      break;
    case BrowserPurpose::kSaveModel:
      b.file_name = stem + ".vxm";
      break;
    case BrowserPurpose::kExportBinvox:
      b.file_name = stem + ".binvox";
      break;
    case BrowserPurpose::kExportViewPng:
      b.file_name = stem + "_view.png";
      break;
    case BrowserPurpose::kExportSectionPng:
      b.file_name = stem + "_section_" + axisName(state.section.axis) + std::to_string(state.section.index) + ".png";
      break;
    case BrowserPurpose::kExportXrayPng:
      b.file_name =
          stem + "_xray_" + axisName(state.xray.params.axis) + "_" + xrayModeName(state.xray.params.mode) + ".png";
      break;
    case BrowserPurpose::kExportXrayCsv:
      b.file_name =
          stem + "_xray_" + axisName(state.xray.params.axis) + "_" + xrayModeName(state.xray.params.mode) + ".csv";
      break;
  }
}

bool acceptBrowserPath(AppState& state, BrowserPurpose purpose, const std::filesystem::path& path) {
  if (path.filename().empty()) {
    reportError(state, "no file name given", path);
    return false;
  }
  bool ok = false;
  switch (purpose) {
    case BrowserPurpose::kOpen:
      // Refuse a missing file here, where the browser can stay open, rather than after the unsaved prompt.
      if (std::error_code ec; !std::filesystem::is_regular_file(path, ec)) {
        reportError(state, path.string() + ": no such file");
        return false;
      }
      requestOpen(state, path);
      ok = true;
      break;
    case BrowserPurpose::kSaveModel:
      ok = saveModel(state, path);
      break;
    case BrowserPurpose::kExportBinvox:
      ok = exportBinvox(state, path);
      break;
    case BrowserPurpose::kExportViewPng:
      ok = exportViewPng(state, path);
      break;
    case BrowserPurpose::kExportSectionPng:
      ok = exportSectionPng(state, path);
      break;
    case BrowserPurpose::kExportXrayPng:
      ok = exportXrayPng(state, path);
      break;
    case BrowserPurpose::kExportXrayCsv:
      ok = exportXrayCsv(state, path);
      break;
  }
  if (ok) {
    state.settings.last_directory = std::filesystem::absolute(path).parent_path().string();
    if (auto then = std::move(state.browser.then)) {
      state.browser.then = nullptr;
      then(state);
    }
  }
  return ok;
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
  openBrowser(state, BrowserPurpose::kSaveModel);
  state.browser.then = std::move(then);  // runs only if a save from this browser succeeds
}

void requestQuit(AppState& state) {
  guardUnsaved(state, [](AppState& s) { s.quit_requested = true; });
}

// ---- Model ----

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

void startVoxelize(AppState& state, const VoxelizeParams& params) {
  if (!state.doc.mesh) {
    reportError(state, "there is no mesh to voxelize: open an STL file first", state.doc.path);
    return;
  }
  state.settings.resolution = params.resolution;
  state.settings.fill_mode = fillModeName(params.mode);
  state.voxelize_job_params = params;
  state.job_started = nowSeconds();
  auto mesh = state.doc.mesh;
  state.voxelize_job.start("Voxelizing " + mesh->path.filename().string(),
                           [mesh, params](const ProgressFn& progress) -> Result<VoxelizeResult> {
                             return voxelizeSolid(mesh->mesh, params, progress, &mesh->topology);
                           });
}

void cancelJobs(AppState& state) {
  state.load_job.cancel();
  state.voxelize_job.cancel();
}

bool modelBusy(const AppState& state) { return state.load_job.active() || state.voxelize_job.active(); }

void setModelUnits(AppState& state, const std::string& units) {
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

uint64_t skinLayersMemoryLimit() { return physicalMemoryBytes() / 5 * 4; }

std::string skinLayersMemoryProblem(const VoxelGrid& grid) {
  const uint64_t need = estimateDepthMapBytes(grid) + grid.memoryBytes();
  const uint64_t limit = skinLayersMemoryLimit();
  if (limit == 0 || need <= limit) return {};
  return "the skin layers of this " + std::to_string(grid.nx()) + " x " + std::to_string(grid.ny()) + " x " +
         std::to_string(grid.nz()) + " model need up to " + formatBytes(need) + " with the model, more than " +
         formatBytes(limit) +
         " (80% of this machine's memory): voxelize at a lower resolution to peel in the window, "
         "or peel with 'voxmod peel FILE --layers N' (about three copies of the grid)";
}

const DepthMap* currentDepthMap(const AppState& state) {
  if (!state.doc.model) return nullptr;
  const auto* d = state.depth.get(state.doc.model->base_id);
  return d ? d->get() : nullptr;
}

int32_t peelLayersAvailable(const AppState& state) {
  const DepthMap* d = currentDepthMap(state);
  return d ? d->layers() : -1;
}

void peelTo(AppState& state, int32_t layers) {
  if (!state.doc.model) return;
  const DepthMap* depth = currentDepthMap(state);
  if (!depth) {
    state.skin.pending_peel = layers;  // applied by updateDocument when the depth map arrives
    return;
  }
  state.skin.pending_peel.reset();
  // The core (the last layer) stays: peeling it too would leave nothing to look at.
  const int32_t k = std::clamp(layers, 0, std::max(depth->layers() - 1, 0));
  const ModelSnapshot& cur = *state.doc.model;
  if (k == cur.peeled) return;
  ModelSnapshot next;
  next.base_id = cur.base_id;
  next.base = cur.base;
  next.version = takeId(state);
  next.peeled = k;
  next.grid = depth->remainingAfter(k);
  next.origin = cur.origin;
  next.label = k == 0 ? "reset skin" : "peel to layer " + std::to_string(k);
  setModel(state, std::move(next), true);
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

// ---- Each frame ----

const Section* currentSection(AppState& state) {
  if (state.model.empty()) return nullptr;
  const int32_t n = axisLength(state, state.section.axis);
  state.section.index = std::clamp(state.section.index, 0, std::max(n - 1, 0));
  const SectionKey key{state.model_version, state.section.axis, state.section.index};
  if (!(key == state.section_key)) {
    state.section_key = key;
    auto s = computeSection(state.model, SectionParams{state.section.axis, state.section.index});
    if (s) {
      state.section_result = std::move(s).value();
      state.section_error.clear();
    } else {
      state.section_result.reset();
      state.section_error = s.error().message;
    }
    state.section_texture.reset();  // re-uploaded by the panel when shown
  }
  return state.section_result ? &*state.section_result : nullptr;
}

void updateDocument(AppState& state) {
  if (auto loaded = state.load_job.take()) {
    if (loaded->ok()) {
      applyLoaded(state, std::move(*loaded).value());
    } else if (loaded->error().code != ErrorCode::kCancelled) {
      reportError(state, loaded->error().message);
    }
  }
  if (auto result = state.voxelize_job.take()) {
    if (result->ok()) {
      applyVoxelized(state, std::move(*result).value(), state.voxelize_job_params, nowSeconds() - state.job_started);
    } else if (result->error().code != ErrorCode::kCancelled) {
      reportError(state, result->error().message, state.doc.path);
    }
  }
  state.depth.poll();
  state.surface_stats.poll();
  state.mass.poll();
  state.xray_result.poll();
  if (!state.doc.model) return;

  const ModelSnapshot& m = *state.doc.model;
  // The depth map of the base: needed by the Skin panel and by queued peels.
  // (Each request runs only when its key has nothing yet: the grid copies for the workers are made only then.)
  if ((state.panel == Panel::kSkin || state.skin.pending_peel) && state.depth.wants(m.base_id)) {
    VoxelGrid base = m.base;
    state.depth.request(m.base_id, "Computing skin layers", [base](const ProgressFn& progress) {
      // Refused before anything is allocated when it could run the machine out of memory (it would take the
      // window, and the user's work, with it).
      if (const std::string why = skinLayersMemoryProblem(base); !why.empty()) {
        return Result<std::shared_ptr<const DepthMap>>(makeError(ErrorCode::kLimit, why));
      }
      auto d = computeDepthMap(base, progress);
      if (!d) return Result<std::shared_ptr<const DepthMap>>(d.error());
      return Result<std::shared_ptr<const DepthMap>>(std::make_shared<const DepthMap>(std::move(d).value()));
    });
  }
  if (const Error* e = state.depth.error(m.base_id); e && state.skin.pending_peel) {
    state.skin.pending_peel.reset();
    reportError(state, "skin removal failed: " + e->message, state.doc.path);
  }
  if (state.skin.pending_peel && currentDepthMap(state)) peelTo(state, *state.skin.pending_peel);

  const VoxelGrid& grid = state.model;
  if (state.surface_stats.wants(state.model_version)) {
    state.surface_stats.request(state.model_version, "Counting surface voxels",
                                [grid](const ProgressFn&) { return Result<SurfaceStats>(computeSurfaceStats(grid)); });
  }
  if (state.panel == Panel::kMass && state.mass.wants(state.model_version)) {
    state.mass.request(state.model_version, "Mass properties",
                       [grid](const ProgressFn&) { return Result<MassProperties>(computeMassProperties(grid)); });
  }
  const XrayKey xray_key{state.model_version, state.xray.params.axis, state.xray.params.mode};
  if (state.panel == Panel::kXray && state.xray_result.wants(xray_key)) {
    const XrayKey& key = xray_key;
    const XrayParams params = state.xray.params;
    state.xray_result.request(key, "X-ray", [grid, params](const ProgressFn&) {
      auto x = computeXray(grid, params);
      if (!x) return Result<std::shared_ptr<const XrayResult>>(x.error());
      return Result<std::shared_ptr<const XrayResult>>(std::make_shared<const XrayResult>(std::move(x).value()));
    });
  }
}

std::string windowTitle(const AppState& state) {
  std::string t = "voxmod";
  if (!state.doc.path.empty()) {
    t += " - " + state.doc.path.filename().string();
    if (hasUnsavedChanges(state)) t += " *";
  }
  return t;
}

// ---- Settings ----

void rememberSettings(AppState& state) {
  Settings& s = state.settings;
  s.resolution = state.voxelize.params.resolution;
  s.fill_mode = fillModeName(state.voxelize.params.mode);
  s.lit = state.view.lit;
  s.round_points = state.view.round_points;
  s.point_size_px = state.view.point_size_px;
  s.lod = state.view.lod;
}

void applySettings(AppState& state) {
  const Settings& s = state.settings;
  state.voxelize.params.resolution = s.resolution;
  if (auto mode = parseFillMode(s.fill_mode)) state.voxelize.params.mode = *mode;
  state.view.lit = s.lit;
  state.view.round_points = s.round_points;
  state.view.point_size_px = s.point_size_px;
  state.view.lod = s.lod;
}

}  // namespace vox::app
