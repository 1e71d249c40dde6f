#include "app/messages.h"

#include <cstdio>
#include <utility>

namespace vox::app {

void reportError(AppState& state, const std::string& message, const std::filesystem::path& file) {
  std::string text = message;
  if (!file.empty() && message.find(file.filename().string()) == std::string::npos) {
    text = file.filename().string() + ": " + message;
  }
  // A script has nobody to click OK: it fails, and says why on stderr.
  if (state.script) {
    std::fprintf(stderr, "voxmod: %s\n", text.c_str());
    state.script->failed = true;
    state.script->last_error = text;
  }
  state.errors.messages.push_back(std::move(text));
}

std::string describe(const Error& e, const std::filesystem::path& file) {
  return file.empty() || e.message.find(file.filename().string()) != std::string::npos
             ? e.message
             : file.filename().string() + ": " + e.message;
}

}  // namespace vox::app
