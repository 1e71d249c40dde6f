// Exact orientation predicates: floating-point filter plus exact expansion arithmetic.
// After J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates",
// Discrete & Computational Geometry 18(3):305-363, 1997 (error bounds of section 4, Two-Sum, Two-Product and
// Grow-Expansion of section 2). Written for voxmod; the two-product uses fma instead of Dekker's splitting.
#include "voxelize/exact_predicates.h"

#include <array>
#include <cmath>
#include <cstdlib>

namespace vox::voxelize_detail {
namespace {

// a + b = s + e exactly (Knuth's Two-Sum: no precondition on the magnitudes).
inline void twoSum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}

// a * b = p + e exactly (barring underflow): fma computes the rounding error of the product.
inline void twoProduct(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

// An exactly represented sum of doubles: a nonoverlapping expansion, smallest component first, zeros removed.
// Adding a double is Shewchuk's Grow-Expansion; the sign of the sum is the sign of the largest component.
class ExactSum {
 public:
  void add(double b) {
    double q = b;
    int m = 0;
    for (int i = 0; i < n_; ++i) {
      double s, e;
      twoSum(q, c_[size_t(i)], s, e);
      q = s;
      if (e != 0.0) c_[size_t(m++)] = e;
    }
    if (q != 0.0) c_[size_t(m++)] = q;
    n_ = m;
  }
  // Adds the exact product a * b * c (four doubles).
  void addProduct3(double a, double b, double c) {
    double p, e;
    twoProduct(a, b, p, e);
    double p1, e1, p2, e2;
    twoProduct(p, c, p1, e1);
    twoProduct(e, c, p2, e2);
    add(e2);
    add(e1);
    add(p2);
    add(p1);
  }
  // Adds the exact product a * b (two doubles).
  void addProduct2(double a, double b) {
    double p, e;
    twoProduct(a, b, p, e);
    add(e);
    add(p);
  }
  int sign() const { return n_ == 0 ? 0 : (c_[size_t(n_ - 1)] > 0.0 ? 1 : -1); }

 private:
  // Each add() grows the expansion by at most one component; the largest caller adds 192 doubles.
  std::array<double, 256> c_{};
  int n_ = 0;
};

// x - y as an exact two-component value hi + lo.
struct Diff {
  double hi, lo;
};
inline Diff exactDiff(double x, double y) {
  Diff d;
  twoSum(x, -y, d.hi, d.lo);
  return d;
}

}  // namespace

int orient2dExact(double a0, double a1, double b0, double b1, double c0, double c1) {
  const Diff ac0 = exactDiff(a0, c0), ac1 = exactDiff(a1, c1), bc0 = exactDiff(b0, c0), bc1 = exactDiff(b1, c1);
  const double l0[2] = {ac0.hi, ac0.lo}, l1[2] = {bc1.hi, bc1.lo};
  const double r0[2] = {ac1.hi, ac1.lo}, r1[2] = {bc0.hi, bc0.lo};
  ExactSum sum;
  for (double x : l0)
    for (double y : l1) sum.addProduct2(x, y);
  for (double x : r0)
    for (double y : r1) sum.addProduct2(-x, y);
  return sum.sign();
}

int orient3dExact(const double a[3], const double b[3], const double c[3], const double d[3]) {
  Diff ad[3], bd[3], cd[3];
  for (int i = 0; i < 3; ++i) {
    ad[i] = exactDiff(a[i], d[i]);
    bd[i] = exactDiff(b[i], d[i]);
    cd[i] = exactDiff(c[i], d[i]);
  }
  // det = sum over the six permutations (p, q, r) of sign * ad[p] * bd[q] * cd[r]; every factor has two exact
  // components, so each term is eight exact triple products.
  static constexpr int kPerm[6][4] = {{0, 1, 2, 1}, {0, 2, 1, -1}, {1, 0, 2, -1},
                                      {1, 2, 0, 1}, {2, 0, 1, 1},  {2, 1, 0, -1}};
  ExactSum sum;
  for (const auto& p : kPerm) {
    const double x[2] = {ad[p[0]].hi, ad[p[0]].lo};
    const double y[2] = {bd[p[1]].hi, bd[p[1]].lo};
    const double z[2] = {cd[p[2]].hi, cd[p[2]].lo};
    for (double xi : x) {
      if (xi == 0.0) continue;
      for (double yi : y) {
        if (yi == 0.0) continue;
        for (double zi : z) {
          if (zi == 0.0) continue;
          sum.addProduct3(p[3] > 0 ? xi : -xi, yi, zi);
        }
      }
    }
  }
  return sum.sign();
}

}  // namespace vox::voxelize_detail
