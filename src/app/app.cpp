// The modeler window: GLFW (X11/GLX) window with an OpenGL 3.3 core context, Dear ImGui for the panels, and the
// render module's point renderer for the 3D view (shared notes headless-gl.md, section 3a).
#include "vox/app/app.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "vox/render/gl.h"  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "app/app_state.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/script.h"
#include "app/script_runner.h"
#include "app/viewport.h"
#include "vox/io/image_io.h"

namespace vox::app {
namespace {

constexpr const char* kUsage =
    "usage: voxmod [FILE] [--script SCRIPT] [--screenshot PNG] [--size WIDTHxHEIGHT]\n"
    "Opens the modeler window. FILE is a mesh (.stl) or voxel file (.vxm, .binvox); without one the bundled part\n"
    "models/featuretype.stl is opened and voxelized.\n"
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

std::string g_glfw_error;  // GLFW reports errors through a C callback without a user pointer
void glfwErrorCallback(int code, const char* description) {
  char buf[32];
  std::snprintf(buf, sizeof buf, " (GLFW error 0x%x)", code);
  g_glfw_error = std::string(description) + buf;
}

AppState& stateOf(GLFWwindow* w) { return *static_cast<AppState*>(glfwGetWindowUserPointer(w)); }
// Any input: draw a few frames so ImGui can settle (hover states, popups opening) before sleeping again.
void wake(GLFWwindow* w) { stateOf(w).redraw_frames = std::max(stateOf(w).redraw_frames, 3); }

void installCallbacks(GLFWwindow* window) {
  // Installed before ImGui's GLFW backend, which chains to them.
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { wake(w); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { wake(w); });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_PRESS) stateOf(w).key_presses.emplace_back(key, mods);
    wake(w);
  });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int) { wake(w); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { wake(w); });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { wake(w); });
  // Not used by ImGui 1.86's backend (it polls the cursor), so set directly.
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { wake(w); });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { wake(w); });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { wake(w); });
  glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
    AppState& s = stateOf(w);
    for (int i = 0; i < count; ++i) s.dropped_files.emplace_back(paths[i]);
    wake(w);
  });
}

void setUpImGui(GLFWwindow* window, const std::string& ini_path) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // ImGui keeps the pointer; the string lives in main's frame until DestroyContext.
  io.IniFilename = ini_path.empty() ? nullptr : ini_path.c_str();
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // fonts-dejavu-core, when installed
  std::error_code ec;
  if (std::filesystem::is_regular_file(font, ec)) io.Fonts->AddFontFromFileTTF(font, 15.0f);
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.FrameRounding = 3.0f;
  style.GrabRounding = 3.0f;
  style.GrabMinSize = 14.0f;
  style.ItemSpacing = ImVec2(8.0f, 6.0f);
  // Dialogs over a busy point rendering read better opaque.
  style.Colors[ImGuiCol_PopupBg].w = 1.0f;
  style.Colors[ImGuiCol_WindowBg].w = 1.0f;
  installCallbacks(window);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

// The window's back buffer after ImGui has drawn, as the user sees it.
ImageRgba readWindow(GLFWwindow* window) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window, &w, &h);
  ImageRgba img(w, h);
  std::vector<Rgba8> rows(size_t(w) * size_t(h));
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  for (int y = 0; y < h; ++y) {  // GL rows run bottom-up
    std::copy_n(rows.begin() + ptrdiff_t(size_t(h - 1 - y) * size_t(w)), w,
                img.pixels.begin() + ptrdiff_t(size_t(y) * size_t(w)));
  }
  for (Rgba8& p : img.pixels) p.a = 255;  // the window's alpha channel is not meaningful
  return img;
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

