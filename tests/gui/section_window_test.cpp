// The zoomed section picture's mapping between the picture's voxels, the screen and the texture (SectionWindow), worked
// out by hand from its definition: zoom Z about the centre (cx, cy), fractions of the width (right) and the height
// (up), shows 1/Z of each axis; rows count from the top, so "up" fractions turn into rows from the bottom.
#include <gtest/gtest.h>

#include "app/panels/section_window.h"

namespace vox::app {
namespace {

TEST(SectionWindow, aWholePictureMapsItsCornersToTheRectangleAndTheWholeTexture) {
  SectionUi ui;  // zoom 1, centred
  const SectionWindow w(ui, ImVec2(10, 20), ImVec2(200, 100), 100, 50);
  EXPECT_FLOAT_EQ(w.px, 2.0f);
  EXPECT_DOUBLE_EQ(w.cellAt(ImVec2(10, 20)).x, 0.0);
  EXPECT_DOUBLE_EQ(w.cellAt(ImVec2(10, 20)).y, 0.0);
  EXPECT_FLOAT_EQ(w.screenOf(100, 50).x, 210.0f);
  EXPECT_FLOAT_EQ(w.screenOf(100, 50).y, 120.0f);
  EXPECT_FLOAT_EQ(w.uvMin().x, 0.0f);
  EXPECT_FLOAT_EQ(w.uvMin().y, 0.0f);
  EXPECT_FLOAT_EQ(w.uvMax().x, 1.0f);
  EXPECT_FLOAT_EQ(w.uvMax().y, 1.0f);
  EXPECT_TRUE(w.shows(ImVec2(110, 70)));
  EXPECT_FALSE(w.shows(ImVec2(211, 70)));
}

TEST(SectionWindow, aZoomedPictureShowsTheQuarterAboutItsCentreWithTheUpAxisFlippedToRows) {
  SectionUi ui;
  ui.zoom = 4.0;
  ui.centre = {0.25, 0.75};  // a quarter of the way right, three quarters up: the upper left of the picture
  const SectionWindow w(ui, ImVec2(10, 20), ImVec2(200, 100), 100, 50);
  // Columns 12.5 to 37.5 (0.25 +- 0.125 of 100); rows from the top 6.25 to 18.75 ((1 - 0.75) +- 0.125 of 50).
  EXPECT_FLOAT_EQ(w.px, 8.0f);
  EXPECT_DOUBLE_EQ(w.cellAt(ImVec2(10, 20)).x, 12.5);
  EXPECT_DOUBLE_EQ(w.cellAt(ImVec2(10, 20)).y, 6.25);
  EXPECT_DOUBLE_EQ(w.cellAt(ImVec2(210, 120)).x, 37.5);
  EXPECT_DOUBLE_EQ(w.cellAt(ImVec2(210, 120)).y, 18.75);
  EXPECT_FLOAT_EQ(w.uvMin().x, 0.125f);
  EXPECT_FLOAT_EQ(w.uvMin().y, 0.125f);
  EXPECT_FLOAT_EQ(w.uvMax().x, 0.375f);
  EXPECT_FLOAT_EQ(w.uvMax().y, 0.375f);
  // A voxel and its screen point map back to each other; one outside the quarter is off the rectangle.
  const ImVec2 p = w.screenOf(20.0, 10.0);
  EXPECT_FLOAT_EQ(p.x, 10.0f + 7.5f * 8.0f);
  EXPECT_FLOAT_EQ(p.y, 20.0f + 3.75f * 8.0f);
  EXPECT_DOUBLE_EQ(w.cellAt(p).x, 20.0);
  EXPECT_DOUBLE_EQ(w.cellAt(p).y, 10.0);
  EXPECT_FALSE(w.shows(w.screenOf(50.0, 10.0)));
}

}  // namespace
}  // namespace vox::app
