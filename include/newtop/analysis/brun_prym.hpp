#pragma once
/// \file
/// Brun's case on any level f = m·γ: the motion as a straight line on the Prym variety of the
/// spectral curve Γ: v² = P(u), ξ² = N(u) + 2√λ f v of brun_level.hpp, through a divisor of three
/// points of Γ that are functions of the state (working frame and notation of brun_curve.hpp).
///
/// With c_i = √(e_j − e_k) ((i, j, k) cyclic; Σ c_i² = Σ e_i c_i² = 0) the vector
/// α_i(u) = c_i w_i(u), w_i = √(u − e_i), is isotropic for every u, and the Lax vector X(u) of
/// brun_lax gives
///   α(u)·X(u) = A u + B + √λ C v,  A = Σ c_i m_i,  B = −Σ c_i e_i m_i,  C = Σ c_i γ_i:
/// a function on the elliptic curve v² = P(u) with a triple pole at ∞, so with three zeros u_1,
/// u_2, u_3 — the roots of λ C² P(u) = (A u + B)², with v_j = −(A u_j + B)/(√λ C) — collinear on
/// the cubic. At a zero, α is an isotropic vector orthogonal to X, hence an eigenvector of X×:
/// X × α = i ξ_j α with ξ_j² = N(u_j) + 2√λ f v_j, which lifts the point to Γ. Along the motion
/// (docs/model.md §4 equations) the divisor P_1 + P_2 + P_3 moves linearly under the Prym
/// differentials du/(vξ), u du/(vξ) (the holomorphic differentials of Γ odd under ξ ↦ −ξ):
///   Σ_j u̇_j/(v_j ξ_j) = −2i/κ,   Σ_j u_j u̇_j/(v_j ξ_j) = 0,
/// so the Abel–Prym sums Σ_j ∫^{P_j} (1, u) du/(vξ) are (−2i t/κ, 0) plus constants — on every
/// level, f = 0 included (docs/integrable.md, "Brun's case, level f ≠ 0"). The points are complex
/// for real states (c_1 and c_3 are imaginary), so they do not oscillate in real ranges.

#include <array>
#include <complex>
#include <functional>
#include <span>
#include <vector>

#include "newtop/analysis/brun_curve.hpp"
#include "newtop/analysis/brun_level.hpp"

