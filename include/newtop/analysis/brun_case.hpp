#pragma once
/// \file
/// Brun's case on the level f = 0 solved by quadratures: the Abel–Jacobi relations of the
/// separated motion (brun_curve.hpp, brun_separation.hpp) and their inversion.
///
/// The Hamilton–Jacobi equation separates with p_s² = −N(u_s)/(4P(u_s)); differentiating the
/// complete integral in h and c gives
///   (κ/2) Σ_s ∫^{u_s} du/w = t + τ0,   Σ_s ∫^{u_s} u du/w = η0,   w² = R(u),
/// the integrals taken along the motion (w changes sign at each turning value). In the angles
/// φ_s, du/w = σ_s dφ/√R̃_s(u(φ)), so with
///   A_s^(n)(φ) = ∫_0^φ u(ϑ)ⁿ dϑ / √R̃_s(u(ϑ))   (smooth: the endpoint singularities are gone)
/// the Abel map U(φ1, φ2) = Σ_s σ_s (A_s^(0)(φ_s), A_s^(1)(φ_s)) equals (2t/κ + U0_0, U0_1). Its
/// inversion (safeguarded Newton, see brun_angles_at; A_s by Gauss–Kronrod, whole periods by the
/// trapezoidal rule) gives
/// φ_s(t) and the state. The real periods Ω_s^(n) = A_s^(n)(2π) = 2∫_{a_s}^{b_s} uⁿ du/√R form the
/// period matrix M = [σ_s Ω_s^(n)]; the mean rates of φ_s, the torus frequencies, are
/// ω = 2π M⁻¹ (2/κ, 0).

#include <array>
#include <optional>

#include "newtop/analysis/brun_separation.hpp"

namespace newtop {

/// A resonance p ω1 = q ω2 (to the tolerance of the frequencies).
struct BrunResonance {
  int p = 0, q = 0;
  double defect = 0;  ///< |p ω1 − q ω2| / (ω1 + ω2)
};

/// The resonance of two positive frequencies: a ratio ω1/ω2 within 1e-9 of p/q with p, q ≤ 20
/// (continued-fraction convergents), or none.
std::optional<BrunResonance> brun_resonance(double w1, double w2);

/// The motion on one level (data only).
struct BrunCase {
  BrunCurve curve;
  BrunAngles initial;                             ///< angles and signs at t = 0
  std::array<double, 2> abel0{};                  ///< U(φ(0))
  std::array<std::array<double, 2>, 2> period{};  ///< period[n][s] = Ω_s^(n)
  std::array<double, 2> frequency{};              ///< ω_s, mean dφ_s/dt (rad per unit time)
  std::optional<BrunResonance> resonance;         ///< set when ω1/ω2 is a ratio of small integers
  /// flips[s][i]: γ_i (body axis i) changes sign at each turn of φ_s (e_i bounds the range).
  std::array<std::array<bool, 3>, 2> flips{};
};

/// The solution from x0 (throws InputError as brun_curve does).
BrunCase brun_case(const QuadraticModel& model, const State& x0);

/// A_s^(n)(φ) for any real φ (whole periods plus a Gauss–Kronrod remainder).
double brun_abel_integral(const BrunCase& b, int s, int n, double phi);

/// The Abel map U(φ1, φ2).
std::array<double, 2> brun_abel_map(const BrunCase& b, const std::array<double, 2>& phi);

/// The Abel–Jacobi sums normalised: (κ/2)(U_0 − U0_0) = t and U_1 − U0_1 = 0 along the motion.
std::array<double, 2> brun_abel_sums(const BrunCase& b, const std::array<double, 2>& phi);

/// The unwrapped angles φ_s(t): U_0 = T0 fixes φ2 as an increasing function of φ1, and U_1
/// along that curve increases with φ1 (derivative (u2 − u1)/√R̃1): two nested monotone
/// one-dimensional solves by safeguarded Newton (Boost.Math) inside brackets.
/// Throws InputError naming `times` for a finite t whose phases ω_s t reach 2^53: no digit of the
/// angles remains in double precision (and the brackets of 2π no longer separate doubles).
std::array<double, 2> brun_angles_at(const BrunCase& b, double t);

/// The check of brun_angles_at alone, so that a caller can refuse a list of times before any work.
void brun_check_time(const BrunCase& b, double t);

/// The state at time t.
State brun_state(const BrunCase& b, double t);

}  // namespace newtop
