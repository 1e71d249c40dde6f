#pragma once
// File > Export report (HTML): the report `voxmod report` writes (vox/workflow/report.h), of the model shown, with
// the 3D view as the window shows it for its first picture. The view is rendered at once; the analyses and the file
// run in the background as the volume exports do (progress in the status bar, Esc cancels, "Wrote FILE" when done).
// The minimum wall is the Thickness panel's when chosen there, the material the Mass panel's.
#include <filesystem>

#include "app/app_state.h"

namespace vox::app {

// False, with an error dialog, without a model or for a name not ending in .html.
bool startReportExport(AppState& state, const std::filesystem::path& path);

}  // namespace vox::app
