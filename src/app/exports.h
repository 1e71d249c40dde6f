#pragma once
// Writing the model and the derived results to files: the model as binvox, the section and X-ray images as PNG, the
// X-ray thickness as CSV. Each returns false after an error dialog that names the file. The 3D view's export
// renders, so it lives with the viewport (view_export.h). No ImGui and no GL here.
#include <filesystem>

#include "app/app_state.h"

namespace vox::app {

bool exportBinvox(AppState& state, const std::filesystem::path& path);
// The model's surface (vox/analysis/surface_mesh.h; smooth: 10 smoothing passes) as a mesh file chosen by
// extension (.stl, .ply, .obj, .3mf).
bool exportSurface(AppState& state, const std::filesystem::path& path, bool smooth);
bool exportSectionPng(AppState& state, const std::filesystem::path& path);
bool exportXrayPng(AppState& state, const std::filesystem::path& path);
bool exportXrayCsv(AppState& state, const std::filesystem::path& path);

}  // namespace vox::app
