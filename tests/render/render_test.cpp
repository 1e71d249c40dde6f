// Render regression tests on Mesa llvmpipe (headless EGL): small scenes against tests/baselines/*.png (metric and
// threshold in render_fixture.h), plus image properties that need no baseline: a closed surface from any view,
// culling that changes nothing visible, incremental updates equal to a rebuild, row order of the read-back.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render_fixture.h"
#include "vox/render/framebuffer.h"
#include "vox/render/gl.h"
#include "vox/render/point_renderer.h"
#include "vox/render/render.h"

namespace vox::render::testing {
namespace {

constexpr Rgba8 kBlack{0, 0, 0, 255};

RenderParams small(double yaw, double pitch) {
  RenderParams p;
  p.width = 256;
  p.height = 256;
  p.yaw_deg = yaw;
  p.pitch_deg = pitch;
  return p;
}

ImageRgba render(const VoxelGrid& g, const RenderParams& p) {
  auto image = renderGridInCurrentContext(g, p);
  EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error().message);
  return image.ok() ? std::move(image).value() : ImageRgba();
}

// An L-shaped block with a square through-hole along Z: concave corners, an inner wall, flat faces of all six
// orientations.
VoxelGrid bracket() {
  VoxelGrid g(Dims{84, 64, 44});
  fillBox(g, {2, 2, 2}, {82, 62, 42});
  fillBox(g, {30, 22, 2}, {50, 42, 42}, false);   // the hole
  fillBox(g, {56, 40, 24}, {82, 62, 42}, false);  // the step
  return g;
}

TEST(RenderBaseline, sphereR64Classic) {
  VOX_REQUIRE_GL();
  expectMatchesBaseline(render(ball(64), small(30, 20)), "sphere_r64_classic");
}

TEST(RenderBaseline, sphereR64Lit) {
  VOX_REQUIRE_GL();
  RenderParams p = small(30, 20);
  p.lut = Lut::kLit;
  expectMatchesBaseline(render(ball(64), p), "sphere_r64_lit");
}

TEST(RenderBaseline, sphereR64CutAwayAlongX) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = ball(64);
  RenderParams p = small(60, 25);  // the eye on the +X side, looking at the cut face
  p.section = {SectionAxis::kX, g.nx() / 2, SectionSide::kBelow};
  expectMatchesBaseline(render(g, p), "sphere_r64_cut_x");
}

TEST(RenderBaseline, bracketRotatedOrthographicLitRoundPoints) {
  VOX_REQUIRE_GL();
  RenderParams p = small(150, 30);  // from behind, above: the step, the hole and two inner walls
  p.projection = Projection::kOrthographic;
  p.lut = Lut::kLit;
  p.round_points = true;
  p.background = {40, 40, 48, 255};
  expectMatchesBaseline(render(bracket(), p), "bracket_rotated_ortho_lit");
}

TEST(RenderBaseline, sphereR100CoarseLevelOfDetail) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = ball(100);
  auto renderer = PointRenderer::create();
  ASSERT_TRUE(renderer.ok());
  Framebuffer fb;
  ASSERT_TRUE(fb.resize(256, 256).ok());
  (*renderer)->setGrid(g);
  const RenderParams p = small(30, 20);
  DrawParams d;
  d.coarse = true;
  d.lod_point_budget = 20'000;  // ~120k surface points at full detail: two halvings
  fb.clear(kBlack);
  const DrawStats stats = (*renderer)->draw(cameraFor((*renderer)->bounds(), p), 256, 256, d);
  EXPECT_EQ(stats.lod_level, 2);
  EXPECT_LE(stats.points_available, 20'000);
  expectMatchesBaseline(fb.readPixels(), "sphere_r100_lod2");
}

// ---- Properties ----

struct View {
  double yaw, pitch;
};

TEST(RenderProperties, pointSurfaceIsClosedFromAnyView) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = ball(40);
  // (45, 90) looks straight down with the face lattice turned 45 degrees on screen; iso is the largest factor.
  for (View v : {View{45, 90}, View{0, 0}, View{45, 35.26}, View{17, -63}, View{-100, 12}}) {
    for (Projection proj : {Projection::kPerspective, Projection::kOrthographic}) {
      for (bool round : {false, true}) {
        for (int32_t size : {200, 560}) {  // about 2 and 6 pixels per voxel
          RenderParams p = small(v.yaw, v.pitch);
          p.projection = proj;
          p.round_points = round;
          p.width = p.height = size;
          EXPECT_EQ(holesInsideBall(render(g, p), kBlack), 0)
              << "yaw " << v.yaw << " pitch " << v.pitch << " round " << round << " perspective "
              << (proj == Projection::kPerspective) << " size " << size;
        }
      }
    }
  }
}

