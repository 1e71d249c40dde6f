#include "app/messages.h"

#include <utility>

namespace vox::app {

void reportError(AppState& state, const std::string& message, const std::filesystem::path& file) {
  std::string text = message;
  if (!file.empty() && message.find(file.filename().string()) == std::string::npos) {
    text = file.filename().string() + ": " + message;
  }
  ++state.errors.reported;
  state.errors.last_reported = text;
  state.errors.messages.push_back(std::move(text));
}

std::string describe(const Error& e, const std::filesystem::path& file) {
  return file.empty() || e.message.find(file.filename().string()) != std::string::npos
             ? e.message
             : file.filename().string() + ": " + e.message;
}

}  // namespace vox::app
