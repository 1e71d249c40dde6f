// The exact orientation predicates (src/voxelize/exact_predicates.h) against integer arithmetic.
#include "voxelize/exact_predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vox::voxelize_detail {
namespace {

// Dyadic test coordinates: integers times 2^-20 below 2^10 in magnitude, so every determinant is an exact integer
// times 2^-40 (2D) or 2^-60 (3D) that fits in __int128 after scaling.
constexpr double kScale = 1048576.0;  // 2^20
__extension__ typedef __int128 Int;   // __extension__: a GCC type, fine for a test under -Wpedantic

int sign(Int v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }
Int scaled(double v) { return Int(std::llround(v * kScale)); }

int orient2dInt(double a0, double a1, double b0, double b1, double c0, double c1) {
  const Int ax = scaled(a0) - scaled(c0), ay = scaled(a1) - scaled(c1);
  const Int bx = scaled(b0) - scaled(c0), by = scaled(b1) - scaled(c1);
  return sign(ax * by - ay * bx);
}

int orient3dInt(const double a[3], const double b[3], const double c[3], const double d[3]) {
  Int ad[3], bd[3], cd[3];
  for (int i = 0; i < 3; ++i) {
    ad[i] = scaled(a[i]) - scaled(d[i]);
    bd[i] = scaled(b[i]) - scaled(d[i]);
    cd[i] = scaled(c[i]) - scaled(d[i]);
  }
  return sign(ad[0] * (bd[1] * cd[2] - bd[2] * cd[1]) - ad[1] * (bd[0] * cd[2] - bd[2] * cd[0]) +
              ad[2] * (bd[0] * cd[1] - bd[1] * cd[0]));
}

class Dyadic {
 public:
  explicit Dyadic(uint32_t seed) : rng_(seed) {}
  double coordinate() { return double(std::uniform_int_distribution<int64_t>(-(1 << 29), 1 << 29)(rng_)) / kScale; }
  int64_t small(int64_t n) { return std::uniform_int_distribution<int64_t>(-n, n)(rng_); }

 private:
  std::mt19937_64 rng_;
};

// Points on a line (and then nudged by a few units of 2^-20) defeat the floating-point filter: the exact stage
// must then agree with integer arithmetic, exactly zero included.
TEST(ExactPredicates, orient2dMatchesIntegerArithmeticOnNearlyCollinearPoints) {
  Dyadic g(7);
  int zeros = 0, exact_needed = 0;
  for (int i = 0; i < 20000; ++i) {
    const double a0 = g.coordinate(), a1 = g.coordinate();
    const double d0 = double(g.small(1 << 8)) / 64.0, d1 = double(g.small(1 << 8)) / 64.0;
    const double t = double(g.small(64)) / 16.0;
    const double c0 = a0 + t * d0 + double(g.small(2)) / kScale, c1 = a1 + t * d1 + double(g.small(2)) / kScale;
    const double b0 = a0 + d0, b1 = a1 + d1;
    const int expected = orient2dInt(a0, a1, b0, b1, c0, c1);
    ASSERT_EQ(orient2d(a0, a1, b0, b1, c0, c1), expected) << i;
    ASSERT_EQ(orient2dExact(a0, a1, b0, b1, c0, c1), expected) << i;
    zeros += expected == 0;
    const double left = (a0 - c0) * (b1 - c1), right = (a1 - c1) * (b0 - c0);
    exact_needed += std::abs(left - right) <= kOrient2dBound * (std::abs(left) + std::abs(right));
  }
  EXPECT_GT(zeros, 500);
  EXPECT_GE(exact_needed, zeros);
}

// Large coordinates (up to 2^31, on the 2^-20 grid: 51 significant bits) with a nudge of one grid unit: the
// determinant is far below the filter's bound, so the exact stage decides nonzero signs too.
TEST(ExactPredicates, orient2dExactStageDecidesNonzeroSignsBelowTheFilterBound) {
  Dyadic g(5);
  int exact_nonzero = 0;
  for (int i = 0; i < 20000; ++i) {
    const double a0 = double(g.small(int64_t(1) << 51)) / kScale, a1 = double(g.small(int64_t(1) << 51)) / kScale;
    const double d0 = double(g.small(int64_t(1) << 50)) / kScale, d1 = double(g.small(int64_t(1) << 50)) / kScale;
    const double t = double(g.small(2));
    const double c0 = a0 + t * d0, c1 = a1 + t * d1 + double(g.small(1)) / kScale;
    const double b0 = a0 + d0, b1 = a1 + d1;
    const int expected = orient2dInt(a0, a1, b0, b1, c0, c1);
    ASSERT_EQ(orient2d(a0, a1, b0, b1, c0, c1), expected) << i;
    ASSERT_EQ(orient2dExact(a0, a1, b0, b1, c0, c1), expected) << i;
    const double left = (a0 - c0) * (b1 - c1), right = (a1 - c1) * (b0 - c0);
    exact_nonzero += expected != 0 && std::abs(left - right) <= kOrient2dBound * (std::abs(left) + std::abs(right));
  }
  EXPECT_GT(exact_nonzero, 100);
}

TEST(ExactPredicates, orient3dMatchesIntegerArithmeticOnNearlyCoplanarPoints) {
  Dyadic g(11);
  int zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    double a[3], b[3], c[3], d[3];
    const double s = double(g.small(32)) / 8.0, t = double(g.small(32)) / 8.0;
    for (int k = 0; k < 3; ++k) {
      a[k] = double(g.small(1 << 23)) / kScale;  // below 8: the 3D determinant stays within __int128 after scaling
      b[k] = a[k] + double(g.small(1 << 10)) / 256.0;
      c[k] = a[k] + double(g.small(1 << 10)) / 256.0;
      d[k] = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]) + double(g.small(1)) / kScale;
    }
    const int expected = orient3dInt(a, b, c, d);
    ASSERT_EQ(orient3d(a, b, c, d), expected) << i;
    ASSERT_EQ(orient3dExact(a, b, c, d), expected) << i;
    zeros += expected == 0;
  }
  EXPECT_GT(zeros, 500);
}

