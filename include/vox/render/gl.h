#pragma once
// The one place the renderer (and the GUI) include OpenGL from. Core-profile prototypes from <GL/glcorearb.h>,
// resolved at link time against glvnd's libOpenGL (CMake OpenGL::OpenGL): no loader and no init call, and the same
// entry points dispatch to whichever context is current, GLX (a GLFW window) or EGL (headless). Switching to a
// portable loader such as libepoxy would be a change to this file only (see docs/dependencies.md, "Headless OpenGL").
// Include GLFW with GLFW_INCLUDE_NONE after this header.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>  // IWYU pragma: export
