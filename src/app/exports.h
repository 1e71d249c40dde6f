#pragma once
// Writing the model and the derived results to files: the model as binvox, the section and X-ray images as PNG, the
// X-ray thickness as CSV. Each returns false after an error dialog that names the file. The 3D view's export
// renders, so it lives with the viewport (view_export.h). No ImGui and no GL here.
#include <filesystem>

#include "app/app_state.h"

namespace vox::app {

bool exportBinvox(AppState& state, const std::filesystem::path& path);
// True while the view shows the Section panel's cut-away: the surface and volume exports of the model then write
// the half it keeps (cutAwayModel), and their status line says so (kCutAwayNote).
bool exportsCutAway(const AppState& state);
// The model as the view shows it: with the cut-away on, the half it keeps (the plane's voxels included).
VoxelGrid cutAwayModel(const AppState& state);
inline constexpr const char* kCutAwayNote = " (the half the cut-away keeps)";
// The model's surface (vox/analysis/surface_mesh.h; smooth: 10 smoothing passes) as a mesh file chosen by
// extension (.stl, .ply, .obj, .3mf); with the cut-away on, the half it keeps, the cut face included.
bool exportSurface(AppState& state, const std::filesystem::path& path, bool smooth);
bool exportSectionPng(AppState& state, const std::filesystem::path& path);
bool exportXrayPng(AppState& state, const std::filesystem::path& path);
bool exportXrayCsv(AppState& state, const std::filesystem::path& path);

}  // namespace vox::app