TEST(RenderProperties, backGroupCullingSkipsPointsButNotPixels) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = bracket();
  auto renderer = PointRenderer::create();
  ASSERT_TRUE(renderer.ok());
  Framebuffer fb;
  ASSERT_TRUE(fb.resize(256, 256).ok());
  (*renderer)->setGrid(g);
  for (View v : {View{30, 20}, View{-130, -35}, View{90, 0}}) {
    for (Projection proj : {Projection::kPerspective, Projection::kOrthographic}) {
      RenderParams p = small(v.yaw, v.pitch);
      p.projection = proj;
      const Camera cam = cameraFor((*renderer)->bounds(), p);
      DrawParams d;
      d.cull_back_groups = false;
      fb.clear(kBlack);
      const DrawStats all = (*renderer)->draw(cam, 256, 256, d);
      const ImageRgba full = fb.readPixels();
      d.cull_back_groups = true;
      fb.clear(kBlack);
      const DrawStats culled = (*renderer)->draw(cam, 256, 256, d);
      const ImageRgba fast = fb.readPixels();
      EXPECT_EQ(all.points_drawn, (*renderer)->cloud().size());
      EXPECT_LT(culled.points_drawn, all.points_drawn) << "yaw " << v.yaw;
      if (proj == Projection::kOrthographic) {  // perspective's test is conservative: it keeps more
        EXPECT_LT(culled.points_drawn, all.points_drawn * 3 / 4) << "yaw " << v.yaw;
      }
      const Comparison c = compareImages(fast, full);
      // Culled voxels all lie behind nearer ones; only sprite corners poking past a silhouette may differ.
      EXPECT_LE(double(c.different), 0.001 * 256 * 256) << "yaw " << v.yaw << " proj " << int(proj);
    }
  }
}

TEST(RenderProperties, incrementalUpdateDrawsWhatAFullRebuildDraws) {
  VOX_REQUIRE_GL();
  VoxelGrid g = ball(48);
  auto incremental = PointRenderer::create();
  auto fresh = PointRenderer::create();
  ASSERT_TRUE(incremental.ok() && fresh.ok());
  (*incremental)->setGrid(g);
  Framebuffer fb;
  ASSERT_TRUE(fb.resize(256, 256).ok());
  const Camera cam = cameraFor((*incremental)->bounds(), small(30, 20));
  DrawParams coarse;
  coarse.coarse = true;
  coarse.lod_point_budget = 5'000;
  fb.clear(kBlack);
  (*incremental)->draw(cam, 256, 256, coarse);  // builds the coarse levels, so the edit must update them too
  // Carve a slot through layers 40..59 and add a block on top.
  for (int32_t z = 40; z < 60; ++z) fillBox(g, {0, 45, z}, {100, 55, z + 1}, false);
  fillBox(g, {45, 45, 92}, {55, 55, 100});
  (*incremental)->updateLayers(g, 40, 60);
  (*incremental)->updateLayers(g, 92, 100);
  (*fresh)->setGrid(g);
  for (bool lod : {false, true}) {
    DrawParams d;
    d.coarse = lod;
    d.lod_point_budget = 5'000;
    fb.clear(kBlack);
    const DrawStats a = (*incremental)->draw(cam, 256, 256, d);
    const ImageRgba ia = fb.readPixels();
    fb.clear(kBlack);
    const DrawStats b = (*fresh)->draw(cam, 256, 256, d);
    const ImageRgba ib = fb.readPixels();
    EXPECT_EQ(a.lod_level, b.lod_level);
    EXPECT_EQ(a.points_available, b.points_available);
    EXPECT_EQ(compareImages(ia, ib).max_difference, 0) << "lod " << lod;
  }
}

// A renderer that drew another grid's coarse levels must not keep their GPU copies after setGrid.
TEST(RenderProperties, setGridReplacesEveryLevelOfDetail) {
  VOX_REQUIRE_GL();
  auto reused = PointRenderer::create();
  auto fresh = PointRenderer::create();
  ASSERT_TRUE(reused.ok() && fresh.ok());
  Framebuffer fb;
  ASSERT_TRUE(fb.resize(128, 128).ok());
  DrawParams d;
  d.coarse = true;
  d.lod_point_budget = 3'000;
  (*reused)->setGrid(ball(40));
  fb.clear(kBlack);
  (*reused)->draw(cameraFor((*reused)->bounds(), small(30, 20)), 128, 128, d);
  const VoxelGrid other = bracket();
  (*reused)->setGrid(other);
  (*fresh)->setGrid(other);
  const Camera cam = cameraFor((*fresh)->bounds(), small(30, 20));
  fb.clear(kBlack);
  const DrawStats a = (*reused)->draw(cam, 128, 128, d);
  const ImageRgba ia = fb.readPixels();
  fb.clear(kBlack);
  const DrawStats b = (*fresh)->draw(cam, 128, 128, d);
  const ImageRgba ib = fb.readPixels();
  EXPECT_GE(a.lod_level, 1);
  EXPECT_EQ(a.lod_level, b.lod_level);
  EXPECT_EQ(a.points_drawn, b.points_drawn);
  EXPECT_LE(a.points_drawn, a.points_available);
  EXPECT_EQ(compareImages(ia, ib).max_difference, 0);
}

