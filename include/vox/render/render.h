#pragma once
// One-call rendering for `voxmod render` (docs/conventions.md, "Command line") and tests: grid in, image out, no
// window.
//
//   vox::render::RenderParams p;             // defaults: 800 x 600, yaw 30, pitch 20, classic table, perspective
//   p.lut = vox::render::Lut::kLit;
//   auto image = vox::render::renderGridHeadless(grid, p);
//   if (!image) { /* image.error().code == ErrorCode::kNoOpenGL -> exit code 3 */ }
//   vox::io::savePng(*image, "out.png");
#include <cstddef>  // vox/core/image.h uses size_t without including it
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "vox/core/image.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/render/camera.h"
#include "vox/render/point_cloud.h"
#include "vox/render/point_renderer.h"
#include "vox/render/shading.h"

namespace vox::render {

struct RenderParams {
  int32_t width = 800;  // image size in pixels, 1..16384
  int32_t height = 600;
  // View direction (camera.h): yaw about +Y, pitch towards +Y, degrees; 0, 0 looks along -Z with X right, Y up.
  double yaw_deg = 30.0;
  double pitch_deg = 20.0;
  Lut lut = Lut::kClassic;
  Projection projection = Projection::kPerspective;
  // Magnification relative to fitting the model's bounding sphere to the image (1 = fit, 2 = twice as large).
  double zoom = 1.0;
  CutAway section;             // cut-away: keep one side of a plane along X, Y or Z and show the cut face
  double point_size_px = 0.0;  // > 0 overrides the automatic point size (projected voxel size, thesis 6.2)
  bool round_points = false;   // thesis "point smooth"
  Rgba8 background{0, 0, 0, 255};
  std::optional<glm::vec3> colour;  // surface colour at intensity 1 (RGB 0..1); default per table (DrawParams)
  glm::dvec3 light_dir_view = kDefaultLightView;  // kLit only
  double ambient = kDefaultAmbient;               // kLit only
};

// Checks the parameters: kInvalidArgument naming the bad one (size out of range, zoom <= 0, non-finite angles,
// section index outside the grid along its axis, point size not in [0, 255], ambient not in [0, 1]).
Status validateRenderParams(const VoxelGrid& grid, const RenderParams& params);

// The camera renderGridHeadless uses: fitted to `bounds` (there PointCloud::bounds(section), so a cut-away fills
// the image), then yaw, pitch, zoom applied.
Camera cameraFor(const Box3& bounds, const RenderParams& params);

// Creates a HeadlessContext, draws the surface points of `grid` at full detail and reads the image back (row 0 at
// the top). Errors: kInvalidArgument (validateRenderParams), kNoOpenGL (no EGL / GL 3.3 core available, or a
// driver failure). Cost: a context (~0.1 s) + PointCloud build + about 0.12 s per million points drawn on llvmpipe.
Result<ImageRgba> renderGridHeadless(const VoxelGrid& grid, const RenderParams& params);

// The same in the GL context current on this thread (no context creation): for callers that render many images.
Result<ImageRgba> renderGridInCurrentContext(const VoxelGrid& grid, const RenderParams& params);

}  // namespace vox::render
