#pragma once
/// \file
/// Brun's case on a level f ≠ 0: the state at time t, by inverting the Abel–Prym map of
/// brun_prym.hpp (docs/integrable.md, "The state at time t on f ≠ 0").
///
/// The state reached from x0 by the flows of H and of Brun's integral c for times τ = (τ_H, τ_c)
/// is the state of the divisor D with Abel–Prym sums
///   S(D) = S(D0) + V_H τ_H + V_c τ_c,  V_H = (−2i/κ, 0),  V_c = (0, −4i),
/// and the state is periodic in τ with the torus lattice T of brun_prym_periods.hpp. So:
///  1. t is reduced modulo T: (t, 0) = T (n + θ), n integer, θ ∈ [−½, ½)² (exact: a period of
///     the torus returns the state); the cost no longer depends on t.
///  2. The divisor at τ = T θ is reached from the nearest node of a table over one cell of the
///     torus (a grid in θ, built once per level the same way from D0): D is moved by Newton's
///     method on the equation S(D) − S(D_node) = V (τ − τ_node), where D is the set of zeros of a
///     line A u + B + √λ C v (two complex unknowns: the line up to scale) and the difference of
///     the sums is the integral of brun_prym_line_rate along the straight segment of lines from
///     the node's (12-point Gauss–Legendre), the ξ_j continued from node to node. Long moves are
///     split into steps in τ, each short enough that no point moves by more than half of
///     its distance to another point or to a branch point of Γ (so that the continuation of the
///     points and of ξ is unambiguous and the quadrature converged) — a continuation along the
///     real torus, which chooses between the two divisors of one Abel image (the map from the
///     torus is two to one) by continuity.
///  3. The state is brun_prym_state of the divisor; every step checks that a real state of the
///     level carries its divisor and that it lies where the two flows take the previous one to
///     first order.
/// No integration of the motion is involved: the answer is the solution of the Abel–Prym
/// equations to round-off, with the periods of brun_prym_frequencies.

#include <array>
#include <complex>
#include <vector>

#include "newtop/analysis/brun_prym.hpp"
#include "newtop/analysis/brun_prym_periods.hpp"

namespace newtop {

/// A point of the real torus with its divisor, as reached by the continuation.
struct BrunPrymNode {
  std::array<double, 2> tau{};  ///< flow times (τ_H, τ_c) from the start
  BrunPrymLine line{};          ///< A u + B + √λ C v, up to scale
  BrunPrymDivisor divisor{};    ///< its zeros, with ξ_j
  State state;                  ///< body frame, brun_prym_state of the divisor
};

/// The solution on the level of x0 (data only).
struct BrunPrymSolution {
  QuadraticModel model;
  BrunCurve curve;
  State initial;
  BrunPrymFrequencies torus;  ///< the torus lattice (torus_period) and frequencies
  std::array<std::complex<double>, 2> velocity_h{}, velocity_c{};  ///< V_H, V_c
  int grid = 0;                     ///< table nodes per side of the cell, minus one
  std::vector<BrunPrymNode> table;  ///< (grid + 1)² nodes at θ = (i, j)/grid − ½, row-major in i
};

/// The solution from x0 on its level f ≠ 0 (a Brun model, λ ≠ 0, distinct moments). Throws
/// InputError as brun_level and brun_prym_frequencies do, on f = 0 (brun_case.hpp solves it by
/// separation), or when the continuation cannot proceed (a step shorter than 1e-10 of a cell).
BrunPrymSolution brun_prym_solution(const QuadraticModel& model, const State& x0);

/// The state at time t with the data of the inversion.
struct BrunPrymStateAt {
  State state;                   ///< body frame
  BrunPrymDivisor divisor{};     ///< its divisor on Γ
  std::array<double, 2> cell{};  ///< θ: the torus coordinates of t in the cell, [−½, ½)²
  std::array<double, 2> tau{};   ///< T θ: the reduced flow times (τ_H, τ_c)
  double residual = 0;           ///< |S(D) − law| left by Newton's method in the last step
  int steps = 0;                 ///< continuation steps from the nearest table node
};
BrunPrymStateAt brun_prym_state_at(const BrunPrymSolution& s, double t);

/// The linearisation checked at the start: the initial state's divisor on Γ, the largest
/// component of |state → divisor → state − state| (m and γ), and the rates of the Abel–Prym sums
/// along the state's velocity (to be equal to the solution's law, velocity_h).
struct BrunPrymCheck {
  BrunPrymDivisor divisor{};
  double round_trip_error = 0;
  BrunPrymRate rate;
};
BrunPrymCheck brun_prym_check(const BrunPrymSolution& s);

/// The state at time t on the level f ≠ 0 of x0 (brun_prym_solution, then brun_prym_state_at;
/// for many times build the solution once).
State brun_state_at(const QuadraticModel& model, const State& x0, double t);

}  // namespace newtop
