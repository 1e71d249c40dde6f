#pragma once
// Offscreen render target: an RGBA8 colour texture (the GUI can show it with ImGui::Image) and a 24-bit depth
// renderbuffer. Needs a current GL 3.3 context; create, use and destroy it in that context.
#include <cstddef>  // vox/core/image.h uses size_t without including it
#include <cstdint>

#include "vox/core/image.h"
#include "vox/core/result.h"

namespace vox::render {

class Framebuffer {
 public:
  Framebuffer() = default;
  ~Framebuffer();
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // (Re)allocates storage for width x height pixels (1..16384 each). kInvalidArgument for other sizes, kNoOpenGL
  // when the driver reports the framebuffer incomplete. Cheap when the size is unchanged.
  Status resize(int32_t width, int32_t height);
  // Binds it for drawing and sets the viewport to its size.
  void bind() const;
  // Clears colour (to `background`) and depth. Binds it first.
  void clear(Rgba8 background) const;
  // Reads the colour buffer back; row 0 is the top row. Waits for rendering to finish.
  ImageRgba readPixels() const;

  int32_t width() const { return width_; }
  int32_t height() const { return height_; }
  uint32_t colourTexture() const { return colour_; }  // GL texture name
  uint32_t id() const { return fbo_; }                // GL framebuffer name

 private:
  void release();
  uint32_t fbo_ = 0, colour_ = 0, depth_ = 0;
  int32_t width_ = 0, height_ = 0;
};

}  // namespace vox::render
