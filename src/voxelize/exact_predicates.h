#pragma once
// Exact signs of the 2D and 3D orientation determinants for double inputs.
//
// Builds on J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
// Discrete & Computational Geometry 18(3), 1997: a plain floating-point evaluation is accepted when it exceeds the
// paper's forward error bound (ccwerrboundA, o3derrboundA); otherwise the determinant is expanded into a sum of
// exact products (fma two-product) and summed exactly as a nonoverlapping expansion (Grow-Expansion with zero
// elimination), whose sign is the sign of its largest component. Only the first and the last stage of the paper's
// adaptive scheme are used: the exact stage runs only for (near-)degenerate inputs, i.e. rarely.
//
// Assumes no overflow and no underflow in the products (coordinates between about 1e-70 and 1e70 in magnitude, or
// zero), which holds for float32 STL vertices and voxel centres derived from them.

#include <cmath>

namespace vox::voxelize_detail {

// The exact stages alone (the filtered versions below call them; tests compare the two on every input).
int orient2dExact(double a0, double a1, double b0, double b1, double c0, double c1);
int orient3dExact(const double a[3], const double b[3], const double c[3], const double d[3]);

// Half an ulp of 1: the unit roundoff of round-to-nearest double arithmetic.
inline constexpr double kUnitRoundoff = 1.1102230246251565e-16;  // 2^-53
// Forward error bounds of the plain evaluations (Shewchuk 1997, section 4.3), relative to the permanent.
inline constexpr double kOrient2dBound = (3.0 + 16.0 * kUnitRoundoff) * kUnitRoundoff;
inline constexpr double kOrient3dBound = (7.0 + 56.0 * kUnitRoundoff) * kUnitRoundoff;

// Sign (-1, 0, +1) of det[a - c; b - c] = (a0 - c0)(b1 - c1) - (a1 - c1)(b0 - c0): +1 when a, b, c turn
// counter-clockwise in the (0, 1) coordinate plane. Inline: the voxelizer calls it three times per ray and triangle.
inline int orient2d(double a0, double a1, double b0, double b1, double c0, double c1) {
  const double left = (a0 - c0) * (b1 - c1);
  const double right = (a1 - c1) * (b0 - c0);
  const double det = left - right;
  const double bound = kOrient2dBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // |det| <= bound. When both products are exactly zero so is the determinant (a difference of doubles rounds to
  // zero only when it is zero); otherwise the sign needs exact arithmetic.
  if (left == 0.0 && right == 0.0) return 0;
  return orient2dExact(a0, a1, b0, b1, c0, c1);
}

// Sign (-1, 0, +1) of det[a - d; b - d; c - d] (rows). Equals -sign(n . (d - a)) with n = (b - a) x (c - a).
inline int orient3d(const double a[3], const double b[3], const double c[3], const double d[3]) {
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  const double bound = kOrient3dBound * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  if (permanent == 0.0) return 0;  // every product is exactly zero (see orient2d)
  return orient3dExact(a, b, c, d);
}

}  // namespace vox::voxelize_detail
