#include "app/messages.h"

#include <algorithm>
#include <utility>

namespace vox::app {

void reportError(AppState& state, const std::string& message, const std::filesystem::path& file) {
  std::string text = message;
  if (!file.empty() && message.find(file.filename().string()) == std::string::npos) {
    text = file.filename().string() + ": " + message;
  }
  ++state.errors.reported;
  state.errors.last_reported = text;
  // The same message already waiting (a failure that repeats every frame) is shown once.
  if (std::find(state.errors.messages.begin(), state.errors.messages.end(), text) != state.errors.messages.end())
    return;
  state.errors.messages.push_back(std::move(text));
}

std::string describe(const Error& e, const std::filesystem::path& file) {
  return file.empty() || e.message.find(file.filename().string()) != std::string::npos
             ? e.message
             : file.filename().string() + ": " + e.message;
}

}  // namespace vox::app
