#include "app/script_runner.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>
#include <system_error>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/actions.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/view_export.h"
#include "vox/io/file_util.h"
#include "vox/core/text.h"

namespace vox::app {
namespace {

constexpr double kJobTimeoutS = 600.0;  // a worker that runs longer than this fails the script

enum class Step { kDone, kWait, kFail };

struct Context {
  AppState& state;
  ScriptRun& run;
  const ScriptCommand& cmd;
  std::string error;  // set with kFail

  Step fail(std::string message) {
    error = std::move(message);
    return Step::kFail;
  }
};

bool parseOnOff(const std::string& s, bool& out) {
  if (s == "on" || s == "1" || s == "true") return out = true, true;
  if (s == "off" || s == "0" || s == "false") return out = false, true;
  return false;
}

std::optional<Panel> parsePanel(const std::string& s) {
  for (Panel p : {Panel::kModel, Panel::kSection, Panel::kSkin, Panel::kXray, Panel::kMass}) {
    if (s == panelName(p)) return p;
  }
  return std::nullopt;
}

void showPanel(AppState& state, Panel p) {
  state.panel = p;
  state.panel_change_requested = true;
}

// First call starts; later calls wait until the model workers are idle. Fails when the script's error count rose.
Step waitForModel(Context& c) {
  if (modelBusy(c.state)) {
    if (nowSeconds() > c.run.deadline) return c.fail("timed out waiting for '" + c.cmd.name + "'");
    return Step::kWait;
  }
  return c.run.failed ? Step::kFail : Step::kDone;
}

// Waits until no background work runs, then `frames` more frames so that its results are drawn.
Step waitSettled(Context& c, int frames) {
  ScriptRun& r = c.run;
  if (!settled(c.state)) {
    r.settle_countdown = -1;
    if (nowSeconds() > r.deadline) return c.fail("timed out waiting for background work");
    return Step::kWait;
  }
  if (r.settle_countdown < 0) r.settle_countdown = frames;
  if (r.settle_countdown > 0) {
    --r.settle_countdown;
    return Step::kWait;
  }
  return Step::kDone;
}

Step runSweep(Context& c) {
  AppState& s = c.state;
  ScriptRun& r = c.run;
  const int32_t n = axisLength(s, s.section.axis);
  if (!r.sweeping) {
    if (n <= 0) return c.fail("sweep needs a model");
    auto axis = parseAxis(c.cmd.args[0]);
    if (!axis) return c.fail("unknown axis '" + c.cmd.args[0] + "' (x, y or z)");
    if (c.cmd.args.size() > 1 && (!parseNumber(c.cmd.args[1], r.sweep_step) || r.sweep_step < 1)) {
      return c.fail("sweep step must be a positive integer");
    }
    s.section.axis = *axis;
    s.section.index = 0;
    showPanel(s, Panel::kSection);
    r.sweeping = true;
    r.sweep_frame_ms.clear();
    r.sweep_last = 0.0;
    r.sweep_view_ms = 0.0;
    for (double& p : r.sweep_phase_ms) p = 0.0;
    return Step::kWait;
  }
  // One section per frame, timed from frame start to frame start (the whole frame: section, 3D view, UI, swap).
  const double now = nowSeconds();
  if (r.sweep_last > 0.0) {
    r.sweep_frame_ms.push_back((now - r.sweep_last) * 1000.0);
    r.sweep_view_ms += s.viewport.draw_ms;  // the 3D part of that frame (point rendering into the framebuffer)
    for (int i = 0; i < 3; ++i) r.sweep_phase_ms[i] += s.frame_phase_ms[i];
  }
  r.sweep_last = now;
  s.viewport.interacting = true;  // what a slider drag does: coarse points while it moves
  const int32_t next = r.sweep_frame_ms.empty() && s.section.index == 0 ? 0 : s.section.index + r.sweep_step;
  if (!r.sweep_frame_ms.empty() && next >= n) {
    r.sweeping = false;
    std::vector<double> ms = r.sweep_frame_ms;
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
        mean, ms[ms.size() / 2], 1000.0 / mean, r.sweep_phase_ms[0] / frames, r.sweep_view_ms / frames,
        r.sweep_phase_ms[1] / frames, r.sweep_phase_ms[2] / frames);
    std::fflush(stdout);
    return Step::kDone;
  }
  s.section.index = std::min(next, n - 1);
  return Step::kWait;
}

Step execute(Context& c) {
  AppState& s = c.state;
  ScriptRun& r = c.run;
  const std::string& name = c.cmd.name;
  const auto& args = c.cmd.args;
  const bool first = !r.started;
  if (first) r.deadline = nowSeconds() + kJobTimeoutS;

  if (name == "echo") {
    std::printf("%s\n", c.cmd.rest.c_str());
    std::fflush(stdout);
    return Step::kDone;
  }
  if (name == "open") {
    if (first) startOpen(s, c.cmd.rest);
    return waitForModel(c);
  }
  if (name == "voxelize") {
    if (first) {
      VoxelizeParams p = s.voxelize.params;
      if (!parseNumber(args[0], p.resolution) || p.resolution < 1) {
        return c.fail("resolution must be a positive integer, found '" + args[0] + "'");
      }
      p.voxel_size = 0.0;
      if (args.size() > 1) {
        auto mode = parseFillMode(args[1]);
        if (!mode) return c.fail("unknown mode '" + args[1] + "' (auto, parity, nonzero or vote)");
        p.mode = *mode;
      }
      if (!s.doc.mesh) return c.fail("voxelize needs an open mesh");
      s.voxelize.params = p;
      startVoxelize(s, p);
    }
    return waitForModel(c);
  }
  if (name == "section") {
    if (args[0] == "off") {
      s.view.cut_away = false;
      return Step::kDone;
    }
    auto axis = parseAxis(args[0]);
    int32_t index = 0;
    if (!axis) return c.fail("unknown axis '" + args[0] + "' (x, y, z or off)");
    if (args.size() < 2 || !parseNumber(args[1], index)) return c.fail("section needs an integer index");
    if (s.model.empty()) return c.fail("section needs a model");
    const int32_t n = axisLength(s, *axis);
    if (index < 0 || index >= n) {
      return c.fail("section index " + std::to_string(index) + " is outside 0.." + std::to_string(n - 1));
    }
    s.section.axis = *axis;
    s.section.index = index;
    s.view.cut_away = true;
    showPanel(s, Panel::kSection);
    return Step::kDone;
  }
  if (name == "sweep") return runSweep(c);
  if (name == "peel") {
    if (first) {
      if (!s.doc.model) return c.fail("peel needs a model");
      const int32_t cur = s.doc.model->peeled;
      int32_t n = 0;
      showPanel(s, Panel::kSkin);
      if (args[0] == "core") {
        peelTo(s, std::numeric_limits<int32_t>::max());
      } else if (args[0] == "back") {
        peelTo(s, cur - 1);
      } else if (args[0] == "reset") {
        peelTo(s, 0);
      } else if (parseNumber(args[0], n) && n >= 0) {
        peelTo(s, cur + n);
      } else {
        return c.fail("peel takes a layer count, core, back or reset; found '" + args[0] + "'");
      }
    }
    if (s.skin.pending_peel) return nowSeconds() > r.deadline ? c.fail("timed out computing skin layers") : Step::kWait;
    return r.failed ? Step::kFail : Step::kDone;
  }
  if (name == "xray") {
    if (first) {
      auto axis = parseAxis(args[0]);
      auto mode = parseXrayMode(args[1]);
      if (!axis) return c.fail("unknown axis '" + args[0] + "'");
      if (!mode) return c.fail("unknown X-ray mode '" + args[1] + "' (min, max or total)");
      if (s.model.empty()) return c.fail("xray needs a model");
      s.xray.params = XrayParams{*axis, *mode};
      showPanel(s, Panel::kXray);
    }
    const XrayKey key{s.model_version, s.xray.params.axis, s.xray.params.mode};
    if (const Error* e = s.xray_result.error(key)) return c.fail("X-ray failed: " + e->message);
    if (!s.xray_result.get(key))
      return nowSeconds() > r.deadline ? c.fail("timed out computing the X-ray") : Step::kWait;
    return Step::kDone;
  }
  if (name == "panel") {
    auto p = parsePanel(args[0]);
    if (!p) return c.fail("unknown panel '" + args[0] + "' (model, section, skin, xray, mass)");
    showPanel(s, *p);
    return Step::kDone;
  }
  if (name == "view") {
    double yaw = 0.0, pitch = 0.0;
    if (args.size() == 2) {
      if (!parseNumber(args[0], yaw) || !parseNumber(args[1], pitch)) return c.fail("view YAW PITCH takes degrees");
      s.view.camera.yaw_deg = yaw;
      s.view.camera.pitch_deg = std::clamp(pitch, -90.0, 90.0);
    } else {
      static const std::pair<const char*, render::StandardView> kViews[] = {
          {"iso", render::StandardView::kIso}, {"+x", render::StandardView::kPosX}, {"-x", render::StandardView::kNegX},
          {"+y", render::StandardView::kPosY}, {"-y", render::StandardView::kNegY}, {"+z", render::StandardView::kPosZ},
          {"-z", render::StandardView::kNegZ}};
      auto it = std::find_if(std::begin(kViews), std::end(kViews), [&](const auto& v) { return args[0] == v.first; });
      if (it == std::end(kViews)) return c.fail("unknown view '" + args[0] + "' (iso, +x, -x, +y, -y, +z, -z)");
      s.view.camera.setStandardView(it->second);
    }
    s.view.fit_pending = true;
    return Step::kDone;
  }
  if (name == "measure") {  // measure I J K picks a voxel as a click would; measure clear
    if (args.size() == 1 && args[0] == "clear") {
      clearMeasure(s);
      return Step::kDone;
    }
    double v[3];
    if (args.size() != 3 || !parseNumber(args[0], v[0]) || !parseNumber(args[1], v[1]) || !parseNumber(args[2], v[2]))
      return c.fail("measure takes I J K (a voxel index) or 'clear'");
    const glm::ivec3 voxel{int(v[0]), int(v[1]), int(v[2])};
    if (!s.model.inBounds(voxel.x, voxel.y, voxel.z)) return c.fail("measure: voxel outside the model's grid");
    addMeasurePick(s, voxel);
    return Step::kDone;
  }
  if (name == "zoom") {
    double f = 0.0;
    if (!parseNumber(args[0], f) || !(f > 0.0)) return c.fail("zoom takes a positive factor");
    s.view.camera.zoom(f);
    return Step::kDone;
  }
  if (name == "lit" || name == "round" || name == "disputed" || name == "cut" || name == "lod") {
    bool on = false;
    if (!parseOnOff(args[0], on)) return c.fail("'" + name + "' takes on or off");
    (name == "lit"        ? s.view.lit
     : name == "round"    ? s.view.round_points
     : name == "disputed" ? s.view.show_disputed
     : name == "lod"      ? s.view.lod
                          : s.view.cut_away) = on;
    return Step::kDone;
  }
  if (name == "undo" || name == "redo") {
    if (name == "undo" ? !canUndo(s) : !canRedo(s)) return c.fail("nothing to " + name);
    name == "undo" ? undo(s) : redo(s);
    return Step::kDone;
  }
  if (name == "save") return saveModel(s, c.cmd.rest) ? Step::kDone : Step::kFail;
  if (name == "export-view" || name == "export-section" || name == "export-xray" || name == "export-csv") {
    if (Step w = waitSettled(c, 1); w != Step::kDone) return w;  // export what the window shows
    // The path the file browser's Save takes, so a script exports exactly as a user does.
    const BrowserPurpose purpose = name == "export-view"      ? BrowserPurpose::kExportViewPng
                                   : name == "export-section" ? BrowserPurpose::kExportSectionPng
                                   : name == "export-xray"    ? BrowserPurpose::kExportXrayPng
                                                              : BrowserPurpose::kExportXrayCsv;
    return acceptBrowserPath(s, purpose, c.cmd.rest) ? Step::kDone : Step::kFail;
  }
  if (name == "export-size") {  // export-size W H: the 3D view's export size (0 0: as shown)
    double w = 0, h = 0;
    if (!parseNumber(args[0], w) || !parseNumber(args[1], h) || w < 0 || h < 0 || w > 8192 || h > 8192)
      return c.fail("export-size takes a width and a height in pixels, 0 to 8192");
    s.export_width = int32_t(w);
    s.export_height = int32_t(h);
    return Step::kDone;
  }
  if (name == "screenshot") {
    if (!r.screenshot_requested) {
      if (Step w = waitSettled(c, 2); w != Step::kDone) return w;
      r.screenshot_path = c.cmd.rest;  // app.cpp writes it after this frame is drawn, then clears the path
      r.screenshot_requested = true;
      return Step::kWait;
    }
    if (!r.screenshot_path.empty()) return Step::kWait;
    r.screenshot_requested = false;
    return r.failed ? Step::kFail : Step::kDone;
  }
  if (name == "state") {
    if (Step w = waitSettled(c, 0); w != Step::kDone) return w;  // counts that are still being computed
    if (Status st = io::writeFileAtomic(c.cmd.rest, describeState(s)); !st) return c.fail(st.error().message);
    return Step::kDone;
  }
  if (name == "wait") {
    int n = 0;
    const std::string& count = args[0] == "frames" && args.size() > 1 ? args[1] : args[0];  // "wait frames N"
    if (!parseNumber(count, n) || n < 0) return c.fail("wait takes a frame count");
    if (first) r.wait_frames = n;
    if (r.wait_frames > 0) {
      --r.wait_frames;
      return Step::kWait;
    }
    return Step::kDone;
  }
  if (name == "wait-file") {
    double timeout = 60.0;
    if (args.size() > 1 && (!parseNumber(args[1], timeout) || timeout <= 0.0)) return c.fail("bad time-out");
    if (first) r.deadline = nowSeconds() + timeout;
    std::error_code ec;
    if (std::filesystem::exists(args[0], ec)) return Step::kDone;
    if (nowSeconds() > r.deadline) return c.fail("timed out waiting for " + args[0]);
    return Step::kWait;
  }
  if (name == "hover") {
    // Moves the real pointer (glfwSetCursorPos warps the X pointer) to a point of a widget drawn last frame, given
    // as fractions of its width and height, so hover read-outs and tooltips can be shown without a mouse.
    float fx = 0.5f, fy = 0.5f;
    if (args.size() > 1 && !parseNumber(args[1], fx)) return c.fail("hover fractions must be numbers");
    if (args.size() > 2 && !parseNumber(args[2], fy)) return c.fail("hover fractions must be numbers");
    auto it = std::find_if(s.widget_rects.begin(), s.widget_rects.end(),
                           [&](const WidgetRect& w) { return w.name == args[0]; });
    if (it == s.widget_rects.end()) return c.fail("no widget '" + args[0] + "' on screen");
    glfwSetCursorPos(s.window, double(it->x0 + (it->x1 - it->x0) * fx), double(it->y0 + (it->y1 - it->y0) * fy));
    return Step::kDone;
  }
  if (name == "dialog") {
    if (args[0] == "voxelize") {
      if (!s.doc.mesh) return c.fail("the voxelize dialog needs an open mesh");
      s.voxelize.open_requested = true;
    } else if (args[0] == "open") {
      openBrowser(s, BrowserPurpose::kOpen);
    } else if (args[0] == "save") {
      openBrowser(s, BrowserPurpose::kSaveModel);
    } else if (args[0] == "about") {
      s.show_about = true;
    } else if (args[0] == "controls") {
      dispatch(s, ActionId::kControls);
    } else if (args[0] == "close") {
      s.close_dialogs = true;
    } else {
      return c.fail("dialog takes voxelize, open, save, about, controls or close");
    }
    return Step::kDone;
  }
  if (name == "expect-error") {
    r.expect_error = c.cmd.rest;
    return Step::kDone;
  }
  if (name == "quit") {
    s.quit_requested = true;
    return Step::kDone;
  }
  return c.fail("unknown command '" + name + "'");
}

}  // namespace

