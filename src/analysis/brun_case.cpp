#include "newtop/analysis/brun_case.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "newtop/analysis/analytic_quadrature.hpp"

namespace newtop {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
// G is monotone and its root lies within a few turns of the mean-motion guess.
constexpr int kBracketSteps = 64;
/// 2^53: a phase of that size has a unit in the last place of 2 rad (no digit of the angle left).
constexpr double kPhaseLimit = 9007199254740992.0;
// Frequencies are accurate to ~1e-12 (trapezoidal periods to a few ulps, then a 2×2 solve);
// a ratio within 1e-9 of p/q with q, p ≤ 20 is reported as a resonance.
constexpr double kResonanceTolerance = 1e-9;
constexpr int kResonanceOrder = 20;

/// uⁿ / √R̃_s along the angle φ.
auto integrand(const BrunCase& b, int s, int n) {
  return [&b, s, n](double phi) {
    const double u = brun_u_at(b.curve, s, phi);
    return (n == 0 ? 1.0 : u) / std::sqrt(brun_reduced_R_at(b.curve, s, phi));
  };
}

void set_frequencies(BrunCase& b) {
  for (int s = 0; s < 2; ++s) {
    for (int n = 0; n < 2; ++n) b.period[n][s] = integrate_one_period(integrand(b, s, n), kTwoPi);
  }
  // M = [σ_s Ω_s^(n)], mean rates of φ_s / 2π = M⁻¹ (2/κ, 0).
  const double m00 = kBrunOrientation[0] * b.period[0][0];
  const double m01 = kBrunOrientation[1] * b.period[0][1];
  const double m10 = kBrunOrientation[0] * b.period[1][0];
  const double m11 = kBrunOrientation[1] * b.period[1][1];
  const double det = m00 * m11 - m01 * m10;
  const double rhs = 2 / b.curve.kappa;
  b.frequency = {kTwoPi * m11 * rhs / det, -kTwoPi * m10 * rhs / det};
  b.resonance = brun_resonance(b.frequency[0], b.frequency[1]);
}

}  // namespace

BrunCase brun_case(const QuadraticModel& model, const State& x0) {
  BrunCase b;
  b.curve = brun_curve(model, x0);
  b.initial = brun_angles(b.curve, x0);
  set_frequencies(b);
  b.abel0 = brun_abel_map(b, b.initial.phi);
  for (int s = 0; s < 2; ++s) {
    for (int i = 0; i < 3; ++i) {
      b.flips[s][b.curve.axis[i]] = b.curve.lower[s] == i || b.curve.upper[s] == i;
    }
  }
  return b;
}

double brun_abel_integral(const BrunCase& b, int s, int n, double phi) {
  const double turns = std::round(phi / kTwoPi);
  const double rest = phi - turns * kTwoPi;  // in [−π, π]
  const auto f = integrand(b, s, n);
  const double part =
      rest >= 0 ? integrate_interval(f, 0.0, rest) : -integrate_interval(f, rest, 0.0);
  return turns * b.period[n][s] + part;
}

std::array<double, 2> brun_abel_map(const BrunCase& b, const std::array<double, 2>& phi) {
  std::array<double, 2> U{};
  for (int n = 0; n < 2; ++n) {
    for (int s = 0; s < 2; ++s) U[n] += kBrunOrientation[s] * brun_abel_integral(b, s, n, phi[s]);
  }
  return U;
}

std::array<double, 2> brun_abel_sums(const BrunCase& b, const std::array<double, 2>& phi) {
  const auto U = brun_abel_map(b, phi);
  return {0.5 * b.curve.kappa * (U[0] - b.abel0[0]), U[1] - b.abel0[1]};
}

void brun_check_time(const BrunCase& b, double t) {
  const double phase = std::max(std::abs(b.frequency[0] * t), std::abs(b.frequency[1] * t));
  if (!std::isfinite(t) || !(phase < kPhaseLimit)) {
    throw InputError(
        "times: expected times whose phases omega*t stay below 2^53 (beyond, no "
        "digit of the angle remains in double precision), found t = " +
        format_number(t) + " (omega*t = " + format_number(phase) + ")");
  }
}

