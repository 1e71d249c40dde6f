#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

#include "grids.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

using test::boxGrid;

// Solid box of extents (a, b, c) about its centre, unit density: diagonal inertia m (b^2 + c^2) / 12, ...
glm::dmat3 boxInertia(glm::dvec3 e) {
  const double m = e.x * e.y * e.z;
  glm::dmat3 i(0.0);
  i[0][0] = m * (e.y * e.y + e.z * e.z) / 12;
  i[1][1] = m * (e.x * e.x + e.z * e.z) / 12;
  i[2][2] = m * (e.x * e.x + e.y * e.y) / 12;
  return i;
}

// Inertia of a body of mass m about point p, when its own inertia about its centroid c is ic (parallel axes).
glm::dmat3 shifted(const glm::dmat3& ic, double m, glm::dvec3 c, glm::dvec3 p) {
  const glm::dvec3 d = c - p;
  glm::dmat3 out = ic;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) out[a][b] += m * ((a == b ? glm::dot(d, d) : 0.0) - d[a] * d[b]);
  return out;
}

void expectMatNear(const glm::dmat3& got, const glm::dmat3& want, double tol) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(got[a][b], want[a][b], tol) << a << "," << b;
}

TEST(Mass, boxIsExact) {
  const GridFrame frame{glm::dvec3(-1, 2, 3), 0.1, "mm", ""};
  const VoxelGrid g = boxGrid(Dims{100, 30, 20}, {10, 5, 2}, {80, 25, 12}, frame);  // 70 x 20 x 10 voxels
  const MassProperties m = computeMassProperties(g);
  EXPECT_EQ(m.filled, 14000);
  EXPECT_NEAR(m.volume, 7.0 * 2.0 * 1.0, 1e-12);
  const glm::dvec3 lo = frame.origin + glm::dvec3(10, 5, 2) * 0.1, hi = frame.origin + glm::dvec3(80, 25, 12) * 0.1;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(m.centroid[a], (lo[a] + hi[a]) / 2, 1e-12);
    EXPECT_NEAR(m.bbox.min[a], lo[a], 1e-12);
    EXPECT_NEAR(m.bbox.max[a], hi[a], 1e-12);
  }
  EXPECT_EQ(m.bbox_min_ijk, glm::ivec3(10, 5, 2));
  EXPECT_EQ(m.bbox_max_ijk, glm::ivec3(79, 24, 11));
  // A box of voxels is the box itself: the cube-per-voxel inertia is exact.
  expectMatNear(m.inertia, boxInertia(glm::dvec3(7, 2, 1)), 1e-10);
}

TEST(Mass, lShapeMatchesTheCompositeBody) {
  // Two boxes sharing no voxel: [0,40)x[0,10)x[0,10) and [0,10)x[10,50)x[0,10), voxel size 0.5.
  const GridFrame frame{glm::dvec3(0), 0.5, "model", ""};
  VoxelGrid g(Dims{64, 64, 16}, frame);
  test::fillBox(g, {0, 0, 0}, {40, 10, 10});
  test::fillBox(g, {0, 10, 0}, {10, 50, 10});
  const MassProperties m = computeMassProperties(g);
  const double h = 0.5;
  const glm::dvec3 e1 = glm::dvec3(40, 10, 10) * h, c1 = glm::dvec3(20, 5, 5) * h;
  const glm::dvec3 e2 = glm::dvec3(10, 40, 10) * h, c2 = glm::dvec3(5, 30, 5) * h;
  const double m1 = e1.x * e1.y * e1.z, m2 = e2.x * e2.y * e2.z;
  const glm::dvec3 c = (m1 * c1 + m2 * c2) / (m1 + m2);
  EXPECT_NEAR(m.volume, m1 + m2, 1e-9);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(m.centroid[a], c[a], 1e-12);
  const glm::dmat3 want = shifted(boxInertia(e1), m1, c1, c) + shifted(boxInertia(e2), m2, c2, c);
  expectMatNear(m.inertia, want, 1e-9 * want[0][0]);
  // Seen from its centroid, the L's mass lies at (+x, -y) and (-x, +y): sum x y < 0, and I_xy = -sum x y > 0.
  EXPECT_GT(m.inertia[0][1], 0.0);
}

TEST(Mass, productsOfInertiaCarryTheMinusSign) {
  // Two voxels on the xy diagonal: r = +-(h/2, h/2, 0) from the centroid, so I_xy = -sum m x y = -2 h^3 h^2 / 4.
  VoxelGrid g(Dims{2, 2, 1}, GridFrame{glm::dvec3(0), 2.0, "mm", ""});
  g.set(0, 0, 0);
  g.set(1, 1, 0);
  const MassProperties m = computeMassProperties(g);
  EXPECT_DOUBLE_EQ(m.inertia[0][1], -16.0);
  EXPECT_DOUBLE_EQ(m.inertia[1][0], -16.0);
  EXPECT_DOUBLE_EQ(m.inertia[0][2], 0.0);
  // I_zz = sum m (x^2 + y^2) + 2 h^5 / 6 = 2 * 8 * 2 + 2 * 32 / 6.
  EXPECT_DOUBLE_EQ(m.inertia[2][2], 32.0 + 64.0 / 6.0);
}