bool settled(const AppState& s) {
  return !modelBusy(s) && !s.depth.busy() && !s.surface_stats.busy() && !s.mass.busy() && !s.xray_result.busy() &&
         !s.skin.pending_peel;
}

void stepScript(AppState& state) {
  if (!state.script) return;
  ScriptRun& run = *state.script;
  while (run.next < run.commands.size() && !state.quit_requested) {
    const ScriptCommand& cmd = run.commands[run.next];
    Context c{state, run, cmd, {}};
    const Step step = execute(c);
    if (step == Step::kWait) {
      run.started = true;
      return;
    }
    run.started = false;
    run.wait_frames = 0;
    run.settle_countdown = -1;
    if (!run.expect_error.empty() && cmd.name != "expect-error") {
      // The command before was expect-error: this one has to fail, with that text in its message. The error
      // dialog stays up, as it would for a person.
      const std::string message = !c.error.empty() ? c.error : run.last_error;
      const bool failed_as_expected =
          (step == Step::kFail || run.failed) && message.find(run.expect_error) != std::string::npos;
      if (!failed_as_expected) {
        std::fprintf(stderr, "voxmod: script line %d (%s): expected an error containing '%s', %s\n", cmd.line,
                     cmd.name.c_str(), run.expect_error.c_str(),
                     message.empty() ? "but it succeeded" : ("got: " + message).c_str());
        run.failed = true;
        state.exit_code = 1;
        state.quit_requested = true;
        return;
      }
      std::printf("expected error: %s\n", message.c_str());
      run.expect_error.clear();
      run.failed = false;
      run.last_error.clear();
      ++run.next;
      continue;
    }
    if (step == Step::kFail || run.failed) {
      std::fprintf(stderr, "voxmod: script line %d (%s): %s\n", cmd.line, cmd.name.c_str(),
                   c.error.empty() ? "failed (see the message above)" : c.error.c_str());
      run.failed = true;
      state.exit_code = 1;
      state.quit_requested = true;
      return;
    }
    ++run.next;
  }
  if (run.next >= run.commands.size() && !state.quit_requested) {
    // The script ran out without 'quit': keep the window open for a person to look at.
    state.script.reset();
  }
}

