#pragma once
// A GL texture holding a 2D analysis image (section, X-ray) for ImGui::Image. Needs the window's GL context.
#include <cstddef>  // vox/core/image.h uses size_t without including it
#include <cstdint>

#include "vox/core/image.h"

namespace vox::app {

class Texture {
 public:
  Texture() = default;
  ~Texture();
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  // Uploads the image (row 0 at the top, as ImGui draws it). Pixels are shown magnified without smoothing, so
  // every voxel stays a sharp square.
  void upload(const ImageRgb& image);
  void reset();

  uint32_t id() const { return id_; }
  int32_t width() const { return width_; }
  int32_t height() const { return height_; }
  bool empty() const { return id_ == 0; }

 private:
  uint32_t id_ = 0;
  int32_t width_ = 0, height_ = 0;
};

}  // namespace vox::app
