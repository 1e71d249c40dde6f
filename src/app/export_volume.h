#pragma once
// Volume export from the window (File > Export volume..., File > Export thickness volume...): the model's voxels as
// the view shows them (with the Section panel's cut-away on, the half it keeps), or the Thickness panel's local
// thickness with the voxels and the distance to the surface, written in the format the file's extension names
// (vox/io/volume_export.h). Large volumes take seconds, so the file is written in the background, with progress in the
// status bar and Cancel (Esc); the model can change meanwhile (the export has its own copy). When it finishes, the
// status bar says where it wrote; a failure is an error dialog naming the file. No ImGui and no GL here.
#include <filesystem>

#include "app/app_state.h"

namespace vox::app {

// Starts writing the model to `path` (.vti, .vdb, .nrrd or .vox); with the cut-away on, the half it keeps, and the
// status line says so. False, with an error dialog, when there is no model, the cut-away keeps nothing or the
// extension is none of those.
bool startVolumeExport(AppState& state, const std::filesystem::path& path);
// Starts writing the thickness volume to `path`: in .vti and .vdb the voxels, the local thickness and the distance
// (model units, under those names); in .nrrd the thickness alone. False, with an error dialog, without a computed
// thickness or for another extension.
bool startThicknessExport(AppState& state, const std::filesystem::path& path);
// Each frame (updateDocument): takes a finished export's result in.
void pollVolumeExport(AppState& state);
bool volumeExportRunning(const AppState& state);
void cancelVolumeExport(AppState& state);

}  // namespace vox::app
