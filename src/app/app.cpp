// The modeler window's entry point and frame loop: options, the user's settings, the window (window.cpp), the
// harness when a script or a screenshot asks for one (harness.h), and one frame after another until quit.
#include "vox/app/app.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <memory>
#include <cstdio>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <system_error>

#include "vox/render/gl.h"  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ErrorCheckEndFrameRecover: a frame whose drawing threw still ends

#include "app/actions.h"
#include "app/app_state.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/script.h"
#include "app/script_runner.h"
#include "app/ui.h"
#include "app/window.h"
#include "app/viewport.h"
#include "vox/io/image_io.h"

namespace vox::app {
namespace {

constexpr const char* kUsage =
    "usage: voxmod [FILE] [--script SCRIPT] [--screenshot PNG] [--size WIDTHxHEIGHT]\n"
    "Opens the modeler window. FILE is a mesh or CAD file (.stl .obj .ply .3mf .gltf .glb .off .step .stp .iges\n"
    ".igs) or a voxel file (.vxm, .binvox); without one the bundled part models/featuretype.stl is opened and\n"
    "voxelized.\n"
    "  --script SCRIPT    run the line commands in SCRIPT (see src/app/script.h), e.g. for tests\n"
    "  --screenshot PNG   when everything has been computed, save the window as PNG and quit\n"
    "  --size WxH         window size in pixels (default: the size it had last time)\n"
    "Subcommands work without a window: voxmod --help\n";

struct Options {
  std::string file;
  std::string script;
  std::string screenshot;
  int width = 0, height = 0;
};

enum class Parsed { kRun, kHelp, kUsageError };

// On a usage error, prints why.
Parsed parseOptions(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "voxmod: %s needs a value\n%s", a.c_str(), kUsage);
        return false;
      }
      out = argv[++i];
      return true;
    };
    if (a == "--script") {
      if (!value(o.script)) return Parsed::kUsageError;
    } else if (a == "--screenshot") {
      if (!value(o.screenshot)) return Parsed::kUsageError;
    } else if (a == "--size") {
      std::string s;
      if (!value(s)) return Parsed::kUsageError;
      if (std::sscanf(s.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 320 || o.height < 240 ||
          o.width > 16384 || o.height > 16384) {
        std::fprintf(stderr, "voxmod: --size wants WIDTHxHEIGHT (at least 320x240), found '%s'\n", s.c_str());
        return Parsed::kUsageError;
      }
    } else if (a == "-h" || a == "--help") {
      return Parsed::kHelp;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "voxmod: unknown option '%s'\n%s", a.c_str(), kUsage);
      return Parsed::kUsageError;
    } else if (o.file.empty()) {
      o.file = a;
    } else {
      std::fprintf(stderr, "voxmod: only one FILE can be opened, found '%s' and '%s'\n", o.file.c_str(), a.c_str());
      return Parsed::kUsageError;
    }
  }
  return Parsed::kRun;
}

// The bundled part: beside the installed executable (<exe dir>/../models or <exe dir>/models), else in the source
// tree this binary was built from (__FILE__ is the absolute path CMake compiled).
std::filesystem::path bundledModel() {
  std::error_code ec;
  std::vector<std::filesystem::path> candidates;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(exe.parent_path() / ".." / "models" / "featuretype.stl");
    candidates.push_back(exe.parent_path() / "models" / "featuretype.stl");
  }
  candidates.push_back(std::filesystem::path(__FILE__).parent_path() / ".." / ".." / "models" / "featuretype.stl");
  for (const auto& c : candidates) {
    if (std::filesystem::is_regular_file(c, ec)) return c.lexically_normal();
  }
  return {};
}

bool anyWork(const AppState& s) {
  return modelBusy(s) || s.depth.busy() || s.surface_stats.busy() || s.mass.busy() || s.xray_result.busy() ||
         s.thickness.busy() || s.rays.busy() || s.thin_walls.busy() || s.print.busy() || s.casting.busy();
}

bool writeScreenshot(AppState& state, GLFWwindow* window, const std::string& path) {
  if (Status s = io::savePng(readWindow(window), path); !s) {
    reportError(state, s.error().message, path);
    return false;
  }
  std::printf("screenshot %s\n", path.c_str());
  std::fflush(stdout);
  return true;
}

// The harness, when a script or a screenshot asks for one; null for a person's session.
std::unique_ptr<Harness> makeHarness(const Options& options, AppState& state, int& exit_code) {
  if (options.script.empty() && options.screenshot.empty()) return nullptr;
  auto h = std::make_unique<Harness>();
  if (!options.script.empty()) {
    auto script = loadScript(options.script);
    if (!script) {
      std::fprintf(stderr, "voxmod: %s\n", script.error().message.c_str());
      exit_code = 1;
      return nullptr;
    }
    h->commands = std::move(script).value();
    h->scripted = true;
    state.voxelize_dialog_on_open = false;  // a script voxelizes itself
  }
  h->screenshot_on_idle = options.screenshot;
  if (!options.screenshot.empty()) state.voxelize_after_load = true;
  setWidgetRecorder([raw = h.get()](const std::string& label, const char* kind, ImVec2 a, ImVec2 b) {
    std::string name = label;
    if (const size_t hidden = name.find("##"); hidden != std::string::npos) name.replace(hidden, 2, "@");
    raw->widget_rects.push_back({std::move(name), kind, a.x, a.y, b.x, b.y});
  });
  return h;
}

