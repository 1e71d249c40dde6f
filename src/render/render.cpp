// One-call headless rendering for `voxmod render` (docs/conventions.md, "Command line") and the tests: the thesis 6.2
// point display of a grid, fitted to the image, read back as an RGBA image.
#include "vox/render/render.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "vox/render/context.h"
#include "vox/render/framebuffer.h"
#include "vox/render/gl.h"

namespace vox::render {

Status validateRenderParams(const VoxelGrid& grid, const RenderParams& p) {
  auto bad = [](const std::string& m) { return makeError(ErrorCode::kInvalidArgument, m); };
  if (p.width < 1 || p.width > 16384 || p.height < 1 || p.height > 16384) {
    return bad("image size " + std::to_string(p.width) + "x" + std::to_string(p.height) + " is outside 1..16384");
  }
  if (!std::isfinite(p.yaw_deg) || !std::isfinite(p.pitch_deg)) return bad("yaw and pitch must be finite");
  if (!(p.zoom > 0.0) || !std::isfinite(p.zoom)) return bad("zoom must be a positive number");
  if (!(p.point_size_px >= 0.0 && p.point_size_px <= 255.0)) return bad("point size must lie in [0, 255] pixels");
  if (!(p.ambient >= 0.0 && p.ambient <= 1.0)) return bad("ambient must lie in [0, 1]");
  if (p.section.axis == SectionAxis::kPlane) {
    const glm::vec3 n = p.section.normal;
    const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!std::isfinite(length) || std::abs(length - 1.0f) > 1e-3f || !std::isfinite(p.section.offset)) {
      return bad("a section at an angle needs a unit normal and a finite offset");
    }
  } else if (p.section.active()) {
    const int axis = int(p.section.axis) - 1;
    const int32_t n = axis == 0 ? grid.nx() : axis == 1 ? grid.ny() : grid.nz();
    if (p.section.index < 0 || p.section.index >= n) {
      return bad("section index " + std::to_string(p.section.index) + " is outside the grid (0.." +
                 std::to_string(n - 1) + " along " + "XYZ"[axis] + ")");
    }
  }
  return Ok{};
}

Camera cameraFor(const Box3& bounds, const RenderParams& p) {
  Camera camera;
  camera.projection = p.projection;
  camera.yaw_deg = p.yaw_deg;
  camera.pitch_deg = p.pitch_deg;
  camera.orbit(0.0, 0.0);  // wraps yaw and clamps pitch
  camera.fitToBox(bounds, double(p.width) / double(p.height));
  camera.zoom(p.zoom);
  return camera;
}

Result<ImageRgba> renderGridInCurrentContext(const VoxelGrid& grid, const RenderParams& p) {
  if (Status s = validateRenderParams(grid, p); !s) return s.error();
  auto renderer = PointRenderer::create();
  if (!renderer) return renderer.error();
  Framebuffer fb;
  if (Status s = fb.resize(p.width, p.height); !s) return s.error();
  (*renderer)->setGrid(grid);
  const Camera camera = cameraFor((*renderer)->cloud().bounds(p.section), p);
  DrawParams d;
  d.lut = p.lut;
  d.colour = p.colour;
  d.light_dir_view = p.light_dir_view;
  d.ambient = p.ambient;
  d.section = p.section;
  d.point_size_px = p.point_size_px;
  d.round_points = p.round_points;
  fb.clear(p.background);
  (*renderer)->draw(camera, p.width, p.height, d);
  ImageRgba image = fb.readPixels();
  if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
    return makeError(ErrorCode::kNoOpenGL, "OpenGL error " + std::to_string(e) + " while rendering");
  }
  return image;
}

Result<ImageRgba> renderGridHeadless(const VoxelGrid& grid, const RenderParams& p) {
  if (Status s = validateRenderParams(grid, p); !s) return s.error();
  auto context = HeadlessContext::create();
  if (!context) return context.error();
  // The renderer and framebuffer live inside renderGridInCurrentContext, so they are gone before the context.
  return renderGridInCurrentContext(grid, p);
}

}  // namespace vox::render
