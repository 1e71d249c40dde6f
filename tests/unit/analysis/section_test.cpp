#include <gtest/gtest.h>

#include "grids.h"
#include "vox/analysis/analysis.h"
#include "vox/io/figure.h"

namespace vox {
namespace {

using test::boxGrid;

TEST(Section, countsOfABoxAlongEachAxis) {
  // Box 3 x 4 x 5 at (10, 20, 30) in a 70 x 40 x 50 grid (two words per row).
  const VoxelGrid g = boxGrid(Dims{70, 40, 50}, {10, 20, 30}, {13, 24, 35});
  for (int i = 0; i < 70; ++i) EXPECT_EQ(sectionCount(g, Axis::kX, i), (i >= 10 && i < 13) ? 20 : 0) << i;
  for (int j = 0; j < 40; ++j) EXPECT_EQ(sectionCount(g, Axis::kY, j), (j >= 20 && j < 24) ? 15 : 0) << j;
  for (int k = 0; k < 50; ++k) EXPECT_EQ(sectionCount(g, Axis::kZ, k), (k >= 30 && k < 35) ? 12 : 0) << k;
  EXPECT_EQ(sectionCount(g, Axis::kX, -1), 0);
  EXPECT_EQ(sectionCount(g, Axis::kZ, 50), 0);
}

TEST(Section, imageAxesFollowTheContract) {
  // One voxel at (x, y, z) = (1, 2, 3) in a 4 x 5 x 6 grid; row 0 of every image holds the largest "up" index.
  VoxelGrid g(Dims{4, 5, 6}, GridFrame{glm::dvec3(10, 20, 30), 0.5, "mm", ""});
  g.set(1, 2, 3);
  auto z = computeSection(g, {Axis::kZ, 3});
  ASSERT_TRUE(z.ok());
  EXPECT_EQ(z->mask.width, 4);
  EXPECT_EQ(z->mask.height, 5);
  EXPECT_EQ(z->mask.at(1, 5 - 1 - 2), 1);  // x right, y up
  EXPECT_EQ(z->filled, 1);
  EXPECT_DOUBLE_EQ(z->position, 30 + 3.5 * 0.5);
  auto y = computeSection(g, {Axis::kY, 2});
  ASSERT_TRUE(y.ok());
  EXPECT_EQ(y->mask.width, 4);
  EXPECT_EQ(y->mask.height, 6);
  EXPECT_EQ(y->mask.at(1, 6 - 1 - 3), 1);  // x right, z up
  EXPECT_DOUBLE_EQ(y->position, 20 + 2.5 * 0.5);
  auto x = computeSection(g, {Axis::kX, 1});
  ASSERT_TRUE(x.ok());
  EXPECT_EQ(x->mask.width, 5);
  EXPECT_EQ(x->mask.height, 6);
  EXPECT_EQ(x->mask.at(2, 6 - 1 - 3), 1);  // y right, z up
  EXPECT_DOUBLE_EQ(x->position, 10 + 1.5 * 0.5);
  EXPECT_EQ(computeSection(g, {Axis::kX, 0})->filled, 0);
}

TEST(Section, matchesBruteForceOnRandomGrids) {
  for (int nx : {1, 63, 64, 65, 129}) {
    const VoxelGrid g = test::randomGrid(Dims{nx, 11, 7}, 0.4, uint32_t(100 + nx));
    for (Axis axis : {Axis::kX, Axis::kY, Axis::kZ}) {
      const int n = axis == Axis::kX ? g.nx() : (axis == Axis::kY ? g.ny() : g.nz());
      for (int i = 0; i < n; ++i) {
        auto s = computeSection(g, {axis, i});
        ASSERT_TRUE(s.ok());
        int64_t count = 0;
        for (int v = 0; v < s->mask.height; ++v) {
          for (int u = 0; u < s->mask.width; ++u) {
            const int up = s->mask.height - 1 - v;
            const bool expect =
                axis == Axis::kX ? g.get(i, u, up) : (axis == Axis::kY ? g.get(u, i, up) : g.get(u, up, i));
            ASSERT_EQ(s->mask.at(u, v) != 0, expect);
            count += expect;
          }
        }
        EXPECT_EQ(s->filled, count);
        EXPECT_EQ(sectionCount(g, axis, i), count);
      }
    }
  }
}

TEST(Section, indexOutsideTheGridIsAnError) {
  const VoxelGrid g(Dims{4, 5, 6});
  auto s = computeSection(g, {Axis::kY, 5});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidArgument);
  EXPECT_NE(s.error().message.find("0..4"), std::string::npos) << s.error().message;
  EXPECT_FALSE(computeSection(g, {Axis::kZ, -1}).ok());
}

TEST(Section, renderShowsMaterialOutlineAndEmpty) {
  const VoxelGrid g = boxGrid(Dims{5, 5, 1}, {1, 1, 0}, {4, 4, 1});  // 3 x 3 square: one interior voxel
  auto s = computeSection(g, {Axis::kZ, 0});
  ASSERT_TRUE(s.ok());
  const ImageRgb img = io::sectionPicture(s->mask, 3);
  ASSERT_EQ(img.width, 15);
  ASSERT_EQ(img.height, 15);
  const Rgb8 empty = img.at(0, 0), outline = img.at(3, 3), material = img.at(7, 7);
  EXPECT_NE(empty, outline);
  EXPECT_NE(outline, material);
  EXPECT_NE(empty, material);
  EXPECT_EQ(img.at(8, 8), material);  // the whole 3x3 block of the interior voxel
  EXPECT_EQ(img.at(14, 14), empty);
  // The outline is darker than the material, which is darker than empty space.
  auto lum = [](Rgb8 c) { return int(c.r) + c.g + c.b; };
  EXPECT_LT(lum(outline), lum(material));
  EXPECT_LT(lum(material), lum(empty));
}

}  // namespace
}  // namespace vox
