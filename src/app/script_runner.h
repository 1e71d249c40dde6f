#pragma once
// Runs a --script (script.h) inside the window's frame loop: at the start of each frame, commands run until one has
// to wait (for a worker, for frames, for a file, or for a screenshot to be written after the frame is drawn).
#include <string>

#include "app/app_state.h"

namespace vox::app {

// Call once per frame before the UI is built.
void stepScript(AppState& state);
// True when no background work is running or queued: the window shows final results.
bool settled(const AppState& state);
// The window's state as "key = value" lines (the `state` command): section, peel, X-ray, model facts and the
// rectangles of the widgets a test driver clicks.
std::string describeState(const AppState& state);

}  // namespace vox::app
