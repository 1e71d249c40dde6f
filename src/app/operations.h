#pragma once
// The operations behind the action table, the panels' buttons and the script: every change to the document goes
// through here (so it is undoable and marks the model unsaved), and every failure becomes an error dialog that
// names the file and the problem. No ImGui and no GL here.
#include <filesystem>
#include <functional>
#include <string>

#include "app/app_state.h"

namespace vox::app {

// ---- Files ----
// Asks about unsaved changes first, then opens (in the background) a mesh or voxel file.
void requestOpen(AppState& state, const std::filesystem::path& path);
// Opens without asking (the script, or after the prompt).
void startOpen(AppState& state, const std::filesystem::path& path);
// Saves the model as .vxm or .binvox (by extension); on success it is the file Save writes to from now on.
bool saveModel(AppState& state, const std::filesystem::path& path);
// Save to the current file, or ask for one (file browser) when there is none.
void saveOrAsk(AppState& state);
bool exportBinvox(AppState& state, const std::filesystem::path& path);
bool exportSectionPng(AppState& state, const std::filesystem::path& path);
bool exportXrayPng(AppState& state, const std::filesystem::path& path);
bool exportXrayCsv(AppState& state, const std::filesystem::path& path);
// Opens the file browser for a purpose (open, save as, exports).
void openBrowser(AppState& state, BrowserPurpose purpose);
// The extension(s) a purpose writes or reads, e.g. {".stl", ".vxm", ".binvox"} for kOpen.
std::vector<std::string> browserExtensions(BrowserPurpose purpose);
const char* browserTitle(BrowserPurpose purpose);
// Runs the purpose's operation on the chosen path; false when it failed (the browser stays open).
bool acceptBrowserPath(AppState& state, BrowserPurpose purpose, const std::filesystem::path& path);

// ---- Unsaved changes ----
bool hasUnsavedChanges(const AppState& state);
// Runs `then` now when nothing would be lost; otherwise asks Save / Discard / Cancel first.
void guardUnsaved(AppState& state, std::function<void(AppState&)> then);
// The unsaved prompt's "Save": save to the document's file, or ask where with the browser; `then` (quit, open
// another file) runs only after a successful save. A browser opened later for anything else never runs it.
void saveThen(AppState& state, std::function<void(AppState&)> then);
void requestQuit(AppState& state);

// ---- Model ----
// Voxelizes the open mesh in the background; the current model stays on screen until the new one is ready.
void startVoxelize(AppState& state, const VoxelizeParams& params);
// Memory a voxelization may take without a second thought: 4 GiB, or a quarter of the machine's memory if less.
uint64_t comfortableVoxelizeBytes();
// When the voxelize dialog opens: if the last resolution would need more than that for this mesh, propose the
// largest of 1000, 400, 200, 100 that does not, and say why (VoxelizeDialog::proposal_note).
void proposeResolution(AppState& state);
// The plan (dims, voxel size, memory) for these params, or why they cannot work.
Result<VoxelizePlan> planFor(const AppState& state, const VoxelizeParams& params);
void cancelJobs(AppState& state);
bool modelBusy(const AppState& state);  // loading or voxelizing

// Skin removal: show the model with `layers` outer layers removed from its base (0 = the base). Needs the depth
// map; asked for before it is ready, the peel is queued and happens when it arrives.
void peelTo(AppState& state, int32_t layers);
int32_t peelLayersAvailable(const AppState& state);  // layers of the base's depth map; -1 while unknown
const DepthMap* currentDepthMap(const AppState& state);
// The memory the skin layers may use (80% of physical memory), and why they would not fit for this grid (empty when
// they do): the depth map's estimate (estimateDepthMapBytes) plus the model itself.
uint64_t skinLayersMemoryLimit();
// Says what the model's coordinates are in (mm, cm, m, in, or "model"): the whole document, every undo step too.
void setModelUnits(AppState& state, const std::string& units);
std::string skinLayersMemoryProblem(const VoxelGrid& grid);

bool canUndo(const AppState& state);
bool canRedo(const AppState& state);
void undo(AppState& state);
void redo(AppState& state);

// ---- Each frame ----
// Moves finished background results in, applies queued peels, asks for the derived results the open panel needs,
// and recomputes the section when its key changed.
void updateDocument(AppState& state);
// The section for the current params (null when there is no model).
const Section* currentSection(AppState& state);
// The X-ray for the current params, once computed (null before, and without a model).
const XrayResult* currentXray(const AppState& state);
// Number of voxels along an axis of the model (0 without one).
int32_t axisLength(const AppState& state, Axis axis);

// ---- Messages ----
// Queues an error dialog. `message` should name the file; `file` is prefixed when it does not.
void reportError(AppState& state, const std::string& message, const std::filesystem::path& file = {});
// "part.stl *" style window title.
std::string windowTitle(const AppState& state);

// ---- Settings ----
void rememberSettings(AppState& state);  // params -> settings
void applySettings(AppState& state);     // settings -> params

}  // namespace vox::app
