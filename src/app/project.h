#pragma once
// The document as a voxmod project (vox/io/project_file.h, docs/file-format.md "Projects"): the model or the scene of
// parts with their names, colours, visibility and placements, the units, and the view worth keeping. Save writes one
// for a .vxp path, open reads one back, and autosave (autosave.h) keeps one for recovery. No ImGui and no GL here.
#include <filesystem>

#include "app/app_state.h"
#include "vox/io/project_file.h"

namespace vox::app {

// What the document holds now, as a project (grids shared, not copied).
io::ProjectFile projectOf(const AppState& state);
// A project read from `path` becomes the document, as it was saved: a new document whose model (or scene of parts)
// is the project's, with the panel, section and selection it had. `recovered`: it comes from an autosave, so it
// has no file of its own yet and is unsaved.
void applyProject(AppState& state, io::ProjectFile project, const std::filesystem::path& path, bool recovered);

}  // namespace vox::app
