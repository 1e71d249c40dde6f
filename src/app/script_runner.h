#pragma once
// Runs a --script (script.h) inside the window's frame loop: at the start of each frame, commands run until one has
// to wait (for background work, for frames, for a file, or for a screenshot to be written after the frame is drawn).
// A command that names an action is dispatched exactly as its menu item or button is (actions.h), then waits until
// its background work has finished; the harness's own commands are listed in script.h.
#include <string>

#include "app/app_state.h"
#include "app/harness.h"

namespace vox::app {

// Call once per frame before the UI is built.
void stepScript(Harness& harness, AppState& state);
// Between the backends' new frame and ImGui's: the harness's press or typing (harness.h), one step this frame, in
// place of what the mouse and keyboard gave (script_input.cpp).
void feedSyntheticInput(Harness* harness);
// True when no background work is running or queued: the window shows final results.
bool settled(const AppState& state);
// The window's state as "key = value" lines (the `state` command): section, peel, X-ray, model facts and the
// rectangles of the widgets a test driver clicks.
std::string describeState(const AppState& state, const Harness& harness);

}  // namespace vox::app
