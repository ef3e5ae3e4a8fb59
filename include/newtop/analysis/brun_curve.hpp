#pragma once
/// \file
/// Brun's case (docs/model.md §5: r0 = 0, k = 0, V = ½λ γ·Iγ) on the level f = m·γ = 0: the genus-2
/// curve of its separation in sphero-conic coordinates on the Poisson sphere (Weber, Kharlamova).
///
/// In a working frame (a signed permutation of the principal axes, det = +1) with the moments
/// ascending, let κ = ABC, e_i = −κ/I_i (e1 < e2 < e3 < 0) and P(u) = (u − e1)(u − e2)(u − e3). The
/// separating variables u1 ∈ [e1, e2], u2 ∈ [e2, e3] are the roots of Σ γ_i²/(u − e_i) = 0. With
/// h = energy and c = Brun's integral I4,
///   N(u) = λu² + (c − λ(e1 + e2 + e3)) u + 2κh = λ P(u) Σ γ_i²/(u − e_i) + Σ m_i² (u − e_i),
/// and on f = 0 each u_s obeys w_s² = R(u_s), R(u) = −P(u) N(u): a quintic, so the curve w² = R(u)
/// is hyperelliptic of genus 2 (λ ≠ 0). u_s oscillates in a range [a_s, b_s] bounded by two
/// consecutive roots of R (the e_i and the roots ν of N) where R ≥ 0.

#include <array>
#include <complex>

#include "newtop/model/basic_model.hpp"

namespace newtop {

/// The curve of one level, with the working frame and the oscillation ranges (data only).
struct BrunCurve {
  std::array<int, 3> axis{};     ///< working component k is body component axis[k]
  std::array<double, 3> sign{};  ///< ... times sign[k] (so that the frame has det = +1)
  Vec3 inertia;                  ///< working-frame moments, ascending
  double kappa = 0;              ///< ABC
  double lambda_ = 0;            ///< λ
  double h = 0, c = 0, f = 0;    ///< energy, Brun's integral I4, area m·γ
  std::array<double, 3> e{};     ///< e_i = −κ/I_i, ascending
  std::array<double, 2> nu{};    ///< roots of N, ascending
  /// The five finite roots of R: root[0..2] = e1, e2, e3 and root[3..4] = ν1, ν2 (∞ is the sixth
  /// branch point).
  std::array<double, 5> root{};
  std::array<double, 6> coefficient{};  ///< R(u) = Σ coefficient[i] uⁱ
  /// Range of u_s: [root[lower[s]], root[upper[s]]].
  std::array<int, 2> lower{}, upper{};
};

/// u1 ≤ u2, the roots of Σ γ_i²/(u − e_i) = 0 for a working-frame γ (written in u − e2, whose
/// discriminant is a sum of squares: no cancellation).
std::array<double, 2> brun_u(const BrunCurve& k, const Vec3& gamma);

/// Body → working frame and back.
State to_working_frame(const BrunCurve& k, const State& s);
State from_working_frame(const BrunCurve& k, const State& s);

/// The working frame, the integrals h, c, f, the e_i, the roots ν of N and the coefficients of
/// −P N of the level through x0, on any level f (the ranges are left unset: they belong to
/// f = 0). Throws InputError unless Brun's case holds, λ ≠ 0, the moments are distinct and
/// |γ| = 1.
BrunCurve brun_level(const QuadraticModel& model, const State& x0);

/// The curve and ranges of the level through x0. Throws InputError unless Brun's case holds
/// (brun_holds), λ ≠ 0, the moments are distinct, |γ| = 1 and m·γ = 0 (to 1e-12 relative): the
/// level f ≠ 0 needs Kötter's separation, which is not implemented.
BrunCurve brun_curve(const QuadraticModel& model, const State& x0);

/// N(u) and R(u) = −P(u) N(u).
double brun_N(const BrunCurve& k, double u);
std::complex<double> brun_N(const BrunCurve& k, std::complex<double> u);
double brun_R(const BrunCurve& k, double u);

/// R(u)/((u − a_s)(b_s − u)) on the range of u_s, as a product of |u − r| over the other three
/// roots: positive and smooth on [a_s, b_s] (no cancellation).
double brun_reduced_R(const BrunCurve& k, int s, double u);

/// True when the level f = m·γ vanishes to the tolerance used by brun_curve.
bool brun_level_solvable(const QuadraticModel& model, const State& x0);

}  // namespace newtop
