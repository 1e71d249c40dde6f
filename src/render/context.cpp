// Headless EGL context (docs/dependencies.md, "Headless OpenGL"): EGL_PLATFORM_SURFACELESS_MESA needs no X
// server, no /dev/dri and no environment variable; the EGL device platform is the fallback (it is also what a
// non-Mesa driver such as NVIDIA's offers). eglGetDisplay(EGL_DEFAULT_DISPLAY) is not used: without DISPLAY, Mesa's
// default platform (x11) fails in eglInitialize.
#include "vox/render/context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "vox/render/gl.h"

namespace vox::render {
namespace {

std::string eglErrorName(EGLint e) {
  switch (e) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      break;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "EGL error 0x%04X", unsigned(e));
  return buf;
}

// EGL displays are per process and shared: eglTerminate on one would kill every context on it. Count the live
// HeadlessContexts per display and terminate with the last one.
std::mutex g_display_mutex;
// Never destroyed: a context held by a static object (a benchmark's scene) is released after this file's function
// statics would have gone, at exit.
std::map<EGLDisplay, int>& displayUsers() {
  static auto* users = new std::map<EGLDisplay, int>;
  return *users;
}

bool hasExtension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string s = std::string(" ") + list + " ";
  return s.find(" " + name + " ") != std::string::npos;
}

// Initialises `dpy` and creates a 3.3 core context on it. Returns the context or EGL_NO_CONTEXT with `why` set.
EGLContext initAndCreate(EGLDisplay dpy, std::string& why) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) {
    why = "eglInitialize failed (" + eglErrorName(eglGetError()) + ")";
    return EGL_NO_CONTEXT;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "eglBindAPI(EGL_OPENGL_API) failed (" + eglErrorName(eglGetError()) + ")";
    return EGL_NO_CONTEXT;
  }
  // No surface is ever made (surfaceless), but a config with 8-bit RGBA and depth keeps drivers that want one happy.
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE,
                                   EGL_PBUFFER_BIT,
                                   EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_BIT,
                                   EGL_RED_SIZE,
                                   8,
                                   EGL_GREEN_SIZE,
                                   8,
                                   EGL_BLUE_SIZE,
                                   8,
                                   EGL_ALPHA_SIZE,
                                   8,
                                   EGL_DEPTH_SIZE,
                                   24,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n_configs = 0;
  if (!eglChooseConfig(dpy, config_attribs, &config, 1, &n_configs) || n_configs < 1) {
    config = nullptr;  // EGL_KHR_no_config_context: contexts without a config are fine for FBO-only rendering
  }
  const EGLint context_attribs[] = {
      EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, context_attribs);
  if (ctx == EGL_NO_CONTEXT) {
    why = "eglCreateContext(OpenGL 3.3 core) failed (" + eglErrorName(eglGetError()) + ")";
    return EGL_NO_CONTEXT;
  }
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    why = "eglMakeCurrent without a surface failed (" + eglErrorName(eglGetError()) + ")";
    eglDestroyContext(dpy, ctx);
    return EGL_NO_CONTEXT;
  }
  return ctx;
}

void releaseDisplay(EGLDisplay dpy) {
  std::lock_guard lock(g_display_mutex);
  auto& users = displayUsers();
  if (--users[dpy] <= 0) {
    users.erase(dpy);
    eglTerminate(dpy);
  }
}

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create() {
  std::vector<std::string> failures;
  struct Candidate {
    std::string platform;
    EGLDisplay display;
  };
  std::vector<Candidate> candidates;

  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (hasExtension(client_ext, "EGL_MESA_platform_surfaceless")) {
    candidates.push_back(
        {"surfaceless", eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)});
  } else {
    failures.push_back("surfaceless: EGL_MESA_platform_surfaceless not offered (not Mesa's EGL?)");
  }
  if (hasExtension(client_ext, "EGL_EXT_platform_device")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLDeviceEXT devices[8];
    EGLint n_devices = 0;
    if (query_devices && query_devices(8, devices, &n_devices) && n_devices > 0) {
      candidates.push_back({"device", eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr)});
    } else {
      failures.push_back("device: no EGL devices");
    }
  } else {
    failures.push_back("device: EGL_EXT_platform_device not offered");
  }

  for (const Candidate& c : candidates) {
    if (c.display == EGL_NO_DISPLAY) {
      failures.push_back(c.platform + ": eglGetPlatformDisplay failed (" + eglErrorName(eglGetError()) + ")");
      continue;
    }
    std::lock_guard lock(g_display_mutex);
    std::string why;
    EGLContext ctx = initAndCreate(c.display, why);
    if (ctx == EGL_NO_CONTEXT) {
      failures.push_back(c.platform + ": " + why);
      if (displayUsers().count(c.display) == 0) eglTerminate(c.display);
      continue;
    }
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 33) {
      failures.push_back(c.platform + ": got OpenGL " + glString(GL_VERSION) + ", need 3.3 core");
      eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(c.display, ctx);
      if (displayUsers().count(c.display) == 0) eglTerminate(c.display);
      continue;
    }
    ++displayUsers()[c.display];
    std::unique_ptr<HeadlessContext> hc(new HeadlessContext());
    hc->display_ = c.display;
    hc->context_ = ctx;
    hc->info_ = {c.platform, glString(GL_VENDOR), glString(GL_RENDERER), glString(GL_VERSION)};
    return hc;
  }

  std::string message = "no usable OpenGL 3.3 core context (headless EGL):";
  for (const auto& f : failures) message += "\n  " + f;
  message += "\n  (needs libegl1, libegl-mesa0 and libgl1-mesa-dri on Debian; EGL_LOG_LEVEL=debug shows more)";
  return makeError(ErrorCode::kNoOpenGL, message);
}

HeadlessContext::~HeadlessContext() {
  if (!display_) return;
  auto dpy = static_cast<EGLDisplay>(display_);
  if (eglGetCurrentContext() == static_cast<EGLContext>(context_)) {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  eglDestroyContext(dpy, static_cast<EGLContext>(context_));
  releaseDisplay(dpy);
}

Status HeadlessContext::makeCurrent() {
  if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                      static_cast<EGLContext>(context_))) {
    return makeError(ErrorCode::kNoOpenGL, "eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")");
  }
  return Ok{};
}

}  // namespace vox::render