// Draw continuously only while something moves; while a worker computes, refresh its progress 20 times a second and
// leave the CPU to it (llvmpipe draws on the same cores); otherwise sleep until an event. Returns whether this frame
// animates (counts for the frame rate).
bool waitForFrame(const AppState& state, const Harness* h) {
  const bool sweeping = h && h->sweep.running;
  const bool moving = state.section.playing || state.redraw_frames > 0 || state.viewport.interacting || sweeping;
  const bool working =
      anyWork(state) || (h && h->scriptRunning() && !sweeping) || (h && !h->screenshot_on_idle.empty());
  if (moving || (working && !anyWork(state))) {
    glfwPollEvents();
  } else if (working) {
    glfwWaitEventsTimeout(0.05);
  } else {
    glfwWaitEventsTimeout(0.5);
  }
  return moving || working;
}

// Closing the window (the unsaved-changes prompt decides, except while a script runs) and files dropped on it.
void handleWindowEvents(AppState& state, const Harness* h) {
  if (glfwWindowShouldClose(state.window)) {
    glfwSetWindowShouldClose(state.window, GLFW_FALSE);
    if (h && h->scriptRunning()) {
      state.quit_requested = true;
    } else {
      requestQuit(state);
    }
  }
  if (!state.dropped_files.empty()) {
    const std::string first = state.dropped_files.front();
    state.dropped_files.clear();
    requestOpen(state, first);
  }
}

// A frame whose drawing threw: ImGui's windows and stacks are closed so the frame can end, the actions its widgets
// gave are dropped (they were given against a picture that was not finished) and the error is shown. The document
// is untouched: drawing only reads it, and actions wait until the frame is built.
void recoverFrame(AppState& state, const std::exception& e) {
  ImGui::ErrorCheckEndFrameRecover(nullptr);
  state.deferred_actions.clear();
  const bool memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
  reportError(state, memory ? std::string("Drawing the window needed more memory than this machine can give")
                            : std::string("Drawing the window failed: ") + e.what());
}

// The document's update between frames (finished background work taken in, the autosave): an exception there is
// shown, not fatal.
void updateDocumentGuarded(AppState& state) {
  try {
    updateDocument(state);
    updateAutosave(state);
  } catch (const std::bad_alloc&) {
    reportError(state, "Taking in finished work needed more memory than this machine can give");
  } catch (const std::exception& e) {
    reportError(state, std::string("Taking in finished work failed: ") + e.what());
  }
}

// Builds the UI and draws it into the back buffer; returns the times the phases started (build, draw, swap).
std::array<double, 3> drawUi(AppState& state, bool finish, Harness* h) {
  std::array<double, 3> t{nowSeconds(), 0.0, 0.0};
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  feedSyntheticInput(h);
  ImGui::NewFrame();
  state.building_frame = true;  // actions the widgets give wait until the frame is built (actions.h)
  try {
    drawFrame(state);
  } catch (const std::exception& e) {
    recoverFrame(state, e);
  }
  state.building_frame = false;
  state.key_presses.clear();
  ImGui::Render();
  if (h) h->clipped_text = findClippedText(*ImGui::GetDrawData());
  t[1] = nowSeconds();
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(state.window, &fb_w, &fb_h);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb_w, fb_h);
  glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  // The section benchmark splits each frame into phases; llvmpipe rasterizes when the work is flushed, so wait for
  // it there (only then: glFinish would slow every frame of an interactive session for nothing).
  if (finish) glFinish();
  t[2] = nowSeconds();
  return t;
}

// After the frame is drawn, before it is shown: the screenshots a script or --screenshot asked for.
void takeScreenshots(Harness& h, AppState& state) {
  if (!h.screenshot_path.empty()) {
    writeScreenshot(state, state.window, h.screenshot_path);
    h.screenshot_path.clear();
  }
  if (!h.screenshot_on_idle.empty()) {
    // Everything loaded and computed, and a few frames drawn since, so the panels show the final numbers.
    h.idle_frames = (settled(state) && (state.doc.model || state.doc.path.empty())) ? h.idle_frames + 1 : 0;
    if (h.idle_frames >= 3) {
      if (!writeScreenshot(state, state.window, h.screenshot_on_idle)) h.exit_code = 2;
      state.quit_requested = true;
    }
  }
}

