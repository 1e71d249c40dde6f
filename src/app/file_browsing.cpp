#include "app/file_browsing.h"

#include <system_error>
#include <utility>

#include "app/actions.h"
#include "app/messages.h"
#include "vox/core/text.h"
#include "vox/io/mesh_file.h"

namespace vox::app {

void openBrowser(AppState& state, Browsing browsing) {
  FileBrowser& b = state.browser;
  b.open_requested = true;
  b.accepted = false;
  b.then = nullptr;  // a continuation belongs to the browsing that set it (saveThen), never to a later one
  b.action = browsing.action;
  b.title = std::move(browsing.title);
  b.extensions = std::move(browsing.extensions);
  b.file_name = std::move(browsing.file_name);
  b.saving = browsing.saving;
  b.error.clear();
  std::error_code ec;
  std::filesystem::path dir = state.settings.last_directory;
  if (dir.empty() || !std::filesystem::is_directory(dir, ec)) dir = std::filesystem::current_path(ec);
  b.directory = dir;
}

std::string documentStem(const AppState& state) {
  return state.doc.path.empty() ? std::string("model") : state.doc.path.stem().string();
}

std::vector<std::string> openableExtensions(bool projects) {
  std::vector<std::string> all = io::meshFileExtensions();
  if (projects) all.push_back(".vxp");
  all.insert(all.end(), {".vxm", ".binvox"});
  return all;
}

Browsing saveModelBrowsing(const AppState& state) {
  const bool scene = state.doc.model && state.doc.model->parts;
  return {ActionId::kSaveAs,
          "Save the model as",
          {".vxp", ".vxm", ".binvox"},
          documentStem(state) + (scene ? ".vxp" : ".vxm")};
}

void usePath(AppState& state, const std::filesystem::path& path, PathSays says,
             const std::function<bool(AppState&, const std::filesystem::path&)>& use) {
  state.browser.went_through = false;
  if (path.filename().empty()) {
    reportError(state, "no file name given", path);
    return;
  }
  if (!use(state, path)) return;
  state.browser.went_through = true;
  state.settings.last_directory = std::filesystem::absolute(path).parent_path().string();
  if (says == PathSays::kWrote) {  // where it went: the name typed may have been relative, or the folder not in mind
    state.status_message = "Wrote " + std::filesystem::absolute(path).lexically_normal().string();
    state.status_since = nowSeconds();
  }
  if (auto then = std::move(state.browser.then)) {
    state.browser.then = nullptr;
    then(state);
  }
}

bool isExistingFile(AppState& state, const std::filesystem::path& path) {
  if (std::error_code ec; std::filesystem::is_regular_file(path, ec)) return true;
  reportError(state, path.string() + ": no such file");
  return false;
}

bool givePath(AppState& state, ActionId action, const std::filesystem::path& path) {
  state.browser.went_through = false;
  const std::string text = path.string();
  // the action's own function, without its enabled check: the browser was opened by it, and a path it can no longer
  // use (the results it writes gone meanwhile) is refused by the function, saying why
  const Action& a = vox::app::action(action);
  if (!a.run_with) return false;
  if (Status st = a.run_with(state, ActionArgs{{text}, text}); !st) {
    reportError(state, st.error().message, path);
    return false;
  }
  return state.browser.went_through;
}

}  // namespace vox::app