namespace newtop {

/// A point of Γ: v² = P(u), ξ² = N(u) + 2√λ f v.
struct BrunPrymPoint {
  std::complex<double> u, v, xi;
};

/// The three points of Γ of a state, in the order of the eigenvalues of the cubic's companion
/// matrix.
using BrunPrymDivisor = std::array<BrunPrymPoint, 3>;

/// The coefficients A, B, C of α·X = A u + B + √λ C v for a body-frame state.
struct BrunPrymLine {
  std::complex<double> A, B, C;
};
BrunPrymLine brun_prym_line(const BrunCurve& k, const State& s);

/// The divisor of a body-frame state on the level of k (λ ≠ 0; needs C ≠ 0, true off two points
/// of the Poisson sphere).
BrunPrymDivisor brun_prym_divisor(const BrunCurve& k, const State& s);

/// The three zeros (u_j, v_j) on v² = P(u) of A u + B + √λ C v for any complex line (C ≠ 0),
/// with ξ_j the principal square root of N(u_j) + 2√λ f v_j: the sign of each ξ_j is the
/// caller's (brun_prym_divisor takes it from the state's eigenvector).
BrunPrymDivisor brun_prym_zeros(const BrunCurve& k, const BrunPrymLine& l);

/// Σ_j (1, u_j) u̇_j/(v_j ξ_j) as the line l, whose zeros with their ξ_j are d, moves by dl:
/// u̇_j/(v_j ξ_j) = −2(Ȧu_j + Ḃ + √λ Ċ v_j)/((2A v_j + √λ C P′(u_j)) ξ_j).
std::array<std::complex<double>, 2> brun_prym_line_rate(const BrunCurve& k, const BrunPrymLine& l,
                                                        const BrunPrymLine& dl,
                                                        const BrunPrymDivisor& d);

/// The body-frame state on the level of k whose divisor is d (the inverse of brun_prym_divisor):
/// the line through the points gives (A : B : C); with μA = Σc_i m_i, μB = −Σc_i e_i m_i,
/// μC = Σc_i γ_i six real linear equations leave a plane of (m, γ, μ), on which m·γ = f and
/// |γ| = 1 leave four candidates, ±(m, γ) on two directions; the one whose eigenvalues at the
/// points are the ξ_j is returned (the sign of (m, γ) flips every ξ_j; the other direction is a
/// state of another level through the same points). Throws InputError when no real state of the
/// level carries d.
State brun_prym_state(const BrunCurve& k, const BrunPrymDivisor& d);

/// The rates of the Abel–Prym sums along a tangent vector ds at s (both body frame):
/// Σ_j (1, u_j) u̇_j/(v_j ξ_j) with u̇_j from differentiating the line A u + B + √λ C v = 0 on
/// v² = P(u).
/// Along the motion's own vector field, rhs(model, s): (−2i/κ, 0). `magnitude` is the sum of the
/// moduli of the terms (times 1 + |u_j|); `error_scale` models the round-off of `rate` (a few
/// hundred ε times it): each term's modulus times 1 + (1 + |u_j|)/δ_j (δ_j the distance to the
/// nearest other point: the root's error and the term grow as points close in) +
/// (|N(u_j)| + |2√λ f v_j|)/|ξ_j|² (near a root of D).
struct BrunPrymRate {
  std::array<std::complex<double>, 2> rate{};
  double magnitude = 0;
  double error_scale = 0;
};
BrunPrymRate brun_prym_rate(const BrunCurve& k, const State& s, const State& ds);

/// The Hamiltonian vector field of Brun's integral c = |m|² − λκ γ·I⁻¹γ at a body-frame state
/// (bracket of docs/model.md §4): ṁ = m × 2m + γ × ∂c/∂γ, γ̇ = γ × 2m. It commutes with the motion,
/// and along it the rates of the Abel–Prym sums are (0, −4i): the two flows of the Liouville torus
/// are both straight lines on the Prym.
State brun_c_flow(const BrunCurve& k, const State& s);

/// The state of a motion at any time of the interval asked for (from a numerical integration).
using BrunMotion = std::function<State(double)>;

/// The increments of the Abel–Prym sums Σ_j ∫ (1, u) du/(vξ) over the paths of the three points
/// while the state follows x(t) from t0 to t1, from positions only: Gauss–Legendre in t (12 nodes)
/// of brun_prym_rate along the state's velocity, the spectral derivative of the states at the
/// nodes, on intervals bisected until two levels agree to `tolerance` or to their round-off (at
/// most 8 levels). The sums are analytic in t along a motion even where single points are not
/// (a point through a branch point of Γ over the u-line, two points passing close, which exchange
/// in complex time), so no branch or order is tracked. x must be smooth in t to round-off (e.g. a
/// fixed-step method with a fixed number of steps from t0): the differentiation amplifies noise.
std::array<std::complex<double>, 2> brun_prym_abel_increment(const BrunCurve& k,
                                                             const BrunMotion& x, double t0,
                                                             double t1, double tolerance);

/// The Abel–Prym sums at the given ascending times ≥ 0 along the numerical motion from x0 on its
/// level (brun_level): brun_prym_abel_increment on intervals of at most 0.5 between the states of
/// rkf78 at 1e-14, with the states inside an interval from 32 fixed splitting8 steps from its
/// start. Linear in t, (−2i t/κ, 0), to ~1e-11 over tens of time units (tests/integrable/
/// test_brun_prym.cpp). Throws InputError on times out of order.
std::vector<std::array<std::complex<double>, 2>> brun_prym_sums_along(
    const QuadraticModel& model, const State& x0, std::span<const double> times);

}  // namespace newtop