// A document was closed (another opened): its grids, depth map and point buffers are gone by now, after this frame
// drew the new one. Hand the freed heap back to the system, or the process keeps gigabytes it no longer uses
// (glibc keeps freed memory for reuse).
void releaseMemory(AppState& state) {
  if (!state.release_memory) return;
  state.release_memory = false;
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

// One frame: events, the document's update, the script's step, the UI, the screenshots, the swap.
void runFrame(AppState& state, Harness* h, double& last, std::string& title) {
  const bool animate = waitForFrame(state, h);
  handleWindowEvents(state, h);
  updateDocumentGuarded(state);
  state.viewport.interacting = false;  // set again this frame by drags, a playing section or a script sweep
  if (h && (!modelBusy(state) || h->started)) stepScript(*h, state);
  if (state.quit_requested) return;
  const bool timing = h && h->sweep.running;
  if (h) h->widget_rects.clear();  // drawn again this frame; a script's `state` reads the last frame's
  const std::array<double, 3> t = drawUi(state, timing, h);
  if (h) takeScreenshots(*h, state);
  glfwSwapBuffers(state.window);
  runDeferredActions(state);
  releaseMemory(state);
  const double now = nowSeconds();
  if (timing) {
    h->frame_phase_ms[0] = (t[1] - t[0]) * 1000.0;
    h->frame_phase_ms[1] = (t[2] - t[1]) * 1000.0;
    h->frame_phase_ms[2] = (now - t[2]) * 1000.0;
  }
  if (const std::string wt = windowTitle(state); wt != title) {
    glfwSetWindowTitle(state.window, wt.c_str());
    title = wt;
  }
  state.frame_time_s = now - last;
  last = now;
  if (animate && state.frame_time_s > 0.0) state.fps = 0.9 * state.fps + 0.1 / state.frame_time_s;
  ++state.frame;
  state.redraw_frames = std::max(0, state.redraw_frames - 1);
}

void saveWindowSettings(AppState& state, const Options& options) {
  if (state.settings_path.empty()) return;
  int w = 0, h = 0;
  glfwGetWindowSize(state.window, &w, &h);
  if (options.width == 0 && w > 0 && h > 0) {  // a --size for a test run is not the user's choice
    state.settings.window_width = w;
    state.settings.window_height = h;
  }
  rememberSettings(state);
  if (Status s = saveSettings(state.settings, state.settings_path); !s) {
    std::fprintf(stderr, "voxmod: settings not saved: %s\n", s.error().message.c_str());
  }
}

// A script (a test, a benchmark, the documentation's screenshots) starts from the defaults and leaves the user's
// settings alone, so its result does not depend on who ran the window last. Returns ImGui's layout file.
std::string loadUserSettings(AppState& state, const Options& options) {
  std::string imgui_ini;
  const std::filesystem::path config = options.script.empty() ? configDirectory() : std::filesystem::path();
  if (!config.empty()) {
    state.settings_path = config / "voxmod.ini";
    state.settings = loadSettings(state.settings_path);
    std::error_code ec;
    std::filesystem::create_directories(config, ec);
    if (!ec) imgui_ini = (config / "imgui.ini").string();
  }
  applySettings(state);
  return imgui_ini;
}

}  // namespace

int runGui(int argc, char** argv) {
  Options options;
  switch (parseOptions(argc, argv, options)) {
    case Parsed::kRun:
      break;
    case Parsed::kHelp:
      std::fputs(kUsage, stdout);
      return 0;
    case Parsed::kUsageError:
      return 1;
  }

  AppState state;
  const std::string imgui_ini = loadUserSettings(state, options);
  initAutosave(state, !options.script.empty() || !options.screenshot.empty());
  int exit_code = 0;
  std::unique_ptr<Harness> harness = makeHarness(options, state, exit_code);
  if (exit_code != 0) return exit_code;

  const int width = options.width > 0 ? options.width : state.settings.window_width;
  const int height = options.height > 0 ? options.height : state.settings.window_height;
  // A script measures frame times, so it must not wait for vertical sync.
  auto window = openWindow(state, width, height, !(harness && harness->scripted), imgui_ini);
  if (!window) {
    std::fprintf(stderr, "voxmod: %s\n", window.error().message.c_str());
    return 3;
  }
  if (Status s = initViewport(state); !s) {
    std::fprintf(stderr, "voxmod: %s\n", s.error().message.c_str());
    closeWindow(*window);
    return 3;
  }

  if (!options.file.empty()) {
    startOpen(state, options.file);
  } else if (!(harness && harness->scripted)) {
    if (const std::filesystem::path bundled = bundledModel(); !bundled.empty()) {
      state.voxelize_after_load = true;
      startOpen(state, bundled);
    }
  }

  double last = nowSeconds();
  std::string title;
  while (!state.quit_requested) runFrame(state, harness.get(), last, title);

  saveWindowSettings(state, options);
  if (!state.autosave.keep_on_exit) finishAutosave(state);
  cancelJobs(state);
  shutdownViewport(state);
  state.section_texture.reset();
  state.oblique_texture.reset();
  state.xray_texture.reset();
  setWidgetRecorder(nullptr);
  closeWindow(*window);
  return harness ? harness->exit_code : 0;
}

}  // namespace vox::app
