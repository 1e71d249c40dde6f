// Offscreen framebuffer and read-back (docs/dependencies.md, "Headless OpenGL": a surfaceless context has no default
// framebuffer, and glReadPixels rows come bottom-up).
#include "vox/render/framebuffer.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "vox/render/gl.h"

namespace vox::render {

Framebuffer::~Framebuffer() { release(); }

Framebuffer::Framebuffer(Framebuffer&& other) noexcept { *this = std::move(other); }

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  if (this != &other) {
    release();
    fbo_ = std::exchange(other.fbo_, 0);
    colour_ = std::exchange(other.colour_, 0);
    depth_ = std::exchange(other.depth_, 0);
    width_ = std::exchange(other.width_, 0);
    height_ = std::exchange(other.height_, 0);
  }
  return *this;
}

void Framebuffer::release() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (colour_) glDeleteTextures(1, &colour_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  fbo_ = colour_ = depth_ = 0;
  width_ = height_ = 0;
}

Status Framebuffer::resize(int32_t width, int32_t height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384) {
    return makeError(ErrorCode::kInvalidArgument, "framebuffer size " + std::to_string(width) + "x" +
                                                      std::to_string(height) + " is outside 1..16384");
  }
  if (fbo_ && width == width_ && height == height_) return Ok{};
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width > max_size || height > max_size) {
    return makeError(ErrorCode::kLimit, "framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                                            " exceeds the driver's limit of " + std::to_string(max_size));
  }
  release();
  glGenFramebuffers(1, &fbo_);
  glGenTextures(1, &colour_);
  glGenRenderbuffers(1, &depth_);
  glBindTexture(GL_TEXTURE_2D, colour_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", unsigned(status));
    return makeError(ErrorCode::kNoOpenGL, std::string("offscreen framebuffer incomplete (status ") + code + ")");
  }
  width_ = width;
  height_ = height;
  return Ok{};
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

void Framebuffer::clear(Rgba8 background) const {
  bind();
  glClearColor(float(background.r) / 255.0f, float(background.g) / 255.0f, float(background.b) / 255.0f,
               float(background.a) / 255.0f);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

ImageRgba Framebuffer::readPixels() const {
  ImageRgba image(width_, height_);
  if (!fbo_) return image;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<Rgba8> rows(size_t(width_) * size_t(height_));
  static_assert(sizeof(Rgba8) == 4, "Rgba8 must be 4 packed bytes for glReadPixels");
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // GL's row 0 is the bottom one; ImageRgba's is the top.
  for (int32_t y = 0; y < height_; ++y) {
    std::copy_n(rows.begin() + std::ptrdiff_t(size_t(height_ - 1 - y) * size_t(width_)), width_,
                image.pixels.begin() + std::ptrdiff_t(size_t(y) * size_t(width_)));
  }
  return image;
}

}  // namespace vox::render
