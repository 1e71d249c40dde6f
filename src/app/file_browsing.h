#pragma once
// The file browser (panels/file_browser.cpp draws it) opened for an action of the table that takes a path, and the
// part those actions share: the path used, its folder remembered, where it wrote said. The browser gives the path it
// names to its action, as a script does. No ImGui and no GL here.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "app/app_state.h"
#include "vox/core/result.h"

namespace vox::app {

// What the browser is opened for.
struct Browsing {
  ActionId action;                      // the action its path is given to
  std::string title;                    // over the browser
  std::vector<std::string> extensions;  // what it lists (none: it names a folder)
  std::string file_name;                // proposed
  bool saving = true;                   // a file to write (else one to open)
};
void openBrowser(AppState& state, Browsing browsing);

// The document's file name without its extension ("model" without one): the start of the names proposed.
std::string documentStem(const AppState& state);
// What Open and Add part list: the mesh and CAD formats and the voxel files, with projects when `projects`.
std::vector<std::string> openableExtensions(bool projects);
// Save As: a project for a scene of parts (which keeps its parts only in a project), else a .vxm file.
Browsing saveModelBrowsing(const AppState& state);

// What a path action says when it went through: nothing more (it says so itself, or runs in the background), or
// "Wrote PATH" in the status bar.
enum class PathSays { kNothing, kWrote };
// Gives `path` (the browser's, or a script's words after the action's name) to `use`, which shows its own failure. A
// path without a file name is refused. When it went through: its folder is remembered, PathSays is said, and the
// browser's continuation (the unsaved-changes prompt's Save) runs. state.browser.went_through records which.
void usePath(AppState& state, const std::filesystem::path& path, PathSays says,
             const std::function<bool(AppState&, const std::filesystem::path&)>& use);

// Whether `path` is a file that exists; when not, says so ("PATH: no such file"). Open and Add part refuse a missing
// file before anything else, while the browser can stay open.
bool isExistingFile(AppState& state, const std::filesystem::path& path);
// Gives `path` to the path action `action` (its function, as the browser's Save or Open does; the action opened the
// browser, so its enabled check is not made again); a failure is shown as a dialog. Returns whether it went through.
bool givePath(AppState& state, ActionId action, const std::filesystem::path& path);

}  // namespace vox::app
