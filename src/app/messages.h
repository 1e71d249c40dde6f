#pragma once
// How the operations say what went wrong: an error dialog that names the file and the problem (a script has nobody
// to click OK: it fails instead). No ImGui and no GL here.
#include <filesystem>
#include <string>

#include "app/app_state.h"

namespace vox::app {

// Queues an error dialog. `message` should name the file; `file` is prefixed when it does not.
void reportError(AppState& state, const std::string& message, const std::filesystem::path& file = {});
// An error's message, with `file`'s name prefixed when the message does not name it.
std::string describe(const Error& e, const std::filesystem::path& file);

}  // namespace vox::app
