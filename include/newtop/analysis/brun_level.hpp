#pragma once
/// \file
/// Brun's case on any level f = m·γ (docs/model.md §5): the sphero-conic coordinates with their
/// momenta, the relations that couple them when f ≠ 0, and the spectral curve of the Lax pair of
/// the Clebsch system (a_i = 1/I_i, b_i = λ I_i), on whose Prym variety brun_prym.hpp makes the
/// motion linear (docs/integrable.md, "Brun's case, level f ≠ 0").
///
/// Working frame and notation of brun_curve.hpp and brun_separation.hpp. On every level,
/// m = γ × y + f γ with y = m × γ tangent to the Poisson sphere, so (u_s, w_s) of brun_point and
/// the signs S_i of γ_i are coordinates of the level; p_s = w_s/(2P(u_s)). With the bracket of
/// docs/model.md §4 ({m_i, m_j} = −ε_ijk m_k), {u_s, u_t} = 0, {u_s, p_t} = −δ_st and
///   {p1, p2} = f (u2 − u1) / (4 V γ1 γ2 γ3),  V = (e2 − e1)(e3 − e2)(e3 − e1):
/// f times the area form of the sphere in (u1, u2) — a magnetic monopole of charge f.

#include <Eigen/Core>
#include <array>
#include <complex>

#include "newtop/analysis/brun_separation.hpp"

namespace newtop {

/// The body-frame state with sphero-conic coordinates (u_s, w_s) and signs S_i of the working-frame
/// γ_i, on the level f = k.f:
///   γ_i = S_i √((u1 − e_i)(u2 − e_i)/P′(e_i)),
///   m_i = (e_k − e_j) γ_j γ_k Σ_s w_s (u_s − e_i)/((u_t − u_s) P(u_s)) + f γ_i
/// ((i, j, k) cyclic, t ≠ s). Needs e1 < u1 < e2 < u2 < e3 (γ off the principal planes).
State brun_state_from_point(const BrunCurve& k, const BrunPoint& p, const std::array<double, 3>& S);

/// M(u) = N(u) − f² u.
double brun_M(const BrunCurve& k, double u);

/// P(u) = (u − e1)(u − e2)(u − e3).
double brun_P(const BrunCurve& k, double u);

/// K = f² (u1 + u2 − e1 − e2 − e3) − 2f Σ_i e_i (m_i − f γ_i) γ_i for a body-frame state. On every
/// level
///   M(u_s) + w_s²/P(u_s) = K,  s = 1, 2:
/// for f = 0, K = 0 and these are the separated relations w_s² = R(u_s); for f ≠ 0, K is linear
/// in the momenta and depends on both u_s, so the relations do not separate in (u1, u2).
double brun_coupling(const BrunCurve& k, const State& s);

/// {p1, p2} = f (u2 − u1)/(4 V γ1 γ2 γ3) at a body-frame state (see above).
double brun_momentum_bracket(const BrunCurve& k, const State& s);

/// The coupling K of brun_coupling written in the separated coordinates of the level f = k.f:
/// Σ_i e_i (m_i − f γ_i) γ_i = −V γ1 γ2 γ3 Σ_s w_s/((u_t − u_s) P(u_s)), so
///   K = f² (u1 + u2 − e1 − e2 − e3) + 2f V γ1γ2γ3 (w1/P(u1) − w2/P(u2))/(u2 − u1),
/// with V γ1γ2γ3 = S1S2S3 √(−P(u1) P(u2)). In the real momenta t1 = w1/√P(u1),
/// t2 = w2/√(−P(u2)) and ε = S1S2S3 the level reads t1² + M(u1) = K = M(u2) − t2² with
///   K = f² (u1 + u2 − e1 − e2 − e3) + 2fε (√(−P(u2)) t1 + √P(u1) t2)/(u2 − u1)
/// (docs/integrable.md, "The level as a reduced system").
double brun_coupling_at(const BrunCurve& k, const BrunPoint& p, const std::array<double, 3>& S);

/// The integrals h and c as functions of the separated coordinates on the level f = k.f (the
/// reduced system of the level: its Hamiltonian with the monopole bracket above). With
/// q_s = w_s²/P(u_s) and K = brun_coupling_at,
///   c − λ(e1 + e2 + e3) − f² = (q2 − q1)/(u1 − u2) − λ(u1 + u2),
///   2κh = K + λ u1 u2 + (u2 q1 − u1 q2)/(u1 − u2).
struct BrunIntegrals {
  double h = 0, c = 0;
};
BrunIntegrals brun_integrals_at(const BrunCurve& k, const BrunPoint& p,
                                const std::array<double, 3>& S);

/// The Lax vector of the Clebsch system, X_i(u) = w_i m_i + √λ w_j w_k γ_i with w_i = √(u − e_i)
/// (principal complex roots; √λ imaginary for λ < 0), working frame, (i, j, k) cyclic. For every
/// u, Σ X_i² = N(u) + 2√λ f v with v = w1 w2 w3 (v² = P(u)): the quadratic form of the Lax
/// pair, conserved along the motion.
std::array<std::complex<double>, 3> brun_lax(const BrunCurve& k, const State& s,
                                             std::complex<double> u);

/// The spectral curve Γ: v² = P(u), ξ² = N(u) + 2√λ f v, a double cover of the elliptic curve
/// v² = P(u) (genus 3 when f ≠ 0); the motion is linear on its Prym variety (dimension 2),
/// isogenous to the Jacobian of Kötter's genus-2 curve. Over the u-line Γ branches at e1, e2, e3,
/// ∞ and at the roots of D(u) = N(u)² − 4λf² P(u) (where the two values of ξ² meet). For f = 0,
/// D = N² and Γ/(v, ξ) ↦ (−v, −ξ) is the curve w² = −P N of brun_curve.hpp.
struct BrunSpectralCurve {
  std::array<double, 5> discriminant{};              ///< D(u) = Σ discriminant[i] uⁱ
  std::array<std::complex<double>, 4> branch_point;  ///< roots of D (real ones first, ascending)
};

/// The spectral curve of the level of k.
BrunSpectralCurve brun_spectral_curve(const BrunCurve& k);

/// A Lax matrix with rational spectral parameter (working frame), of the twisted form
///   L(ℓ) = ℓ A + m̂ + ℓ⁻¹ γγᵀ,  A = −λ diag(e1, e2, e3),  m̂ x = m × x
/// (L(−ℓ) = −L(ℓ)ᵀ). It is isospectral: with v = −μ/(λℓ) and z = λℓ²,
///   −ℓ det(μ I − L(ℓ)) = λ z² P(v) + z N(v) + f²   (|γ| = 1),
/// so the curve is a double cover (ℓ² = z/λ) of the elliptic curve y² = D(v), D = N² − 4λf²P,
/// branched over v = e1, e2, e3, ∞: the bigonal partner of the curve of brun_spectral_curve
/// (a double cover of v² = P(u) branched over the roots of D).
Eigen::Matrix3cd brun_rational_lax(const BrunCurve& k, const State& s, std::complex<double> l);

}  // namespace newtop
