#pragma once
// The document's operations: opening and saving files, the unsaved-changes guard, the model's units, undo and
// redo, and the window title. The other operations replace the model through setModel, so every change is undoable
// and marks the model unsaved. No ImGui and no GL here.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "app/app_state.h"

namespace vox::app {

// ---- Files ----
// Asks about unsaved changes first, then opens (in the background) a mesh or voxel file.
void requestOpen(AppState& state, const std::filesystem::path& path);
// Opens without asking (the script, or after the prompt). `recovered`: `path` is an autosave (autosave.h) to recover.
void startOpen(AppState& state, const std::filesystem::path& path, bool recovered = false);
// Asks about unsaved changes first, then recovers an autosave as an unsaved document (autosave.h).
void startRecover(AppState& state, const std::filesystem::path& autosave);
// Saves the model as .vxm or .binvox (by extension); on success it is the file Save writes to from now on.
bool saveModel(AppState& state, const std::filesystem::path& path);
// Save to the current file, or ask for one (file browser) when there is none.
void saveOrAsk(AppState& state);

// ---- Unsaved changes ----
bool hasUnsavedChanges(const AppState& state);
// Runs `then` now when nothing would be lost; otherwise asks Save / Discard / Cancel first.
void guardUnsaved(AppState& state, std::function<void(AppState&)> then);
// The unsaved prompt's "Save": save to the document's file, or ask where with the browser; `then` (quit, open
// another file) runs only after a successful save. A browser opened later for anything else never runs it.
void saveThen(AppState& state, std::function<void(AppState&)> then);
void requestQuit(AppState& state);
// The document's name: the file it was last saved to, else the file it was opened from ("part.vxm").
std::string documentName(const AppState& state);
// "part.stl *" style window title.
std::string windowTitle(const AppState& state);

// ---- Model ----
// Says what the model's coordinates are in (mm, cm, m, in, or "model"): the whole document, every undo step too.
// For a file that names no unit (STL, OBJ, PLY, OFF, .binvox) the choice is remembered for that file.
void setModelUnits(AppState& state, const std::string& units);
// Whether the document's file names no length unit, so that the user's choice is remembered for it.
bool fileNamesNoUnits(const AppState& state);
// `path` made absolute and normal: the name files are remembered by.
std::string absoluteName(const std::filesystem::path& path);

bool canUndo(const AppState& state);
bool canRedo(const AppState& state);
void undo(AppState& state);
void redo(AppState& state);

// ---- For the operations that replace the model (loading, voxelizing, peeling, undo / redo) ----
// A new id for a base or a version (AppState::next_id).
uint64_t takeId(AppState& state);
// Makes `snapshot` the current model. The previous one goes on the undo stack when `undoable`.
void setModel(AppState& state, ModelSnapshot snapshot, bool undoable);
// A new base (a loaded or voxelized grid, nothing peeled) with its own base id and version.
ModelSnapshot newBase(AppState& state, VoxelGrid grid, std::shared_ptr<const ModelOrigin> origin, std::string label);
// A finished load becomes the document (updateDocument): what was derived from the previous one is dropped; a voxel
// file is the model, a mesh waits to be voxelized.
void applyLoaded(AppState& state, LoadedFile loaded);

}  // namespace vox::app
