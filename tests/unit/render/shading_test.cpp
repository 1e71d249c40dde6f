#include "vox/render/shading.h"

#include <cmath>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "vox/core/neighbour_code.h"

namespace vox::render {
namespace {

TEST(ClassicTable, isTheThesisTableOverTwenty) {
  const IntensityTable t = classicTable();
  EXPECT_FLOAT_EQ(t[0], 1.0f);            // isolated voxel: 20 (SPEC section 3)
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

TEST(PointSize, closesTheLargestGapOfAFaceLattice) {
  // A face seen head-on with the camera yawed 45 degrees: point centres on a square lattice of side s rotated by
  // 45 degrees; the point farthest from all centres is s / sqrt(2) from the nearest one in both x and y.
  EXPECT_NEAR(closedPointSize(2.0), 2.0 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(closedPointSize(10.0) / 2, 10.0 / std::sqrt(2.0), 1e-6);
  EXPECT_EQ(closedPointSize(0.3), 1.0);  // never below one pixel
  EXPECT_EQ(closedPointSize(0.0), 1.0);
}

}  // namespace
}  // namespace vox::render
