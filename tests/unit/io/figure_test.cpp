// Annotated figures: the layout they report is where the map really is, the legend grows with the map, and the
// text is drawn (stb_easy_font).
#include <gtest/gtest.h>

#include <algorithm>

#include "vox/io/figure.h"

namespace vox::io {
namespace {

// A w x h map whose value rises to the right (0 in the first column: no material).
Image2D<int32_t> ramp(int32_t w, int32_t h) {
  Image2D<int32_t> m(w, h);
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) m.at(x, y) = x;
  return m;
}

ScalarMapLegend legend() {
  ScalarMapLegend l;
  l.title = "X-ray along z: total thickness per ray";
  l.value_name = "voxels";
  l.units_per_value = 0.5;
  l.units = "mm";
  l.right_axis = "x";
  l.up_axis = "y";
  l.notes = {"a note under the map"};
  return l;
}

int inkPixels(const ImageRgb& img, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(img.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width, x1); ++x) n += img.at(x, y) == Rgb8{20, 20, 20};
  return n;
}

TEST(Figure, reportsWhereItDrewTheMapAndTheBar) {
  const Image2D<int32_t> values = ramp(30, 20);
  const ScalarMapFigure f = drawScalarMapFigure(values, 29, legend(), 3);
  EXPECT_EQ(f.map.width, 90);
  EXPECT_EQ(f.map.height, 60);
  for (int32_t y = 0; y < values.height; ++y) {
    for (int32_t x = 0; x < values.width; ++x) {
      const Rgb8 expected = x == 0 ? kNoMaterialColour : rampColour(double(x) / 29.0);
      ASSERT_EQ(f.image.at(f.map.x + 3 * x + 1, f.map.y + 3 * y + 1), expected) << x << ", " << y;
    }
  }
  EXPECT_GT(f.bar.x, f.map.x + f.map.width);                     // the bar right of the map
  EXPECT_EQ(f.image.at(f.bar.x + 1, f.bar.y), rampColour(1.0));  // the maximum at the top
  EXPECT_EQ(f.image.at(f.bar.x + 1, f.bar.y + f.bar.height - 1), rampColour(0.0));
  // Title above the map, labels right of the bar, the note below.
  EXPECT_GT(inkPixels(f.image, 0, 0, f.image.width, f.map.y - textLineHeight(f.text_scale)), 100);
  EXPECT_GT(inkPixels(f.image, f.bar.x + f.bar.width + 1, f.bar.y, f.image.width, f.bar.y + f.bar.height), 50);
  EXPECT_GT(
      inkPixels(f.image, f.map.x, f.map.y + f.map.height + textLineHeight(f.text_scale), f.image.width, f.image.height),
      30);
}

// At R = 4096 an X-ray is about 1243 x 2110 rays: the legend must stay readable when the whole figure is shown,
// so its letters grow with the map (1/60 of the larger side), never below 14 pixels.
TEST(Figure, legendTextGrowsWithTheMap) {
  EXPECT_EQ(drawScalarMapFigure(ramp(40, 30), 39, legend(), 1).text_scale, 2);
  const ScalarMapFigure big = drawScalarMapFigure(ramp(1243, 2110), 1242, legend(), 1);
  EXPECT_GE(big.text_scale * 7, 2110 / 60);
  EXPECT_GE(textWidth(legend().title, big.text_scale), big.map.width / 2);
}

TEST(Figure, textIsDrawnAndMeasured) {
  ImageRgb img(200, 40, Rgb8{255, 255, 255});
  drawText(img, 2, 2, "Volume 12.5 mm", Rgb8{20, 20, 20}, 2);
  const int w = textWidth("Volume 12.5 mm", 2);
  EXPECT_GT(inkPixels(img, 0, 0, 2 + w, 40), 100);
  EXPECT_EQ(inkPixels(img, 2 + w + 2, 0, 200, 40), 0);  // nothing past the measured width
  EXPECT_EQ(textWidth("", 2), 0);
}

TEST(Figure, ticksAreRoundNumbersUpToTheMaximum) {
  EXPECT_EQ(colourBarTicks(0), (std::vector<int64_t>{0}));
  EXPECT_EQ(colourBarTicks(7), (std::vector<int64_t>{0, 2, 4, 6, 7}));
  EXPECT_EQ(colourBarTicks(100), (std::vector<int64_t>{0, 20, 40, 60, 80, 100}));
}

}  // namespace
}  // namespace vox::io
