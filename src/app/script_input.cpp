// The harness's presses and typing (script.h: press, type, press-all): ImGui is given the mouse and keys for the
// widget a test names, through the harness's synthetic input (harness.h, fed each frame by feedSyntheticInput).
#include <algorithm>
#include <cstdio>
#include <string>

#include "app/script_runner.h"
#include "app/script_step.h"
#include "vox/core/text.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace vox::app {
namespace {

// The occurrence-th widget of that name drawn last frame (0: the first); null when it is not on screen.
const WidgetRect* findWidget(const Harness& h, const std::string& name, int occurrence = 0) {
  for (const WidgetRect& w : h.widget_rects) {
    if (w.name == name && occurrence-- == 0) return &w;
  }
  return nullptr;
}

// Starts a press (or, with `typing`, a click and typing `text`) at the middle of a widget.
void startInput(Harness& h, const WidgetRect& w, bool typing, const std::string& text) {
  h.input = SyntheticInput{};
  h.input.active = true;
  h.input.x = 0.5f * (w.x0 + w.x1);
  h.input.y = 0.5f * (w.y0 + w.y1);
  h.input.typing = typing;
  h.input.text = text;
}

}  // namespace

// press WIDGET / type TEXT WIDGET: the input over the next frames, then the work it started.
Step runPress(Context& c, bool typing) {
  Harness& h = c.h;
  if (!h.started) {
    const std::string name =
        typing ? c.cmd.rest.substr(std::min(c.cmd.rest.size(), c.cmd.args[0].size() + 1)) : c.cmd.rest;
    const WidgetRect* w = findWidget(h, name);
    if (!w) return c.fail("no widget '" + name + "' on screen");
    startInput(h, *w, typing, typing ? c.cmd.args[0] : std::string());
    return Step::kWait;
  }
  if (h.input.active) return Step::kWait;
  if (Step w = waitSettled(c, 1); w != Step::kDone) return w;
  return h.failed ? Step::kFail : Step::kDone;
}

// click WIDGET FX FY: a press at fractions FX, FY of the widget's width and height (a point of a picture).
Step runClick(Context& c) {
  Harness& h = c.h;
  if (!h.started) {
    const auto& args = c.cmd.args;
    float fx = 0.0f, fy = 0.0f;
    if (args.size() != 3 || !parseNumber(args[1], fx) || !parseNumber(args[2], fy)) {
      return c.fail("click takes WIDGET FX FY: a widget and fractions of its width and height");
    }
    const WidgetRect* w = findWidget(h, args[0]);
    if (!w) return c.fail("no widget '" + args[0] + "' on screen");
    startInput(h, *w, false, std::string());
    h.input.x = w->x0 + (w->x1 - w->x0) * fx;
    h.input.y = w->y0 + (w->y1 - w->y0) * fy;
    return Step::kWait;
  }
  return runPress(c, false);  // the press under way, then the work it started
}

// press-all: one widget after another; what a press raises (an error message, a dialog, a file browser) is closed
// before the next, so that each press reaches its widget.
Step runPressAll(Context& c) {
  Harness& h = c.h;
  PressAll& p = h.press_all;
  AppState& s = c.state;
  if (!h.started) {
    p = PressAll{};
    return Step::kWait;
  }
  if (!p.collected) {  // the widgets once the panel asked for before has been drawn and its work is done
    if (Step w = waitSettled(c, 2); w != Step::kDone) return w;
    p.collected = true;
    for (const WidgetRect& w : h.widget_rects) {
      if (w.kind == "mark") continue;  // a panel's own name for a widget recorded under its label too
      int occurrence = 0;
      for (const PressAll::Target& t : p.targets) occurrence += t.name == w.name ? 1 : 0;
      p.targets.push_back({w.name, w.kind, occurrence});
    }
  }
  // Errors are what a press may well raise (a field given a value out of range): counted, not a failure.
  if (s.errors.reported != h.errors_seen) {
    p.errors += s.errors.reported - h.errors_seen;
    h.errors_seen = s.errors.reported;
    std::printf("press-all: error shown: %s\n", s.errors.last_reported.c_str());
  }
  if (h.input.active) return Step::kWait;
  if (p.pressing) {
    if (Step w = waitSettled(c, 1); w != Step::kDone) return w;
    p.pressing = false;
    s.errors.messages.clear();
    s.close_dialogs = true;
    return Step::kWait;  // a frame for the dialogs to close
  }
  while (p.next < p.targets.size()) {
    const PressAll::Target& t = p.targets[p.next++];
    const WidgetRect* w = findWidget(h, t.name, t.occurrence);
    if (!w) {
      ++p.missing;
      continue;
    }
    std::printf("press-all: %s (%s)\n", t.name.c_str(), t.kind.c_str());
    std::fflush(stdout);
    startInput(h, *w, t.kind == "field", "2");
    p.pressing = true;
    ++p.pressed;
    return Step::kWait;
  }
  std::printf("press-all: pressed %d widgets (%d no longer on screen), %lld error messages shown\n", p.pressed,
              p.missing, static_cast<long long>(p.errors));
  std::fflush(stdout);
  return Step::kDone;
}

// The harness's press or typing (harness.h), one step this frame, in place of what the mouse and keyboard gave.
void feedSyntheticInput(Harness* h) {
  if (!h || !h->input.active) return;
  SyntheticInput& in = h->input;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(in.x, in.y);
  io.MouseDown[0] = in.phase == 1;
  io.KeyCtrl = in.phase == 3;
  io.KeysDown[GLFW_KEY_A] = in.phase == 3;
  if (in.phase == 4) io.AddInputCharactersUTF8(in.text.c_str());
  io.KeysDown[GLFW_KEY_ENTER] = in.phase == 5;
  if (++in.phase >= in.steps()) in.active = false;
}

}  // namespace vox::app
