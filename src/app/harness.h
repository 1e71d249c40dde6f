#pragma once
// The test and documentation harness, beside the window's state and absent when a person runs the window: a
// --script run (script.h), --screenshot on idle, where widgets were drawn (for a driver that clicks them) and the
// frame phases a section sweep times. It drives the application only through the action table (actions.h): every
// script line is an action, dispatched as a menu item is, or one of the harness's own commands, which wait, look,
// write what the window shows or end the run, and change nothing a user edits.
#include <cstdint>
#include <string>
#include <vector>

#include "app/clipped_text.h"
#include "app/script.h"

namespace vox::app {

// Where a widget a test driver needs was drawn (window pixels), e.g. "section_slider".
// A widget's name is its label, with ImGui's hidden "##id" part written "@id" ("Cancel@clearance", "@colour"), or a
// name a panel gives (markWidget: "section_slider"); its kind is markWidget's ("button", "field", "mark", ...).
struct WidgetRect {
  std::string name;
  std::string kind;
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// A press or typing that the harness gives ImGui in place of the mouse and keyboard, one step a frame
// (script_input.cpp, feedSyntheticInput): the pointer over (x, y), the button down, up (the click); when typing, then
// Ctrl+A (select all), the text, and Enter.
struct SyntheticInput {
  bool active = false;
  float x = 0, y = 0;
  bool typing = false;
  std::string text;
  int phase = 0;  // steps given so far
  int steps() const { return typing ? 7 : 3; }
};

// press-all: every widget on screen when it started, pressed one after another (fields typed into), each found again
// by name and occurrence before it is pressed.
struct PressAll {
  struct Target {
    std::string name, kind;
    int occurrence = 0;  // among the widgets of the same name, in drawing order
  };
  std::vector<Target> targets;
  size_t next = 0;
  bool collected = false;  // the targets were taken from the widgets on screen
  bool pressing = false;   // the current target was pressed; its work is awaited
  int pressed = 0, missing = 0;
  int64_t errors = 0;  // error dialogs raised (and closed) on the way
};

// A section sweep (the slider benchmark): the section moves one step per frame, as a slider drag does.
struct Sweep {
  bool running = false;
  int32_t step = 1;
  std::vector<double> frame_ms;
  double view_ms = 0.0;
  double phase_ms[3] = {0.0, 0.0, 0.0};
  double last = 0.0;
};

struct Harness {
  // --script: the commands and where the run stands.
  std::vector<ScriptCommand> commands;
  bool scripted = false;  // a script was given (it may have ended: the window then stays open for a person)
  size_t next = 0;
  bool started = false;  // the current command did its first step and is waiting
  int wait_frames = 0;
  double deadline = 0.0;        // wait-file / background-work time-out (seconds, steady clock)
  int settle_countdown = -1;    // frames still to draw once background work has finished
  std::string screenshot_path;  // written (and cleared) by the frame loop after this frame is drawn
  bool screenshot_requested = false;
  bool failed = false;
  int64_t errors_seen = 0;   // error dialogs raised so far (ErrorQueue::reported) that the run has accounted for
  std::string last_error;    // the last error reported while the script ran
  std::string expect_error;  // expect-error: the next command must fail with a message containing this
  Sweep sweep;

  // --screenshot PATH: written once everything has settled, then the window closes.
  std::string screenshot_on_idle;
  int idle_frames = 0;

  std::vector<WidgetRect> widget_rects;   // refilled every frame
  std::vector<ClippedText> clipped_text;  // text the last frame cut off (clipped_text.h)
  SyntheticInput input;
  PressAll press_all;
  // While sweeping: milliseconds of the last frame spent building the UI (including the section and the 3D view's
  // draw calls), rasterizing (3D points and UI, up to glFinish) and swapping buffers.
  double frame_phase_ms[3] = {0.0, 0.0, 0.0};
  int exit_code = 0;

  bool scriptRunning() const { return scripted && next < commands.size(); }
};

}  // namespace vox::app
