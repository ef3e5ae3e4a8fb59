#pragma once
/// \file
/// Brun's case on any level: the torus frequencies from the periods of the Prym differentials
/// (du, u du)/(vξ) of the spectral curve Γ: v² = P(u), ξ² = N(u) + 2√λ f v (brun_prym.hpp).
///
/// The Abel–Prym sums are linear along the flows of the energy H and of Brun's integral c, with
/// velocities V_H = (−2i/κ, 0) and V_c (brun_prym_rate along the c-flow), so a point of the
/// level reached by the flows for times (τ_H, τ_c) has sums τ_H V_H + τ_c V_c + const, and the
/// state comes back exactly when τ_H V_H + τ_c V_c lies in the period lattice Λ ⊂ C² of the
/// differentials (brun_prym_state is one to one). Λ is computed from loops around the branch
/// points of Γ over the u-line (e1, e2, e3 and the roots of D = N² − 4λf²P) from one base point,
/// the sheets (±v, ±ξ) continued along each loop, every closed word of two and four loops; its
/// basis by rational coordinates and integer row reduction. The lattice {(τ_H, τ_c) : τ_H V_H +
/// τ_c V_c ∈ Λ} contains the time lattice of the torus with index 1 or 2 (on the levels tried,
/// 2: the Abel–Prym map of the torus is two to one there); which of its three index-2 sublattices
/// is the torus is decided by integrating the two flows over short candidate periods (rkf78 at
/// 1e-13: a period returns the state to ~1e-12, a non-period misses by O(1)) — a discrete choice;
/// the numbers come from the periods. The basis T1, T2 is Lagrange–Gauss reduced, and the
/// frequencies (rad per unit time of the motion, made ≥ 0 by the orientation of T1, T2) are
/// ω = 2π [T1 T2]⁻¹ (1, 0): the motion is
/// φ_k = φ_k(0) + ω_k t on the torus, and every frequency of the motion is an integer combination
/// of ω.

#include <array>
#include <complex>
#include <optional>

#include "newtop/analysis/brun_case.hpp"
#include "newtop/analysis/brun_curve.hpp"

namespace newtop {

/// The frequencies of the level of k and the data they come from.
struct BrunPrymFrequencies {
  std::array<double, 2> frequency{};  ///< ω, a reduced basis of the frequency module
  /// Columns: the flow times (τ_H, τ_c) of the two basis cycles of the torus.
  std::array<std::array<double, 2>, 2> torus_period{};
  std::array<std::complex<double>, 2> velocity_c{};  ///< V_c, the Abel–Prym velocity of the c-flow
  int period_vectors = 0;  ///< closed words with a nonzero period found (all enter Λ)
  int index = 1;           ///< of the torus lattice in the lattice the Prym periods give
  std::optional<BrunResonance> resonance;  ///< of |ω1| : |ω2|, as brun_resonance
};

/// The frequencies of the level through the body-frame state s of a Brun model, f ≠ 0. Throws
/// InputError when the lattice cannot be formed (a degenerate level: a double root of D, a
/// branch point on a loop) or the flows close on none of the candidates.
BrunPrymFrequencies brun_prym_frequencies(const QuadraticModel& model, const State& s);

}  // namespace newtop
