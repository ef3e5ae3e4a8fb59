#pragma once
/// \file
/// Brun's case, level f = 0: the change of variables (m, γ) ↔ (u1, u2, w1, w2) ↔ (φ1, φ2, signs).
///
/// Working frame and notation of brun_curve.hpp. With y = m × γ (so m = γ × y on f = 0),
///   w_s = Σ_i γ_i y_i Π_{j≠i}(u_s − e_j)   (= 2P(u_s) p_s, p_s the momentum conjugate to u_s),
/// and w_s² = R(u_s). Back:
///   γ_i² = (u1 − e_i)(u2 − e_i)/P′(e_i),
///   m_i = (e_k − e_j) γ_j γ_k Σ_s w_s (u_s − e_i) / ((u_t − u_s) P(u_s))   ((i, j, k) cyclic,
///   t ≠ s).
/// The map back is many-valued; the motion carries it through the angles φ_s ∈ ℝ,
///   u_s = c_s − d_s cos φ_s,  c_s = (a_s + b_s)/2, d_s = (b_s − a_s)/2,
/// which unfold each oscillation between the turning values a_s, b_s (φ_s grows with t), and the
/// constant signs S_i of γ_i. Every square root is taken signed and smooth in φ_s:
/// √(u_s − a_s) = √(2d_s) sin(φ_s/2), √(b_s − u_s) = √(2d_s) cos(φ_s/2), so a γ_i whose e_i bounds
/// the range changes sign there, and w_s = σ_s d_s sin φ_s √R̃_s(u_s) (R̃_s: brun_reduced_R),
/// σ_1 = −1, σ_2 = +1 (u̇_1 = 2u_2 w_1/(κ(u_2 − u_1)), u̇_2 = 2u_1 w_2/(κ(u_1 − u_2)), u_s < 0).

#include <array>

#include "newtop/analysis/brun_curve.hpp"

namespace newtop {

/// σ_s = sign(u̇_s / w_s).
inline constexpr std::array<double, 2> kBrunOrientation{-1.0, 1.0};

/// The separated point of a state: u_s and w_s (working frame).
struct BrunPoint {
  std::array<double, 2> u{}, w{};
};

/// A point of the level with its discrete data: φ_s (any real; φ_s and φ_s + 4π are the same
/// state) and the signs S_i of γ_i in the working frame.
struct BrunAngles {
  std::array<double, 2> phi{};
  std::array<double, 3> S{1.0, 1.0, 1.0};
};

/// u_s and w_s of a body-frame state.
BrunPoint brun_point(const BrunCurve& k, const State& s);

/// The angles (φ_s ∈ [0, 2π)) and signs of a body-frame state on the level of k.
BrunAngles brun_angles(const BrunCurve& k, const State& s);

/// The body-frame state at the given angles and signs.
State brun_state_at(const BrunCurve& k, const BrunAngles& a);

/// u_s at angle φ.
double brun_u_at(const BrunCurve& k, int s, double phi);

/// R̃_s at angle φ, each |u − r| written from the nearer end of the range (no cancellation).
double brun_reduced_R_at(const BrunCurve& k, int s, double phi);

}  // namespace newtop
