// The exported 3D view: what the window draws over the view while the Thickness panel is open (the colour scale and
// the hot spots' numbered rings) is on the picture too, and nothing of it without the panel.
#include <gtest/gtest.h>

#include "app/thickness.h"
#include "app/thickness_view.h"
#include "app/view_export.h"
#include "app/viewport.h"
#include "gui/app_test_support.h"
#include "vox/io/figure.h"
#include "vox/io/voxel_file.h"

namespace vox::app {
namespace {

using test_app::llvmpipeContext;
using test_app::pump;
using test_app::run;

bool sameColour(const Rgba8& p, ImU32 c) {
  return p.r == (c & 0xff) && p.g == ((c >> 8) & 0xff) && p.b == ((c >> 16) & 0xff);
}

int64_t pixelsOf(const ImageRgba& image, ImU32 c) {
  int64_t n = 0;
  for (const Rgba8& p : image.pixels) n += sameColour(p, c);
  return n;
}

// How many of `samples` points along the colour scale's strip (where drawThicknessLegendOnImage puts it on a picture
// under 800 pixels high) have the ramp's colour for their place.
int stripPointsInRamp(const ImageRgba& image, double max, double wall, int samples) {
  const int line = io::textLineHeight(1) + 2, x0 = 12, y = 10 + line + 3;
  const int strip_w = std::min(300, image.width - 2 * x0);
  int matching = 0;
  for (int k = 0; k < samples; ++k) {
    const int i = k * (strip_w - 1) / (samples - 1);
    const double t = max * (double(i) + 0.5) / double(strip_w);
    matching += sameColour(image.at(x0 + i, y), thicknessColour(t, max, wall));
  }
  return matching;
}

TEST(AppViewExport, carriesTheThicknessScaleAndTheHotSpotRingsWhileThePanelIsOpen) {
  auto context = llvmpipeContext();
  VOX_SKIP_WITHOUT_GL(context);
  test::TempDir dir;
  VoxelGrid block(Dims{40, 30, 16});
  for (int32_t z = 0; z < 16; ++z)
    for (int32_t y = 0; y < 30; ++y) block.fillRun(y, z, 0, 40);
  block.frame().units = "mm";
  ASSERT_TRUE(io::saveVoxelFile(block, dir / "block.vxm").ok());
  AppState state;
  ASSERT_TRUE(initViewport(state).ok());
  ASSERT_TRUE(run(state, "open " + (dir / "block.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  state.viewport.width = 640;
  state.viewport.height = 480;
  syncRenderers(state);
  ASSERT_TRUE(state.model_bounds.has_value());
  state.view.camera.fitToBox(*state.model_bounds, 640.0 / 480.0);
  auto plain = renderViewImage(state);
  ASSERT_TRUE(plain) << plain.error().message;

  ASSERT_TRUE(run(state, "panel-thickness").ok());
  ASSERT_TRUE(pump(state, [&] { return shownThickness(state) != nullptr; }));
  const ThicknessResult& r = *shownThickness(state);
  ASSERT_FALSE(r.hot_spots.empty());  // the block's middle: ringed
  auto shown = renderViewImage(state);
  ASSERT_TRUE(shown) << shown.error().message;
  ASSERT_EQ(shown->width, 640);
  ASSERT_EQ(shown->height, 480);

  const double max = r.thickness.stats.max, wall = minWall(state);
  EXPECT_EQ(stripPointsInRamp(*shown, max, wall, 12), 12);  // the strip, in the ramp's colours end to end
  EXPECT_LE(stripPointsInRamp(*plain, max, wall, 12), 1);   // not there without the panel
  // The hot spot's ring (in the hot spots' magenta): a few dozen pixels on the picture, none on the plain view.
  EXPECT_GT(pixelsOf(*shown, IM_COL32(255, 60, 220, 255)), 30);
  EXPECT_EQ(pixelsOf(*plain, IM_COL32(255, 60, 220, 255)), 0);

  // The panel closed: the export is the plain view again.
  ASSERT_TRUE(run(state, "panel-section").ok());
  auto again = renderViewImage(state);
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_EQ(pixelsOf(*again, IM_COL32(255, 60, 220, 255)), 0);
  EXPECT_LE(stripPointsInRamp(*again, max, wall, 12), 1);
  shutdownViewport(state);
}

}  // namespace
}  // namespace vox::app