std::string describeState(const AppState& s) {
  std::ostringstream out;
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
  }
  if (const SurfaceStats* st = s.surface_stats.get(s.model_version)) {
    out << "filled = " << st->filled << "\n";
    out << "surface_voxels = " << st->surface_voxels << "\n";
  }
  out << "section_axis = " << axisName(s.section.axis) << "\n";
  out << "section_index = " << s.section.index << "\n";
  out << "section_length = " << axisLength(s, s.section.axis) << "\n";
  if (s.section_result && s.section_key.model_version == s.model_version) {
    out << "section_filled = " << s.section_result->filled << "\n";
  }
  out << "peeled = " << (s.doc.model ? s.doc.model->peeled : 0) << "\n";
  if (const DepthMap* d = currentDepthMap(s)) out << "layers = " << d->layers() << "\n";
  out << "xray_axis = " << axisName(s.xray.params.axis) << "\n";
  out << "xray_mode = " << xrayModeName(s.xray.params.mode) << "\n";
  out << "view_yaw = " << s.view.camera.yaw_deg << "\n";
  out << "view_pitch = " << s.view.camera.pitch_deg << "\n";
  out << "viewport = " << s.viewport.x << " " << s.viewport.y << " " << s.viewport.width << " " << s.viewport.height
      << "\n";
  out << "view_points = " << s.viewport.stats.points_drawn << "\n";
  out << "view_lod = " << s.viewport.stats.lod_level << "\n";
  out << "errors = " << s.errors.messages.size() << "\n";
  out << "unsaved_prompt = " << (s.after_unsaved_prompt ? 1 : 0) << "\n";
  for (const WidgetRect& w : s.widget_rects) {
    out << "rect_" << w.name << " = " << w.x0 << " " << w.y0 << " " << w.x1 << " " << w.y1 << "\n";
  }
  return out.str();
}

}  // namespace vox::app
