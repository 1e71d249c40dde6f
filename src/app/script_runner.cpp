#include "app/casting.h"
#include "app/print.h"
#include "app/script_runner.h"
#include "app/script_step.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <system_error>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/actions.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/parts.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"

namespace vox::app {

// Waits until no background work runs, then `frames` more frames so that its results are drawn.
Step waitSettled(Context& c, int frames) {
  Harness& h = c.h;
  if (!settled(c.state)) {
    h.settle_countdown = -1;
    if (nowSeconds() > h.deadline) return c.fail("timed out waiting for background work");
    return Step::kWait;
  }
  if (h.settle_countdown < 0) h.settle_countdown = frames;
  if (h.settle_countdown > 0) {
    --h.settle_countdown;
    return Step::kWait;
  }
  return Step::kDone;
}

namespace {

constexpr double kJobTimeoutS = 600.0;  // background work that runs longer than this fails the script

ActionArgs argsOf(const ScriptCommand& cmd) { return ActionArgs{cmd.args, cmd.rest}; }

// An action: dispatched as its menu item is; then, from the next frame on, wait for the work it started.
Step runAction(Context& c, const Action& a) {
  if (!c.h.started) {
    if (Status s = dispatch(c.state, a, argsOf(c.cmd)); !s) return c.fail(s.error().message);
    return Step::kWait;
  }
  if (Step w = waitSettled(c, 0); w != Step::kDone) return w;
  return c.h.failed ? Step::kFail : Step::kDone;
}

void printSweep(const AppState& s, const Sweep& w) {
  std::vector<double> ms = w.frame_ms;
  std::sort(ms.begin(), ms.end());
  double total = 0.0;
  for (double v : ms) total += v;
  const double mean = total / double(ms.size());
  const int64_t surface = s.viewport.renderer ? s.viewport.renderer->cloud().size() : 0;
  const double frames = double(ms.size());
  std::printf(
      "sweep %s: %zu frames, %d x %d x %d voxels, %s surface points (drew %s at level %d), lod %s: "
      "mean %.1f ms, median %.1f ms, %.1f fps; per frame: UI + section + 3D draw calls %.1f ms (3D calls %.1f), "
      "rasterize %.1f ms, swap %.1f ms\n",
      axisName(s.section.axis), ms.size(), s.model.nx(), s.model.ny(), s.model.nz(), std::to_string(surface).c_str(),
      std::to_string(s.viewport.stats.points_drawn).c_str(), s.viewport.stats.lod_level, s.view.lod ? "on" : "off",
      mean, ms[ms.size() / 2], 1000.0 / mean, w.phase_ms[0] / frames, w.view_ms / frames, w.phase_ms[1] / frames,
      w.phase_ms[2] / frames);
  std::fflush(stdout);
}

// sweep AXIS [STEP]: the section action once per frame through every STEP-th index, timed from frame start to frame
// start (the whole frame: section, 3D view, UI, swap).
Step runSweep(Context& c) {
  AppState& s = c.state;
  Sweep& w = c.h.sweep;
  const std::string& axis = c.cmd.args[0];
  if (!w.running) {
    auto a = parseAxis(axis);
    if (!a) return c.fail("unknown axis '" + axis + "' (x, y or z)");
    if (axisLength(s, *a) <= 0) return c.fail("sweep needs a model");
    w = Sweep{};
    if (c.cmd.args.size() > 1 && (!parseNumber(c.cmd.args[1], w.step) || w.step < 1)) {
      return c.fail("sweep step must be a positive integer");
    }
    w.running = true;
    if (Status st = dispatch(s, ActionId::kSectionAt, ActionArgs{{axis, "0"}, {}}); !st) {
      return c.fail(st.error().message);
    }
    return Step::kWait;
  }
  const double now = nowSeconds();
  if (w.last > 0.0) {
    w.frame_ms.push_back((now - w.last) * 1000.0);
    w.view_ms += s.viewport.draw_ms;  // the 3D part of that frame (point rendering into the framebuffer)
    for (int i = 0; i < 3; ++i) w.phase_ms[i] += c.h.frame_phase_ms[i];
  }
  w.last = now;
  s.viewport.interacting = true;  // what a slider drag does: coarse points while it moves
  const int32_t n = axisLength(s, s.section.axis);
  const int32_t next = w.frame_ms.empty() ? 0 : s.section.index + w.step;
  if (!w.frame_ms.empty() && next >= n) {
    w.running = false;
    printSweep(s, w);
    return Step::kDone;
  }
  const ActionArgs at{{axis, std::to_string(std::min(next, n - 1))}, {}};
  if (Status st = dispatch(s, ActionId::kSectionAt, at); !st) return c.fail(st.error().message);
  return Step::kWait;
}

Step runScreenshot(Context& c) {
  Harness& h = c.h;
  if (!h.screenshot_requested) {
    if (Step w = waitSettled(c, 2); w != Step::kDone) return w;
    h.screenshot_path = c.cmd.rest;  // the frame loop writes it after this frame is drawn, then clears the path
    h.screenshot_requested = true;
    return Step::kWait;
  }
  if (!h.screenshot_path.empty()) return Step::kWait;
  h.screenshot_requested = false;
  return h.failed ? Step::kFail : Step::kDone;
}

Step runWait(Context& c) {
  int n = 0;
  const auto& args = c.cmd.args;
  const std::string& count = args[0] == "frames" && args.size() > 1 ? args[1] : args[0];  // "wait frames N"
  if (!parseNumber(count, n) || n < 0) return c.fail("wait takes a frame count");
  if (!c.h.started) c.h.wait_frames = n;
  if (c.h.wait_frames > 0) {
    --c.h.wait_frames;
    return Step::kWait;
  }
  return Step::kDone;
}

Step runWaitFile(Context& c) {
  const auto& args = c.cmd.args;
  double timeout = 60.0;
  if (args.size() > 1 && (!parseNumber(args[1], timeout) || timeout <= 0.0)) return c.fail("bad time-out");
  if (!c.h.started) c.h.deadline = nowSeconds() + timeout;
  std::error_code ec;
  if (std::filesystem::exists(args[0], ec)) return Step::kDone;
  if (nowSeconds() > c.h.deadline) return c.fail("timed out waiting for " + args[0]);
  return Step::kWait;
}

// Moves the real pointer (glfwSetCursorPos warps the X pointer) to a point of a widget drawn last frame, given as
// fractions of its width and height, so hover read-outs and tooltips can be shown without a mouse.
Step runHover(Context& c) {
  const auto& args = c.cmd.args;
  float fx = 0.5f, fy = 0.5f;
  if (args.size() > 1 && !parseNumber(args[1], fx)) return c.fail("hover fractions must be numbers");
  if (args.size() > 2 && !parseNumber(args[2], fy)) return c.fail("hover fractions must be numbers");
  const auto& rects = c.h.widget_rects;
  auto it = std::find_if(rects.begin(), rects.end(), [&](const WidgetRect& w) { return w.name == args[0]; });
  if (it == rects.end()) return c.fail("no widget '" + args[0] + "' on screen");
  glfwSetCursorPos(c.state.window, double(it->x0 + (it->x1 - it->x0) * fx), double(it->y0 + (it->y1 - it->y0) * fy));
  return Step::kDone;
}

// The harness's own commands (script.h lists them); anything else is an action.
Step runHarnessCommand(Context& c) {
  const std::string& name = c.cmd.name;
  if (name == "echo") {
    std::printf("%s\n", c.cmd.rest.c_str());
    std::fflush(stdout);
    return Step::kDone;
  }
  if (name == "sweep") return runSweep(c);
  if (name == "screenshot") return runScreenshot(c);
  if (name == "state") {
    if (Step w = waitSettled(c, 0); w != Step::kDone) return w;  // counts that are still being computed
    if (Status st = io::writeFileAtomic(c.cmd.rest, describeState(c.state, c.h)); !st) {
      return c.fail(st.error().message);
    }
    return Step::kDone;
  }
  if (name == "wait") return runWait(c);
  if (name == "wait-file") return runWaitFile(c);
  if (name == "hover") return runHover(c);
  if (name == "press") return runPress(c, false);
  if (name == "click") return runClick(c);
  if (name == "type") return runPress(c, true);
  if (name == "press-all") return runPressAll(c);
  if (name == "expect-error") {
    c.h.expect_error = c.cmd.rest;
    return Step::kDone;
  }
  if (name == "exit") {  // ends the run and closes the window, as killing it would: nothing is asked or saved
    c.state.quit_requested = true;
    c.state.autosave.keep_on_exit = true;
    return Step::kDone;
  }
  return c.fail("unknown command '" + name + "'");
}

Step execute(Context& c) {
  if (!c.h.started) c.h.deadline = nowSeconds() + kJobTimeoutS;
  if (const Action* a = findAction(c.cmd.name)) return runAction(c, *a);
  return runHarnessCommand(c);
}

// Error dialogs raised since the last look: the run has failed (unless an error was expected), and says why.
void takeErrors(Harness& h, const AppState& state) {
  if (state.errors.reported == h.errors_seen) return;
  h.errors_seen = state.errors.reported;
  h.failed = true;
  h.last_error = state.errors.last_reported;
  std::fprintf(stderr, "voxmod: %s\n", h.last_error.c_str());
}

void stopRun(Harness& h, AppState& state) {
  h.failed = true;
  h.exit_code = 1;
  state.quit_requested = true;
}

// After the command before was expect-error: this one had to fail, with that text in its message. The error dialog
// stays up, as it would for a person. Returns false when it did not.
bool checkExpectedError(Harness& h, const Context& c, Step step) {
  const std::string message = !c.error.empty() ? c.error : h.last_error;
  const bool failed_as_expected =
      (step == Step::kFail || h.failed) && message.find(h.expect_error) != std::string::npos;
  if (!failed_as_expected) {
    std::fprintf(stderr, "voxmod: script line %d (%s): expected an error containing '%s', %s\n", c.cmd.line,
                 c.cmd.name.c_str(), h.expect_error.c_str(),
                 message.empty() ? "but it succeeded" : ("got: " + message).c_str());
    return false;
  }
  std::printf("expected error: %s\n", message.c_str());
  h.expect_error.clear();
  h.failed = false;
  h.last_error.clear();
  return true;
}

}  // namespace

bool settled(const AppState& s) {
  return !modelBusy(s) && !s.depth.busy() && !s.surface_stats.busy() && !s.mass.busy() && !s.xray_result.busy() &&
         !s.thickness.busy() && !s.rays.busy() && !s.thin_walls.busy() && !s.print.busy() && !s.casting.busy() &&
         !s.skin.pending_peel && !s.volume_export_job.active() && !s.parts_job.active() &&
         !s.interference_job.active() && !s.clearance_job.active() && !autosaveBusy(s);
}

void stepScript(Harness& h, AppState& state) {
  while (h.scriptRunning() && !state.quit_requested) {
    const ScriptCommand& cmd = h.commands[h.next];
    Context c{state, h, cmd, {}};
    const Step step = execute(c);
    takeErrors(h, state);
    if (step == Step::kWait && !h.failed) {
      h.started = true;
      return;
    }
    h.started = false;
    h.wait_frames = 0;
    h.settle_countdown = -1;
    if (!h.expect_error.empty() && cmd.name != "expect-error") {
      if (!checkExpectedError(h, c, step)) return stopRun(h, state);
      ++h.next;
      continue;
    }
    if (step == Step::kFail || h.failed) {
      std::fprintf(stderr, "voxmod: script line %d (%s): %s\n", cmd.line, cmd.name.c_str(),
                   c.error.empty() ? "failed (see the message above)" : c.error.c_str());
      return stopRun(h, state);
    }
    ++h.next;
  }
}

std::string describeState(const AppState& s, const Harness& h) {
  std::ostringstream out;
  out << "pid = " << ::getpid() << "\n";
  out << "frame = " << s.frame << "\n";
  out << "fps = " << s.fps << "\n";
  out << "panel = " << panelName(s.panel) << "\n";
  out << "file = " << s.doc.path.string() << "\n";
  out << "has_model = " << (s.doc.model ? 1 : 0) << "\n";
  out << "model_version = " << s.model_version << "\n";
  out << "unsaved = " << (hasUnsavedChanges(s) ? 1 : 0) << "\n";
  out << "undo_depth = " << s.doc.undo_stack.size() << "\n";
  if (!s.model.empty()) {
    out << "dims = " << s.model.nx() << " " << s.model.ny() << " " << s.model.nz() << "\n";
    out << "voxel_size = " << s.model.voxelSize() << "\n";
    out << "units = " << s.model.frame().units << "\n";
  }
  if (const SurfaceStats* st = s.surface_stats.get(s.model_version)) {
    out << "filled = " << st->filled << "\n";
    out << "surface_voxels = " << st->surface_voxels << "\n";
  }
  out << "section_axis = " << axisName(s.section.axis) << "\n";
  out << "section_index = " << s.section.index << "\n";
  out << "section_length = " << axisLength(s, s.section.axis) << "\n";
  out << "section_zoom = " << s.section.zoom << "\n";
  out << "section_oblique = " << (s.section.oblique ? 1 : 0) << "\n";
  out << "section_normal = " << s.section.normal.x << " " << s.section.normal.y << " " << s.section.normal.z << "\n";
  out << "section_offset = " << s.section.offset << "\n";
  out << "cut_away = " << (s.view.cut_away ? 1 : 0) << "\n";
  out << "cut_points = " << s.viewport.stats.cut_points << "\n";
  out << "measure_picks =";
  for (const glm::ivec3& v : measurePicks(s)) out << " " << v.x << "," << v.y << "," << v.z;
  out << "\n";
  if (s.section_result && s.section_key.model_version == s.model_version) {
    out << "section_filled = " << s.section_result->filled << "\n";
  }
  out << "peeled = " << (s.doc.model ? s.doc.model->peeled : 0) << "\n";
  if (const DepthMap* d = currentDepthMap(s)) out << "layers = " << d->layers() << "\n";
  if (const ThicknessResult* t = currentThickness(s)) {
    out << "thickness_max = " << t->thickness.stats.max << "\n";
    out << "hot_spots = " << t->hot_spots.size() << "\n";
    if (!t->hot_spots.empty()) {
      const glm::ivec3 v = t->hot_spots[0].voxel;
      out << "hot_spot_1 = " << v.x << " " << v.y << " " << v.z << "\n";
    }
  }
  out << "casting_feeders = " << feederParts(s).size() << "\n";
  out << "casting_placing_feeder = " << s.casting_ui.placing_feeder << "\n";
  if (const CastingOutcome* c = currentCasting(s)) {
    out << "casting_solidification_s = " << c->run.result.solidification_s << "\n";
    out << "casting_sound = " << c->run.result.sound << "\n";
    out << "casting_hot_spots = " << c->run.result.hot_spots.size() << "\n";
    out << "casting_run_feeders = " << c->run.result.feeders.size() << "\n";
  }
  out << "print_direction = " << printDirectionName(s.print_ui.up) << "\n";
  out << "print_lay_face = " << s.print_ui.lay_face << "\n";
  if (const PrintResult* p = currentPrint(s)) {
    out << "print_overhang_area = " << p->check.support.overhang_area << "\n";
    out << "print_support_volume = " << p->check.support.support_volume << "\n";
    out << "print_cavities = " << p->check.cavities.size() << "\n";
    out << "print_orientations = " << p->check.orientations.size() << "\n";
  }
  if (const Assembly* parts = currentParts(s)) {
    out << "parts = " << parts->size() << "\n";
    out << "selected_parts =";
    for (size_t i : s.parts_ui.selected) out << " " << i + 1;
    out << "\n";
    if (!s.parts_ui.selected.empty() && s.parts_ui.selected.front() < parts->size()) {
      const Part& p = parts->part(s.parts_ui.selected.front());
      const glm::ivec3 t = p.placement.translation, q = p.placement.quarter_turns;
      out << "selected_part = " << p.name << "\n";
      out << "selected_translation = " << t.x << " " << t.y << " " << t.z << "\n";
      out << "selected_turns = " << q.x << " " << q.y << " " << q.z << "\n";
    }
  }
  out << "xray_axis = " << axisName(s.xray.params.axis) << "\n";
  out << "xray_mode = " << xrayModeName(s.xray.params.mode) << "\n";
  out << "view_yaw = " << s.view.camera.yaw_deg << "\n";
  out << "view_pitch = " << s.view.camera.pitch_deg << "\n";
  out << "view_projection = "
      << (s.view.camera.projection == render::Projection::kOrthographic ? "orthographic" : "perspective") << "\n";
  out << "viewport = " << s.viewport.x << " " << s.viewport.y << " " << s.viewport.width << " " << s.viewport.height
      << "\n";
  out << "view_points = " << s.viewport.stats.points_drawn << "\n";
  out << "view_lod = " << s.viewport.stats.lod_level << "\n";
  out << "errors = " << s.errors.messages.size() << "\n";
  out << "help_term = " << s.help.term << "\n";  // the term Help > Terms was last opened at
  out << "autosave_file = " << (s.autosave.file_written ? s.autosave.file.string() : std::string()) << "\n";
  out << "autosave_orphans = " << s.autosave.orphans.size() << "\n";
  out << "document = " << documentName(s) << "\n";
  out << "unsaved_prompt = " << (s.after_unsaved_prompt ? 1 : 0) << "\n";
  out << "clipped_text = " << h.clipped_text.size() << "\n";
  for (const ClippedText& c : h.clipped_text) {
    out << "clipped_in " << c.window << " = " << c.x0 << " " << c.y0 << " " << c.x1 << " " << c.y1 << "\n";
  }
  for (const WidgetRect& w : h.widget_rects) {
    out << "rect_" << w.name << " = " << w.x0 << " " << w.y0 << " " << w.x1 << " " << w.y1 << "\n";
  }
  return out.str();
}

}  // namespace vox::app
