#pragma once
// Internal helpers of the exact field: the matrix of the cross product, and powers of
// 1/√(1 + t) minus their Taylor polynomials written without subtraction (the point-mass sums far
// from the body, docs/exact_field.md "Accuracy far from the body").

#include <cmath>

#include "newtop/core/types.hpp"

namespace newtop::detail {

/// [v]×, the matrix of v × ·.
inline Mat3 cross_matrix(const Vec3& v) {
  Mat3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

/// A number hi + lo carried to about twice the working precision (Dekker; Ogita, Rump & Oishi
/// 2005): error-free sums by TwoSum, error-free products by fma. Enough for sums whose terms are
/// products of a few exact inputs, such as the first moments of a body.
struct DoubleDouble {
  double hi = 0.0, lo = 0.0;
  double value() const { return hi + lo; }
};

inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b, z = s - a;
  return {s, (a - (s - z)) + (b - z)};
}

inline DoubleDouble two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
  DoubleDouble s = two_sum(a.hi, b.hi);
  s.lo += a.lo + b.lo;
  return two_sum(s.hi, s.lo);
}

inline DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi, -a.lo}; }

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
  DoubleDouble p = two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return two_sum(p.hi, p.lo);
}

/// With d² = s² (1 + t) and w = √(1 + t) > 0 (t > −1), the relative corrections of 1/d³ and 1/d⁵
/// to 1/s³ and 1/s⁵ in forms that keep their relative accuracy for small t:
/// w⁻³ − 1 = −t (w² + w + 1)/((1 + w) w³), w⁻⁵ − 1 = −t (w⁴ + w³ + w² + w + 1)/((1 + w) w⁵)
/// (from wⁿ − 1 = (w − 1)(wⁿ⁻¹ + … + 1) and w − 1 = t/(1 + w)).
struct InversePowers {
  double w;          ///< √(1 + t)
  double inv_w3;     ///< w⁻³
  double inv_w5;     ///< w⁻⁵
  double minus_1_3;  ///< w⁻³ − 1
  double minus_1_5;  ///< w⁻⁵ − 1
};

inline InversePowers inverse_powers(double t) {
  InversePowers p;
  p.w = std::sqrt(1.0 + t);
  const double w = p.w, w2 = w * w;
  p.inv_w3 = 1.0 / (w2 * w);
  p.inv_w5 = p.inv_w3 / w2;
  const double g = t / (1.0 + w);  // w − 1
  p.minus_1_3 = -g * (w2 + w + 1.0) * p.inv_w3;
  p.minus_1_5 = -g * ((w2 + w) * (w2 + 1.0) + 1.0) * p.inv_w5;
  return p;
}

}  // namespace newtop::detail