// Mixed magnitudes as in STL files exported with noise (featuretype: 0 vs 1e-35 next to 2.5): the differences are
// not representable in double, but the exact stage still gets the sign right.
TEST(ExactPredicates, mixedMagnitudesAreExact) {
  const double tiny = double(1e-35f);
  // c = 2 b exactly: collinear with the origin.
  EXPECT_EQ(orient2d(0.0, 0.0, 2.5, tiny, 5.0, 2.0 * tiny), 0);
  EXPECT_EQ(orient2d(0.0, 0.0, 2.5, tiny, 5.0, 2.0 * tiny * (1 + 1e-15)), 1);
  EXPECT_EQ(orient2d(0.0, 0.0, 2.5, tiny, 5.0, 2.0 * tiny * (1 - 1e-15)), -1);
  // A point on the plane z = tiny * x, one just above, one just below.
  const double a[3] = {0, 0, 0}, b[3] = {2.5, 0, 2.5 * tiny}, c[3] = {0, 1, 0};
  const double on[3] = {1.0, 0.375, tiny}, above[3] = {1.0, 0.375, tiny * (1 + 1e-15)};
  const double below[3] = {1.0, 0.375, tiny * (1 - 1e-15)};
  EXPECT_EQ(orient3d(a, b, c, on), 0);
  EXPECT_EQ(orient3d(a, b, c, above), -orient3d(a, b, c, below));
  EXPECT_NE(orient3d(a, b, c, above), 0);
  // Shifting every point by a large offset that makes the differences inexact changes nothing.
  const double big = 1234567.125;
  const double a2[3] = {big, big, big}, b2[3] = {big + 2.5, big, big + 2.5 * tiny}, c2[3] = {big, big + 1, big};
  const double on2[3] = {big + 1.0, big + 0.375, big + tiny};
  EXPECT_EQ(orient3d(a2, b2, c2, on2), orient3dExact(a2, b2, c2, on2));
}

TEST(ExactPredicates, swappingTwoPointsNegatesTheSign) {
  Dyadic g(3);
  for (int i = 0; i < 2000; ++i) {
    const double a0 = g.coordinate(), a1 = g.coordinate(), b0 = g.coordinate(), b1 = g.coordinate();
    const double t = double(g.small(8)) / 4.0;
    const double c0 = a0 + t * (b0 - a0), c1 = a1 + t * (b1 - a1) + double(g.small(1)) / kScale;
    ASSERT_EQ(orient2d(a0, a1, b0, b1, c0, c1), -orient2d(b0, b1, a0, a1, c0, c1));
  }
}

}  // namespace
}  // namespace vox::voxelize_detail
