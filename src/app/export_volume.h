#pragma once
// Volume export from the window (File > Export volume..., Export thickness volume..., Export depth volume...,
// Export X-ray volume...): the model's voxels as the view shows them (with the Section panel's cut-away on, the half
// it keeps), the Thickness panel's local thickness with the voxels and the distance to the surface, the Skin panel's
// skin depth, or the X-ray panel's image, written in the format the file's extension names
// (vox/io/volume_export.h). The depth and the X-ray are written as voxmod peel --depth and voxmod xray --volume write
// them. Large volumes take seconds, so the file is written in the background, with progress in the status bar and
// Cancel (Esc); the model can change meanwhile (the export has its own copy). When it finishes, the status bar says
// where it wrote; a failure is an error dialog naming the file. No ImGui and no GL here.
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
// Starts writing the skin depth to `path` (.vti, .vdb or .nrrd), the field "depth" alone: each voxel's skin layer
// in the Skin panel's depth map of the model before layer peels (1 = the outer skin, the core last, 0 empty), as
// voxmod peel FILE --all --depth writes it for that model; the status line adds how many layers were peeled when
// some were. False, with an error dialog, before the skin layers are computed or for another extension.
bool startDepthExport(AppState& state, const std::filesystem::path& path);
// Starts writing the X-ray panel's image (its axis and mode) to `path` (.vti, .vdb or .nrrd), the field "xray"
// alone: a slab one voxel thick along the axis, each ray's thickness in model units, as voxmod xray --volume writes
// it. False, with an error dialog, before the X-ray is computed or for another extension.
bool startXrayVolumeExport(AppState& state, const std::filesystem::path& path);
// Each frame (updateDocument): takes a finished export's result in.
void pollVolumeExport(AppState& state);
bool volumeExportRunning(const AppState& state);
void cancelVolumeExport(AppState& state);

}  // namespace vox::app
