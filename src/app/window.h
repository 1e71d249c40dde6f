#pragma once
// The window itself: GLFW (X11/GLX) with an OpenGL 3.3 core context, its input callbacks feeding AppState, and
// Dear ImGui on top (docs/dependencies.md: GLFW under Xvfb for the window tests). GL and GLFW live here, in
// viewport.cpp, texture.cpp and app.cpp only.
#include <string>

#include "app/app_state.h"
#include "vox/core/image.h"
#include "vox/core/result.h"

struct GLFWwindow;

namespace vox::app {

// Creates the window for `state` (its user pointer, its callbacks) with ImGui set up; `ini_path` empty: ImGui
// remembers no layout. Without vsync, frames are not held to the display (a script times them). The error names
// why no window could be had.
Result<GLFWwindow*> openWindow(AppState& state, int width, int height, bool vsync, const std::string& ini_path);
// Shuts ImGui down and destroys the window.
void closeWindow(GLFWwindow* window);
// The window's back buffer after ImGui has drawn, as the user sees it.
ImageRgba readWindow(GLFWwindow* window);

}  // namespace vox::app
