#pragma once
// Headless OpenGL: an EGL context with no window and no X server (docs/dependencies.md, "Headless OpenGL"). The GUI
// makes its own GLFW window context instead and uses the same PointRenderer and Framebuffer; this class is only for
// the CLI, tests and benchmarks.
#include <memory>
#include <string>

#include "vox/core/result.h"

namespace vox::render {

struct HeadlessInfo {
  std::string platform;  // "surfaceless" (EGL_PLATFORM_SURFACELESS_MESA) or "device" (EGL_PLATFORM_DEVICE_EXT)
  std::string vendor, renderer, version;  // GL_VENDOR, GL_RENDERER, GL_VERSION of the context
};

// An OpenGL 3.3 core context (Mesa returns 4.5 core for the request) without a default framebuffer: draw into a
// Framebuffer. Tries eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA), then the first EGL device
// (EGL_PLATFORM_DEVICE_EXT). The context is current on the creating thread after create(); it is released and
// destroyed by the destructor, so GL objects made in it must be destroyed first.
//
// For deterministic images (tests), pin Mesa's software rasteriser before create(): GALLIUM_DRIVER=llvmpipe,
// LIBGL_ALWAYS_SOFTWARE=1. Output is then identical for any LP_NUM_THREADS.
class HeadlessContext {
 public:
  // Fails with ErrorCode::kNoOpenGL, with a message naming each platform tried and why it failed, when EGL or a
  // 3.3 core context is not available.
  static Result<std::unique_ptr<HeadlessContext>> create();

  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  // Makes the context current on the calling thread (it is after create()).
  Status makeCurrent();
  const HeadlessInfo& info() const { return info_; }

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  HeadlessInfo info_;
};

}  // namespace vox::render
