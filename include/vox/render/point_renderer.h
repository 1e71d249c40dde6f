#pragma once
// The point renderer (thesis 5.1 and 6.2): draws the surface voxels of a grid as points shaded from a 64-entry
// intensity table, with back-facing code groups skipped, an optional section (cut-away) and a coarser level of
// detail while the camera moves. It draws into whatever framebuffer is bound (a Framebuffer, or the GUI's) in the
// current GL 3.3 core context, which may be EGL (HeadlessContext) or a GLFW window.
//
// Typical GUI use:
//   auto renderer = PointRenderer::create();          // once, after the context exists
//   renderer->setGrid(grid);                           // on load; after an edit of layers [z0, z1):
//   renderer->updateLayers(grid, z0, z1);
//   framebuffer.clear(background);
//   renderer->draw(camera, width, height, params);     // params.coarse = true while the mouse drags
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/render/camera.h"
#include "vox/render/point_cloud.h"
#include "vox/render/shading.h"

namespace vox::render {

struct DrawParams {
  Lut lut = Lut::kClassic;
  // Colour of an intensity-1 point, RGB in 0..1. Default: the thesis's green (0, 1, 0) for kClassic
  // (docs/conventions.md, "Classic intensity table": colour (0, I/20, 0)); a light grey-blue for kLit.
  std::optional<glm::vec3> colour;
  glm::dvec3 light_dir_view = kDefaultLightView;  // kLit: towards the light, view space (need not be unit length)
  double ambient = kDefaultAmbient;               // kLit: intensity of faces turned away from the light
  // Section face colour at full intensity; it is shaded like a surface whose only free face is the cut face.
  glm::vec3 cut_colour{0.95f, 0.35f, 0.25f};
  CutAway section;
  double point_size_px = 0.0;  // > 0: fixed point diameter in pixels; 0: closedPointSize (shading.h), which keeps
                               // the surface closed
  bool round_points = false;   // thesis "point smooth": round instead of square points
  float opacity = 1.0f;        // < 1: blended over what is drawn, depth-tested but not written (a ghost)
  bool cull_back_groups = true;
  // Level of detail: draw a 2^k-downsampled point set (k >= 1, the smallest whose point count fits
  // lod_point_budget) with 2^k-times larger points. For camera motion on a software rasteriser (llvmpipe draws
  // roughly 8 million points a second on 2 cores). Ignored when the full set already fits the budget.
  bool coarse = false;
  int64_t lod_point_budget = 1'000'000;
  // Colour by the scalar volume (PointRenderer::setScalarVolume): each surface point (not the section face) takes
  // the ramp colour of its voxel's value (dark blue, teal, green, yellow: io::rampColour) times its shading, and
  // values under scalar_threshold (0..1 of the ramp) are red. Points without a value keep `colour`. Ignored without
  // a volume.
  bool scalar_colour = false;
  float scalar_threshold = 0.0f;
};

struct DrawStats {
  int lod_level = 0;             // 0 = full detail
  int64_t points_available = 0;  // points of the chosen level
  int64_t points_drawn = 0;      // after group culling (surface points sent to the GPU, clipped ones included)
  int64_t cut_points = 0;        // section face points drawn
  int groups_drawn = 0;          // code groups drawn out of 63
  double point_size_px = 0.0;    // diameter at the target's depth
};

class PointRenderer {
 public:
  // Compiles the embedded shaders and creates the GL objects. Needs a current 3.3 core context; kNoOpenGL with
  // the compiler's log when a shader does not build.
  static Result<std::unique_ptr<PointRenderer>> create();
  ~PointRenderer();
  PointRenderer(const PointRenderer&) = delete;
  PointRenderer& operator=(const PointRenderer&) = delete;

  // Extracts and uploads the surface points of `grid` (O(grid words + surface voxels), see PointCloud::build) and
  // keeps a copy-on-write snapshot of the grid for sections and level of detail (O(nz)).
  void setGrid(const VoxelGrid& grid);
  // After voxels changed in layers [z0, z1) only: re-extracts those layers (and their Z neighbours) and re-uploads
  // the point buffer (a memcpy-speed copy of all points). Falls back to setGrid when the dims changed.
  void updateLayers(const VoxelGrid& grid, int32_t z0, int32_t z1);

  // Uploads the full-detail points now if they changed since the last upload; draw() otherwise does it on first
  // use. Lets a caller time the upload or do it outside a frame. O(points): a copy into draw order and one
  // glBufferSubData (glBufferData when the buffer must grow).
  void prepare();

  // A scalar per voxel over a box of the grid (voxels box_min .. box_min + box_dims - 1), x fastest: 0 = no value,
  // 1..255 = 0..1 along the colour ramp (DrawParams::scalar_colour). Uploaded as a GL_R8 3D texture; refused,
  // saying why, when the box is larger than the GL's GL_MAX_3D_TEXTURE_SIZE (the previous volume is then cleared).
  Status setScalarVolume(glm::ivec3 box_min, Dims box_dims, const std::vector<uint8_t>& values);
  void clearScalarVolume();
  bool hasScalarVolume() const { return scalar_texture_ != 0; }

  // Tight box of the surface voxels in voxel-index space (the grid's box when it has none): for Camera::fitToBox.
  Box3 bounds() const;
  const PointCloud& cloud() const { return levels_[0].cloud; }

  // Draws into the bound framebuffer with a viewport of width x height pixels (the caller binds and clears it).
  // Leaves the depth test enabled and program point size on.
  DrawStats draw(const Camera& camera, int32_t width, int32_t height, const DrawParams& params);

 private:
  struct Level {
    VoxelGrid grid;  // level 0: the caller's grid (shared layers); level k: downsample2 of level k - 1
    PointCloud cloud;
    PointBuffer buffer;  // staging copy in draw order
    uint32_t vbo = 0;
    int64_t vbo_capacity = 0;  // points
    uint64_t uploaded_version = ~uint64_t(0);
    bool built = false;
  };
  PointRenderer() = default;
  Level& level(int k);  // builds coarse levels on first use
  void upload(Level& lvl);

  std::array<uint32_t, 2> programs_{};  // square points, round points
  uint32_t vao_ = 0, cut_vao_ = 0, cut_vbo_ = 0;
  int64_t cut_capacity_ = 0;
  std::array<Level, 5> levels_;
  Box3 bounds_;
  uint64_t grid_version_ = 0;  // bumped by setGrid and updateLayers
  // The section points are recomputed only when the section, the level or the grid changes.
  CutAway cut_section_;
  int cut_level_ = -1;
  uint64_t cut_version_ = ~uint64_t(0);
  int64_t cut_count_ = 0;
  uint32_t scalar_texture_ = 0;  // GL_TEXTURE_3D, GL_R8; 0: none
  glm::ivec3 scalar_min_{0};
  glm::ivec3 scalar_dims_{0};
};

}  // namespace vox::render