TEST(RenderProperties, sectionShowsTheCutFaceInTheCutColour) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = ball(40);
  RenderParams p = small(0, 0);  // looking along -Z at a Z cut keeping z < index: the cut face fills the disc
  p.section = {SectionAxis::kZ, g.nz() / 2, SectionSide::kBelow};
  const ImageRgba image = render(g, p);
  const Rgba8 centre = image.at(128, 128);
  EXPECT_GT(centre.r, 100);  // cut colour (0.95, 0.35, 0.25) at the classic +Z intensity 17/20
  EXPECT_LT(centre.g, centre.r / 2);
  EXPECT_EQ(holesInsideBall(image, kBlack), 0);
  // Keeping the other half from the same side shows the outer surface (green) instead.
  p.section.side = SectionSide::kAbove;
  const Rgba8 outside = render(g, p).at(128, 128);
  EXPECT_EQ(outside.r, 0);
  EXPECT_GT(outside.g, 100);
}

// A plane at an angle: seen along its normal, the cut face fills the disc without holes; normal to Z through the
// centres of an index, it draws the same image as that Z section.
TEST(RenderProperties, aSectionAtAnAngleShowsAClosedCutFace) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = ball(40);
  RenderParams p = small(0, 0);
  const glm::vec3 n = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  p.section = {SectionAxis::kPlane, 0, SectionSide::kBelow, n, glm::dot(n, glm::vec3(float(g.nx()) / 2.0f))};
  ASSERT_TRUE(validateRenderParams(g, p));
  const ImageRgba image = render(g, p);
  const Rgba8 centre = image.at(128, 128);
  EXPECT_GT(centre.r, 100);
  EXPECT_LT(centre.g, centre.r / 2);
  EXPECT_EQ(holesInsideBall(image, kBlack), 0);
  p.section = {SectionAxis::kPlane, 0, SectionSide::kBelow, glm::vec3(0.0f, 0.0f, 1.0f), float(g.nz() / 2) + 0.5f};
  const ImageRgba as_plane = render(g, p);
  p.section = {SectionAxis::kZ, g.nz() / 2, SectionSide::kBelow};
  EXPECT_EQ(compareImages(as_plane, render(g, p)).max_difference, 0);
  p.section = {SectionAxis::kPlane, 0, SectionSide::kBelow, glm::vec3(0.0f, 0.0f, 2.0f), 1.0f};
  EXPECT_FALSE(validateRenderParams(g, p));  // the normal must be a unit vector
}

