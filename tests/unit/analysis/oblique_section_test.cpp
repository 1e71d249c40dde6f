// Sections at any angle against geometry worked out by hand: a ball's disc at every tilt and offset, a box's
// rectangle cut on the diagonal, the axis sections themselves, and bad planes refused.
#include "vox/analysis/oblique_section.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "grids.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

GridFrame frameOf(double h) {
  GridFrame f;
  f.origin = {-3.0, 1.5, 0.25};
  f.voxel_size = h;
  f.units = "mm";
  return f;
}

// A ball of radius 40 voxels (centred on a voxel's centre): the plane at distance d from its centre cuts a disc of
// area pi (r^2 - d^2), whatever the tilt, within the voxels' staircase (a few percent at this size).
TEST(ObliqueSection, aBallsDiscHasItsAreaAtEveryTiltAndOffset) {
  const double h = 0.5, r = 40.0;
  const VoxelGrid ball = test::ballGrid(Dims{96, 96, 96}, {48.5, 48.5, 48.5}, r, frameOf(h));
  const glm::dvec3 centre = frameOf(h).origin + glm::dvec3(48.5) * h;
  for (const glm::dvec3 n :
       {glm::dvec3(0, 0, 1), glm::dvec3(1, 1, 0), glm::dvec3(1, 1, 1), glm::dvec3(0.2, -0.7, 0.4)}) {
    for (const double d : {0.0, 15.0, 30.0}) {
      ObliqueSectionParams p;
      p.normal = n;
      p.point = centre + glm::normalize(n) * (d * h);
      p.point_given = true;
      auto s = computeObliqueSection(ball, p);
      ASSERT_TRUE(s.ok()) << s.error().message;
      const double expected = std::numbers::pi * (r * r - d * d) * h * h;
      EXPECT_NEAR(s->area, expected, 0.03 * expected) << "normal " << n.x << "," << n.y << "," << n.z << " d " << d;
      // The same plane given as the ball's centre and an offset along the normal: the same samples.
      ObliqueSectionParams q;
      q.normal = n;
      q.point = centre;
      q.point_given = true;
      q.offset = d * h;
      auto t = computeObliqueSection(ball, q);
      ASSERT_TRUE(t.ok());
      EXPECT_EQ(t->filled, s->filled);
      EXPECT_DOUBLE_EQ(s->area, double(s->filled) * h * h);
      EXPECT_NEAR(glm::dot(s->u, s->normal), 0.0, 1e-12);
      EXPECT_NEAR(glm::dot(s->v, s->normal), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(glm::cross(s->u, s->v) - s->normal), 0.0, 1e-12);  // right x up = normal
    }
  }
}

// A box cut on its vertical diagonal plane: a rectangle as tall as the box and as wide as its diagonal.
TEST(ObliqueSection, aBoxCutOnItsDiagonalIsARectangle) {
  const double h = 1.0;
  const VoxelGrid box = test::boxGrid(Dims{60, 60, 30}, {0, 0, 0}, {60, 60, 30});
  ObliqueSectionParams p;
  p.normal = {1.0, -1.0, 0.0};
  p.pixel = 0.25;
  auto s = computeObliqueSection(box, p);
  ASSERT_TRUE(s.ok()) << s.error().message;
  const double expected = 30.0 * 60.0 * std::sqrt(2.0) * h * h;
  EXPECT_NEAR(s->area, expected, 0.01 * expected);
  EXPECT_NEAR(s->v.z, 1.0, 1e-12) << "a vertical cut shows Z up";
}

// With an axis as the normal, through a row of voxel centres, the samples are the voxels of the axis section.
TEST(ObliqueSection, anAxisNormalGivesTheAxisSection) {
  const double h = 0.5;
  const VoxelGrid ball = test::ballGrid(Dims{40, 30, 20}, {20.0, 15.0, 10.0}, 9.0, frameOf(h));
  auto axis = computeSection(ball, SectionParams{Axis::kZ, 7});
  ASSERT_TRUE(axis.ok());
  ObliqueSectionParams p;
  p.normal = {0.0, 0.0, 2.0};
  p.point = frameOf(h).origin + glm::dvec3(20.0, 15.0, 7.5) * h;
  p.point_given = true;
  auto s = computeObliqueSection(ball, p);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->filled, axis->filled);
  EXPECT_EQ(s->mask.width, axis->mask.width);
  EXPECT_EQ(s->mask.height, axis->mask.height);
  EXPECT_EQ(s->mask.pixels, axis->mask.pixels);
}

TEST(ObliqueSection, badPlanesAreRefused) {
  const VoxelGrid g = test::boxGrid(Dims{8, 8, 8}, {2, 2, 2}, {6, 6, 6});
  ObliqueSectionParams p;
  p.normal = {0.0, 0.0, 0.0};
  EXPECT_EQ(computeObliqueSection(g, p).error().code, ErrorCode::kInvalidArgument);
  p.normal = {0.0, NAN, 1.0};
  EXPECT_EQ(computeObliqueSection(g, p).error().code, ErrorCode::kInvalidArgument);
  p.normal = {0.0, 0.0, 1.0};
  p.pixel = -1.0;
  EXPECT_EQ(computeObliqueSection(g, p).error().code, ErrorCode::kInvalidArgument);
  p.pixel = 1e308;  // one sample for the whole model (and steps of 1e308 / h voxels: never sampled)
  EXPECT_EQ(computeObliqueSection(g, p).error().code, ErrorCode::kInvalidArgument);
  p.pixel = 1e-300;  // 1e300-odd samples a side: said without converting that to an integer
  EXPECT_EQ(computeObliqueSection(g, p).error().code, ErrorCode::kLimit);
  p.pixel = 1e-6;  // 8e6 x 8e6 samples
  auto big = computeObliqueSection(g, p);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.error().code, ErrorCode::kLimit);
  EXPECT_NE(big.error().message.find("larger pixel size"), std::string::npos);
}

}  // namespace
}  // namespace vox
