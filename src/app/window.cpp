#include "app/window.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <vector>

#include "vox/render/gl.h"  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace vox::app {
namespace {

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
  // ImGui keeps the pointer; the string outlives the context (runGui's frame).
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

}  // namespace

Result<GLFWwindow*> openWindow(AppState& state, int width, int height, bool vsync, const std::string& ini_path) {
  glfwSetErrorCallback(glfwErrorCallback);
  if (!glfwInit()) {
    return makeError(ErrorCode::kNoOpenGL, "cannot open a window: " + g_glfw_error +
                                               "\nUse a subcommand to work without one (voxmod --help).");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(width, height, "voxmod", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    return makeError(ErrorCode::kNoOpenGL, "cannot create an OpenGL 3.3 window: " + g_glfw_error);
  }
  state.window = window;
  glfwSetWindowUserPointer(window, &state);
  glfwMakeContextCurrent(window);
  glfwSwapInterval(vsync ? 1 : 0);
  setUpImGui(window, ini_path);
  return window;
}

void closeWindow(GLFWwindow* window) {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
}

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

}  // namespace vox::app
