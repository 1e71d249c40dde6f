#pragma once
// The file browser's purposes (open, save as, the exports): what it opens on, what it shows and what it does with
// the chosen path. The browser itself is a panel (panels/file_browser.cpp). No ImGui and no GL here.
#include <filesystem>
#include <string>
#include <vector>

#include "app/app_state.h"

namespace vox::app {

// Opens the file browser for a purpose (open, save as, exports).
void openBrowser(AppState& state, BrowserPurpose purpose);
// The extension(s) a purpose writes or reads, e.g. {".stl", ".obj", ..., ".step", ..., ".vxm", ".binvox"} for kOpen.
std::vector<std::string> browserExtensions(BrowserPurpose purpose);
const char* browserTitle(BrowserPurpose purpose);
// Runs the purpose's operation on the chosen path; false when it failed (the browser stays open).
bool acceptBrowserPath(AppState& state, BrowserPurpose purpose, const std::filesystem::path& path);

}  // namespace vox::app
