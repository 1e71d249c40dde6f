#pragma once
// The 3D view's export. It renders with the viewport's GL objects, so it is defined where the rendering is
// (viewport.cpp); it is declared apart from the viewport's ImGui panel (viewport.h) so that the file browser's
// purposes and the script can name it without including the viewport.
#include <filesystem>

#include "app/app_state.h"

namespace vox::app {

// Renders the view at full detail and writes it as PNG; false (and an error dialog) on failure.
bool exportViewPng(AppState& state, const std::filesystem::path& path);
// The view rendered at full detail as the export writes it (with the thickness legend where the panel shows one).
Result<ImageRgba> renderViewImage(AppState& state);

}  // namespace vox::app
