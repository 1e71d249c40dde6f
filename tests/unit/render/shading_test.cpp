#include "vox/render/shading.h"

#include <cmath>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "vox/core/neighbour_code.h"

namespace vox::render {
namespace {

TEST(ClassicTable, isTheThesisTableOverTwenty) {
  const IntensityTable t = classicTable();
  EXPECT_FLOAT_EQ(t[0], 1.0f);            // isolated voxel: 20 (docs/conventions.md, "Classic intensity table")
  EXPECT_FLOAT_EQ(t[2], 1.0f);            // 20
  EXPECT_FLOAT_EQ(t[28], 1.0f);           // the printed table's second "2"
  EXPECT_FLOAT_EQ(t[62], 17.0f / 20.0f);  // the table rules over Figure 5.2's 16
  EXPECT_FLOAT_EQ(t[30], 0.5f);
  EXPECT_FLOAT_EQ(t[63], 0.0f);
  for (int c = 0; c < 64; ++c) EXPECT_FLOAT_EQ(t[size_t(c)], float(kClassicIntensity[size_t(c)]) / 20.0f);
}

TEST(FreeFaceNormals, sumTheOutwardNormalsOfEmptyNeighbours) {
  EXPECT_EQ(freeFaceNormalSum(62), glm::dvec3(0, 0, 1));   // z+1 empty
  EXPECT_EQ(freeFaceNormalSum(31), glm::dvec3(0, -1, 0));  // y-1 empty
  EXPECT_EQ(freeFaceNormalSum(63 & ~8 & ~4), glm::dvec3(1, 1, 0));
  EXPECT_EQ(freeFaceNormalSum(63 & ~16 & ~8), glm::dvec3(0, 0, 0));  // x-1 and x+1 cancel
  EXPECT_EQ(freeFaceNormalSum(0), glm::dvec3(0, 0, 0));
  EXPECT_EQ(freeFaceNormalSum(63), glm::dvec3(0, 0, 0));
}

TEST(LitTable, isAmbientPlusDiffuseOfTheMeanFreeFaceNormal) {
  const double a = 0.2;
  const IntensityTable up = litTable({0, 0, 1}, a);
  EXPECT_FLOAT_EQ(up[62], 1.0f);      // +Z face, light along +Z
  EXPECT_FLOAT_EQ(up[61], float(a));  // -Z face: ambient only
  EXPECT_FLOAT_EQ(up[55], float(a));  // +X face, light grazing
  const uint8_t zy = 63 & ~1 & ~4;    // +Z and +Y free: normal (0, 1, 1) / sqrt 2
  EXPECT_FLOAT_EQ(up[zy], float(a + (1 - a) / std::sqrt(2.0)));
  const IntensityTable diag = litTable({0, 2, 2}, a);  // not unit length: normalised
  EXPECT_FLOAT_EQ(diag[zy], 1.0f);
  EXPECT_FLOAT_EQ(diag[62], float(a + (1 - a) / std::sqrt(2.0)));
  EXPECT_FLOAT_EQ(diag[63], 0.0f);
  // Cancelling free faces (a wall one voxel thick across X) take the best free face.
  const uint8_t wall_x = 63 & ~16 & ~8;
  EXPECT_FLOAT_EQ(litTable({-1, 0, 0}, a)[wall_x], 1.0f);
  EXPECT_FLOAT_EQ(litTable({0, 1, 0}, a)[wall_x], float(a));
  // An isolated voxel (all normals cancel) is lit by its face most turned to the light: here -Y.
  const glm::dvec3 l(0.3, -0.5, 0.2);
  EXPECT_FLOAT_EQ(litTable(l, a)[0], float(a + (1 - a) * 0.5 / std::sqrt(glm::dot(l, l))));
  for (int c = 0; c < 63; ++c) {
    EXPECT_GE(diag[size_t(c)], float(a));
    EXPECT_LE(diag[size_t(c)], 1.0f);
  }
}

Camera view(double yaw, double pitch, Projection proj = Projection::kOrthographic) {
  Camera c;
  c.yaw_deg = yaw;
  c.pitch_deg = pitch;
  c.projection = proj;
  return c;
}

TEST(PointSize, squarePointsCoverTheProjectedCube) {
  const double m = 1.02;                                                     // the documented margin
  EXPECT_NEAR(pointCoverageFactor(view(0, 0), false, 1.0), 1.0 * m, 1e-12);  // axis view: a cube is a square
  EXPECT_NEAR(pointCoverageFactor(view(90, 0), false, 1.0), 1.0 * m, 1e-12);
  EXPECT_NEAR(pointCoverageFactor(view(45, 90), false, 1.0), std::sqrt(2.0) * m, 1e-12);  // face turned 45 deg
  Camera iso;
  iso.projection = Projection::kOrthographic;
  iso.setStandardView(StandardView::kIso);
  // Iso: up = (-1, 2, -1) / sqrt 6 has the larger L1 norm, 4 / sqrt 6.
  EXPECT_NEAR(pointCoverageFactor(iso, false, 1.0), 4.0 / std::sqrt(6.0) * m, 1e-12);
}

TEST(PointSize, roundPointsCoverTheLongestProjectedDiagonal) {
  const double m = 1.02;
  EXPECT_NEAR(pointCoverageFactor(view(0, 0), true, 1.0), std::sqrt(2.0) * m, 1e-12);  // the square's diagonal
  Camera iso;
  iso.projection = Projection::kOrthographic;
  iso.setStandardView(StandardView::kIso);
  EXPECT_NEAR(pointCoverageFactor(iso, true, 1.0), std::sqrt(8.0 / 3.0) * m, 1e-12);
  // Never more than the cube's full diagonal, whatever the view.
  for (double yaw = -180; yaw < 180; yaw += 7.5)
    for (double pitch = -90; pitch <= 90; pitch += 7.5) {
      EXPECT_LE(pointCoverageFactor(view(yaw, pitch), true, 1.0), std::sqrt(3.0) * m + 1e-12);
      EXPECT_LE(pointCoverageFactor(view(yaw, pitch), false, 1.0), std::sqrt(3.0) * m + 1e-12);
      EXPECT_GE(pointCoverageFactor(view(yaw, pitch), false, 1.0), 1.0 * m - 1e-12);
    }
}

TEST(PointSize, perspectiveAddsTheOffAxisGrowthOfTheViewCorners) {
  const Camera c = view(0, 0, Projection::kPerspective);  // fov 30 degrees
  const double tan_corner = std::tan(15.0 * 3.14159265358979323846 / 180.0) * std::sqrt(2.0);
  EXPECT_NEAR(pointCoverageFactor(c, false, 1.0), 1.02 * std::sqrt(1 + tan_corner * tan_corner), 1e-12);
}

TEST(PointSize, isTheProjectedVoxelTimesTheFactorAndAtLeastOnePixel) {
  EXPECT_NEAR(closedPointSize(2.5, 1.4), 3.5, 1e-12);
  EXPECT_EQ(closedPointSize(0.3, 1.4), 1.0);
  EXPECT_EQ(closedPointSize(0.0, 1.0), 1.0);
}

}  // namespace
}  // namespace vox::render