TEST(Mass, ballIsWithinTheDiscretisationBound) {
  const double h = 0.02, r_vox = 37.3;
  const GridFrame frame{glm::dvec3(1, 2, 3), h, "mm", ""};
  const glm::dvec3 c_vox(40.2, 41.7, 39.9);
  const VoxelGrid g = test::ballGrid(Dims{82, 84, 80}, c_vox, r_vox, frame);
  const MassProperties m = computeMassProperties(g);
  const double r = r_vox * h;
  const double volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_GT(m.volume_error_bound, 0.0);
  EXPECT_LE(std::abs(m.volume - volume), m.volume_error_bound);
  EXPECT_LT(std::abs(m.volume - volume), 0.01 * volume);  // the bound is not vacuous either
  // The centroid moves by at most (misclassified volume) x (distance) / volume.
  const glm::dvec3 centre = frame.origin + c_vox * h;
  const double centroid_bound = m.volume_error_bound * (r + h) / (volume - m.volume_error_bound);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(m.centroid[a], centre[a], centroid_bound);
  // Each misclassified voxel changes the inertia by at most its mass times (r + h)^2, plus the centroid shift.
  const double i_ball = 2.0 / 5.0 * volume * r * r;
  const double inertia_bound = m.volume_error_bound * (r + h) * (r + h) + volume * 3 * centroid_bound * centroid_bound;
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(m.inertia[a][a], i_ball, inertia_bound);
    for (int b = 0; b < 3; ++b) {
      if (a != b) {
        EXPECT_NEAR(m.inertia[a][b], 0.0, inertia_bound);
      }
    }
  }
}

TEST(Mass, matchesDirectSumsOnARandomGrid) {
  const GridFrame frame{glm::dvec3(5, -3, 0.25), 0.125, "mm", ""};
  VoxelGrid g = test::randomGrid(Dims{131, 17, 9}, 0.3, 11);
  g.frame() = frame;
  const MassProperties m = computeMassProperties(g);
  double n = 0;
  glm::dvec3 s(0);
  glm::ivec3 lo(1 << 30), hi(-1);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        if (g.get(x, y, z)) {
          n += 1;
          s += frame.voxelCentre(x, y, z);
          lo = glm::min(lo, glm::ivec3(x, y, z));
          hi = glm::max(hi, glm::ivec3(x, y, z));
        }
  const glm::dvec3 c = s / n;
  glm::dmat3 inertia(0.0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        if (g.get(x, y, z)) {
          const glm::dvec3 r = frame.voxelCentre(x, y, z) - c;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) inertia[a][b] += (a == b ? glm::dot(r, r) : 0.0) - r[a] * r[b];
        }
  const double h = frame.voxel_size;
  inertia *= h * h * h;
  for (int a = 0; a < 3; ++a) inertia[a][a] += n * std::pow(h, 5) / 6;
  EXPECT_EQ(m.filled, int64_t(n));
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(m.centroid[a], c[a], 1e-12);
  expectMatNear(m.inertia, inertia, 1e-10 * inertia[0][0]);
  EXPECT_EQ(m.bbox_min_ijk, lo);
  EXPECT_EQ(m.bbox_max_ijk, hi);
  EXPECT_DOUBLE_EQ(m.volume_error_bound, double(computeSurfaceStats(g).surface_voxels) * h * h * h);
}

TEST(Mass, emptyGrid) {
  const MassProperties m = computeMassProperties(VoxelGrid(Dims{3, 3, 3}));
  EXPECT_EQ(m.filled, 0);
  EXPECT_EQ(m.volume, 0.0);
  EXPECT_TRUE(m.bbox.empty());
  EXPECT_EQ(computeMassProperties(VoxelGrid()).filled, 0);
}

// A tensor built from known moments and axes gives them back, sorted ascending, as a right-handed frame.
TEST(PrincipalAxes, recoverTheMomentsAndAxesOfARotatedTensor) {
  const glm::dvec3 moments(1.0, 4.0, 9.0);
  const glm::dmat3 r = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3))));
  const glm::dmat3 tensor =
      r * glm::dmat3(glm::dvec3(moments[2], 0, 0), glm::dvec3(0, moments[0], 0), glm::dvec3(0, 0, moments[1])) *
      glm::transpose(r);
  const PrincipalAxes p = principalAxes(tensor);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.moments[i], moments[i], 1e-12) << i;
  // The axis of the smallest moment (1) is the rotated y axis, of 4 the rotated z, of 9 the rotated x (up to sign).
  EXPECT_NEAR(std::fabs(glm::dot(p.axes[0], r[1])), 1.0, 1e-12);
  EXPECT_NEAR(std::fabs(glm::dot(p.axes[1], r[2])), 1.0, 1e-12);
  EXPECT_NEAR(std::fabs(glm::dot(p.axes[2], r[0])), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(glm::cross(p.axes[0], p.axes[1]), p.axes[2]), 1.0, 1e-12);
}

TEST(Materials, densitiesByNameIgnoringCase) {
  EXPECT_EQ(materialDensity("Steel"), 7850.0);
  EXPECT_EQ(materialDensity("aluminum"), 2700.0);
  EXPECT_EQ(materialDensity("nylon"), 1010.0);
  EXPECT_FALSE(materialDensity("unobtainium").has_value());
}

}  // namespace
}  // namespace vox
