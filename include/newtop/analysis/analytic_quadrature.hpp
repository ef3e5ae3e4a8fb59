#pragma once
/// \file
/// Quadrature of the angle rates of the integrable cases: ∫₀ᵗ f for a smooth f of period T, whole
/// periods by the trapezoidal rule (geometric convergence for periodic analytic integrands), the
/// remainder by adaptive Gauss–Kronrod (Boost.Math).

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>

namespace newtop {

/// ∫ of a T-periodic f over one period by the trapezoidal rule, the number of points doubled until
/// two estimates agree to a few ulps.
template <class Fn>
double integrate_one_period(Fn&& f, double period) {
  constexpr double kTolerance = 4 * std::numeric_limits<double>::epsilon();
  constexpr int kMaxPoints = 1 << 14;
  int n = 16;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += f(period * i / n);
  double estimate = sum * period / n;
  while (n < kMaxPoints) {
    for (int i = 0; i < n; ++i) sum += f(period * (2 * i + 1) / (2 * n));
    n *= 2;
    const double next = sum * period / n;
    const bool converged = std::abs(next - estimate) <= kTolerance * std::abs(next);
    estimate = next;
    if (converged) break;
  }
  return estimate;
}

/// ∫ f over [t0, t1] by adaptive Gauss–Kronrod 15. Boost's error estimate |K15 − G7| bounds the
/// 7-point Gauss error; the Kronrod result returned is far more accurate, so asking 1e-10 of the
/// estimate gives the integral to a few ulps.
template <class Fn>
double integrate_interval(Fn&& f, double t0, double t1) {
  constexpr double kTolerance = 1e-10;
  constexpr unsigned kDepth = 15;
  if (t0 == t1) return 0.0;
  return boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, t0, t1, kDepth,
                                                                       kTolerance);
}

/// ∫₀ᵗ f for f of period T (T = ∞ or 0: no periodicity used).
template <class Fn>
double integrate_periodic(Fn&& f, double period, double t) {
  if (!(std::isfinite(period) && period > 0) || std::abs(t) < period) {
    return integrate_interval(f, 0.0, t);
  }
  const double n = std::trunc(t / period);
  return n * integrate_one_period(f, period) + integrate_interval(f, n * period, t);
}

}  // namespace newtop