bool anyWork(const AppState& s) {
  return modelBusy(s) || s.depth.busy() || s.surface_stats.busy() || s.mass.busy() || s.xray_result.busy();
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
  // A script (a test, a benchmark, the documentation's screenshots) starts from the defaults and leaves the user's
  // settings alone, so its result does not depend on who ran the window last.
  const std::filesystem::path config = options.script.empty() ? configDirectory() : std::filesystem::path();
  std::string imgui_ini;
  if (!config.empty()) {
    state.settings_path = config / "voxmod.ini";
    state.settings = loadSettings(state.settings_path);
    std::error_code ec;
    std::filesystem::create_directories(config, ec);
    if (!ec) imgui_ini = (config / "imgui.ini").string();
  }
  applySettings(state);
  if (!options.script.empty()) {
    auto script = loadScript(options.script);
    if (!script) {
      std::fprintf(stderr, "voxmod: %s\n", script.error().message.c_str());
      return 1;
    }
    state.script.emplace();
    state.script->commands = std::move(script).value();
  }
  state.screenshot_on_idle = options.screenshot;

  glfwSetErrorCallback(glfwErrorCallback);
  if (!glfwInit()) {
    std::fprintf(stderr, "voxmod: cannot open a window: %s\nUse a subcommand to work without one (voxmod --help).\n",
                 g_glfw_error.c_str());
    return 3;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  const int width = options.width > 0 ? options.width : state.settings.window_width;
  const int height = options.height > 0 ? options.height : state.settings.window_height;
  GLFWwindow* window = glfwCreateWindow(width, height, "voxmod", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr, "voxmod: cannot create an OpenGL 3.3 window: %s\n", g_glfw_error.c_str());
    glfwTerminate();
    return 3;
  }
  state.window = window;
  glfwSetWindowUserPointer(window, &state);
  glfwMakeContextCurrent(window);
  // A script measures frame times, so it must not wait for vertical sync.
  glfwSwapInterval(state.script ? 0 : 1);

  setUpImGui(window, imgui_ini);
  if (Status s = initViewport(state); !s) {
    std::fprintf(stderr, "voxmod: %s\n", s.error().message.c_str());
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 3;
  }

  if (!options.file.empty()) {
    startOpen(state, options.file);
  } else if (!state.script) {
    if (const std::filesystem::path bundled = bundledModel(); !bundled.empty()) {
      state.voxelize_after_load = true;
      startOpen(state, bundled);
    }
  }

  double last = nowSeconds();
  std::string title;
  int idle_frames = 0;
  while (!state.quit_requested) {
    // Draw continuously only while something moves; while a worker computes, refresh its progress 20 times a
    // second and leave the CPU to it (llvmpipe draws on the same cores); otherwise sleep until an event.
    const bool moving = state.section.playing || state.redraw_frames > 0 || state.viewport.interacting ||
                        (state.script && state.script->sweeping);
    const bool working =
        anyWork(state) || (state.script && !state.script->sweeping) || !state.screenshot_on_idle.empty();
    const bool animate = moving || working;
    if (moving || (working && !anyWork(state))) {
      glfwPollEvents();
    } else if (working) {
      glfwWaitEventsTimeout(0.05);
    } else {
      glfwWaitEventsTimeout(0.5);
    }
    if (glfwWindowShouldClose(window)) {
      glfwSetWindowShouldClose(window, GLFW_FALSE);  // the unsaved-changes prompt decides
      if (state.script) {
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

    updateDocument(state);
    state.viewport.interacting = false;  // set again this frame by drags, a playing section or a script sweep
    if (!modelBusy(state) || (state.script && state.script->started)) stepScript(state);
    if (state.quit_requested) break;

    const double t_build = nowSeconds();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    drawFrame(state);
    state.key_presses.clear();
    ImGui::Render();
    const double t_draw = nowSeconds();
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window, &fb_w, &fb_h);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb_w, fb_h);
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    const bool timing = state.script && state.script->sweeping;
    // The section benchmark splits each frame into phases; llvmpipe rasterizes when the work is flushed, so wait
    // for it there (only then: glFinish would slow every frame of an interactive session for nothing).
    if (timing) glFinish();
    const double t_swap = nowSeconds();

    if (state.script && !state.script->screenshot_path.empty()) {
      writeScreenshot(state, window, state.script->screenshot_path);
      state.script->screenshot_path.clear();
    }
    if (!state.screenshot_on_idle.empty()) {
      // Everything loaded and computed, and a few frames drawn since, so the panels show the final numbers.
      idle_frames = (settled(state) && (state.doc.model || state.doc.path.empty())) ? idle_frames + 1 : 0;
      if (idle_frames >= 3) {
        if (!writeScreenshot(state, window, state.screenshot_on_idle)) state.exit_code = 2;
        state.quit_requested = true;
      }
    }
    glfwSwapBuffers(window);
    if (state.release_memory) {
      // A document was closed (another opened): its grids, depth map and point buffers are gone by now, after this
      // frame drew the new one. Hand the freed heap back to the system, or the process keeps gigabytes it no
      // longer uses (glibc keeps freed memory for reuse).
      state.release_memory = false;
#if defined(__GLIBC__)
      malloc_trim(0);
#endif
    }
    if (timing) {
      const double t_end = nowSeconds();
      state.frame_phase_ms[0] = (t_draw - t_build) * 1000.0;
      state.frame_phase_ms[1] = (t_swap - t_draw) * 1000.0;
      state.frame_phase_ms[2] = (t_end - t_swap) * 1000.0;
    }

    if (const std::string t = windowTitle(state); t != title) {
      glfwSetWindowTitle(window, t.c_str());
      title = t;
    }
    const double now = nowSeconds();
    state.frame_time_s = now - last;
    last = now;
    if (animate && state.frame_time_s > 0.0) state.fps = 0.9 * state.fps + 0.1 / state.frame_time_s;
    ++state.frame;
    state.redraw_frames = std::max(0, state.redraw_frames - 1);
  }

  if (!state.settings_path.empty()) {
    int w = 0, h = 0;
    glfwGetWindowSize(window, &w, &h);
    if (options.width == 0 && w > 0 && h > 0) {  // a --size for a test run is not the user's choice
      state.settings.window_width = w;
      state.settings.window_height = h;
    }
    rememberSettings(state);
    if (Status s = saveSettings(state.settings, state.settings_path); !s) {
      std::fprintf(stderr, "voxmod: settings not saved: %s\n", s.error().message.c_str());
    }
  }
  cancelJobs(state);
  shutdownViewport(state);
  state.section_texture.reset();
  state.xray_texture.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return state.exit_code;
}

}  // namespace vox::app