std::array<double, 2> brun_angles_at(const BrunCase& b, double t) {
  brun_check_time(b, t);
  static_assert(kBrunOrientation[0] == -1.0 && kBrunOrientation[1] == 1.0);
  // U_0 = −A_1^(0)(φ1) + A_2^(0)(φ2) = T0 gives φ2(φ1), increasing (A^(0) increases); then
  // G(φ1) = U_1(φ1, φ2(φ1)) − T1 has G′ = (u2 − u1)/√R̃1 > 0: two monotone one-dimensional
  // solves, each by safeguarded Newton inside a bracket (Boost.Math), whatever the distance of
  // the start from the solution (near a separatrix the angles are far from uniform).
  const double T0 = b.abel0[0] + 2 * t / b.curve.kappa, T1 = b.abel0[1];
  const int digits = std::numeric_limits<double>::digits - 2;
  auto phi2_of = [&](double phi1) {
    const double y = T0 + brun_abel_integral(b, 0, 0, phi1);  // A_2^(0)(φ2) = y
    const double mean = kTwoPi * y / b.period[0][1];          // |A − Ω φ/2π| < Ω
    auto f = [&](double p) {
      return std::make_pair(brun_abel_integral(b, 1, 0, p) - y,
                            1 / std::sqrt(brun_reduced_R_at(b.curve, 1, p)));
    };
    return boost::math::tools::newton_raphson_iterate(f, mean, mean - kTwoPi, mean + kTwoPi,
                                                      digits);
  };
  auto G = [&](double phi1) {
    const double phi2 = phi2_of(phi1);
    const double g = -brun_abel_integral(b, 0, 1, phi1) + brun_abel_integral(b, 1, 1, phi2) - T1;
    const double u1 = brun_u_at(b.curve, 0, phi1), u2 = brun_u_at(b.curve, 1, phi2);
    return std::make_pair(g, (u2 - u1) / std::sqrt(brun_reduced_R_at(b.curve, 0, phi1)));
  };
  // Bracket the root of G from the mean-motion guess, in steps of 2π.
  const double guess = b.initial.phi[0] + b.frequency[0] * t;
  const double g0 = G(guess).first;
  if (g0 == 0.0) return {guess, phi2_of(guess)};
  const double dir = g0 > 0 ? -1.0 : 1.0;
  double near = guess, far = guess + dir * kTwoPi;
  for (int i = 0; i < kBracketSteps && (G(far).first > 0) == (g0 > 0); ++i) {
    near = far, far += dir * kTwoPi;
  }
  if ((G(far).first > 0) == (g0 > 0)) {
    throw std::runtime_error("brun: the Abel inversion found no bracket at t = " +
                             std::to_string(t));
  }
  const double lo = std::min(near, far), hi = std::max(near, far);
  const double phi1 =
      boost::math::tools::newton_raphson_iterate(G, 0.5 * (lo + hi), lo, hi, digits);
  return {phi1, phi2_of(phi1)};
}

State brun_state(const BrunCase& b, double t) {
  BrunAngles a = b.initial;
  a.phi = brun_angles_at(b, t);
  return brun_state_at(b.curve, a);
}

std::optional<BrunResonance> brun_resonance(double w1, double w2) {
  // Continued-fraction convergents q/p of ω1/ω2 (q ω1 ≈ p ω2 means ω1 : ω2 = p : q).
  double x = w1 / w2;
  double h0 = 1, h1 = 0, k0 = 0, k1 = 1;  // convergents h/k of ω1/ω2 (small integers)
  for (int it = 0; it < 40; ++it) {
    const double a = std::floor(x);
    const double h = a * h0 + h1, k = a * k0 + k1;
    if (h > kResonanceOrder || k > kResonanceOrder) break;
    const double defect = std::abs(k * w1 - h * w2) / (w1 + w2);
    if (defect <= kResonanceTolerance) {
      return BrunResonance{static_cast<int>(h), static_cast<int>(k), defect};
    }
    h1 = h0, h0 = h, k1 = k0, k0 = k;
    if (x - a == 0.0) break;
    x = 1.0 / (x - a);
  }
  return std::nullopt;
}

}  // namespace newtop