// A scalar volume colours the surface points by the ramp (dark blue at 0, yellow at 1) and paints values under the
// threshold red; the section face keeps its colour; without the flag the draw is the plain one.
TEST(RenderProperties, scalarVolumeColoursTheSurface) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = ball(40);
  auto renderer = PointRenderer::create();
  ASSERT_TRUE(renderer.ok());
  (*renderer)->setGrid(g);
  Framebuffer fb;
  ASSERT_TRUE(fb.resize(256, 256).ok());
  const Camera cam = cameraFor((*renderer)->bounds(), small(0, 0));
  const auto draw = [&](const DrawParams& d) {
    fb.clear(kBlack);
    (*renderer)->draw(cam, 256, 256, d);
    return fb.readPixels();
  };
  DrawParams plain;
  plain.lut = Lut::kLit;
  const ImageRgba before = draw(plain);
  // Values along X: 0 (dark blue) on the left half, 1 (yellow) on the right half.
  const Dims d = g.dims();
  std::vector<uint8_t> values(size_t(d.count()));
  for (int64_t i = 0; i < d.count(); ++i) values[size_t(i)] = (i % d.nx) < d.nx / 2 ? 1 : 255;
  ASSERT_TRUE((*renderer)->setScalarVolume({0, 0, 0}, d, values).ok());
  EXPECT_EQ(compareImages(draw(plain), before).max_difference, 0);  // not asked for: the plain draw
  DrawParams coloured = plain;
  coloured.scalar_colour = true;
  const ImageRgba image = draw(coloured);
  EXPECT_GT(compareImages(image, before).different, 1000);
  const Rgba8 left = image.at(128 - 30, 128), right = image.at(128 + 30, 128);
  EXPECT_GT(left.b, left.r);        // dark blue
  EXPECT_GT(right.r, 2 * right.b);  // yellow
  EXPECT_GT(right.g, 2 * right.b);
  DrawParams coarse = coloured;  // a level-of-detail point looks at its fine voxels' values
  coarse.coarse = true;
  coarse.lod_point_budget = 2'000;
  const Rgba8 coarse_right = draw(coarse).at(128 + 30, 128);
  EXPECT_GT(coarse_right.r, 2 * coarse_right.b);
  coloured.scalar_threshold = 0.5f;  // the left half is under it: red
  const Rgba8 red = draw(coloured).at(128 - 30, 128);
  EXPECT_GT(red.r, 3 * std::max<int>(red.g, 1));
  // A box larger than the GL allows is refused, and the colouring is gone.
  GLint most = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &most);
  const Status big =
      (*renderer)->setScalarVolume({0, 0, 0}, Dims{most + 1, 1, 1}, std::vector<uint8_t>(size_t(most) + 1));
  EXPECT_FALSE(big.ok());
  EXPECT_FALSE((*renderer)->hasScalarVolume());
  EXPECT_EQ(compareImages(draw(coloured), before).max_difference, 0);
}

TEST(RenderProperties, imageRowZeroIsTheTop) {
  VOX_REQUIRE_GL();
  VoxelGrid g(Dims{40, 40, 40});
  fillBox(g, {0, 30, 0}, {40, 40, 40});  // a slab at high Y: the top of the default view (Y up)
  RenderParams p = small(0, 0);
  p.projection = Projection::kOrthographic;
  p.zoom = 0.3;  // the slab then sits above the image centre, with empty rows below
  VoxelGrid frame = g;
  fillBox(frame, {0, 0, 0}, {1, 1, 1});  // a voxel at the bottom corner stretches the fitted box over the grid
  const ImageRgba image = render(frame, p);
  auto row_has_points = [&](int32_t y) {
    for (int32_t x = 0; x < image.width; ++x)
      if (!(image.at(x, y) == kBlack)) return true;
    return false;
  };
  int32_t first = -1;
  for (int32_t y = 0; y < image.height && first < 0; ++y)
    if (row_has_points(y)) first = y;
  ASSERT_GE(first, 0);
  // The slab (top quarter of the box) starts above the centre; the corner voxel is a lone point far below it.
  EXPECT_LT(first, 128);
  EXPECT_TRUE(row_has_points(first + 2));
}

TEST(RenderProperties, headlessEntryPointMatchesTheCurrentContextPath) {
  VOX_REQUIRE_GL();
  const VoxelGrid g = ball(20);
  const RenderParams p = small(200, -10);
  const ImageRgba in_current = render(g, p);
  auto own = renderGridHeadless(g, p);  // makes, uses and destroys a second context on the same EGL display
  ASSERT_TRUE(own.ok()) << own.error().message;
  EXPECT_EQ(compareImages(*own, in_current).max_difference, 0);
  ASSERT_TRUE(sharedContext()->makeCurrent().ok());
  EXPECT_EQ(compareImages(render(g, p), in_current).max_difference, 0);  // the shared display survived
}

TEST(RenderProperties, rejectsBadParametersBeforeTouchingGl) {
  const VoxelGrid g = ball(5);
  RenderParams p;
  p.width = 0;
  EXPECT_EQ(renderGridHeadless(g, p).error().code, ErrorCode::kInvalidArgument);
  p = RenderParams();
  p.zoom = 0;
  EXPECT_EQ(renderGridHeadless(g, p).error().code, ErrorCode::kInvalidArgument);
  p = RenderParams();
  p.section = {SectionAxis::kY, g.ny(), SectionSide::kBelow};
  const auto r = renderGridHeadless(g, p);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(r.error().message.find("along Y"), std::string::npos) << r.error().message;
}

TEST(RenderContext, reportsLlvmpipeAndGl33Core) {
  VOX_REQUIRE_GL();
  const HeadlessInfo& info = sharedContext()->info();
  EXPECT_NE(info.renderer.find("llvmpipe"), std::string::npos) << info.renderer;
  EXPECT_FALSE(info.version.empty());
  EXPECT_TRUE(info.platform == "surfaceless" || info.platform == "device") << info.platform;
}

}  // namespace
}  // namespace vox::render::testing
