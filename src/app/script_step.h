#pragma once
// One step of a script command (script_runner.cpp runs them; the harness's presses and typing are
// script_input.cpp): done, waiting for the next frame, or failed with a message.
#include <string>
#include <utility>

#include "app/app_state.h"
#include "app/harness.h"
#include "app/script.h"

namespace vox::app {

enum class Step { kDone, kWait, kFail };

struct Context {
  AppState& state;
  Harness& h;
  const ScriptCommand& cmd;
  std::string error;  // set with kFail

  Step fail(std::string message) {
    error = std::move(message);
    return Step::kFail;
  }
};

// Waits until no background work runs, then `frames` more frames so that its results are drawn.
Step waitSettled(Context& c, int frames);

// press WIDGET, or (typing) type TEXT WIDGET: the input over the next frames, then the work it started.
Step runPress(Context& c, bool typing);
// click WIDGET FX FY: a press at a point of the widget (script.h).
Step runClick(Context& c);
// press-all: every widget on screen pressed one after another (script.h).
Step runPressAll(Context& c);

}  // namespace vox::app
