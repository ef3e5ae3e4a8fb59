#pragma once
/// \file
/// The stability of one fixed point as `newtop stability` reports it (docs/model.md §7–§9): which
/// state is analysed (a spin about a principal axis, the K-th equilibrium, or a given state
/// polished by Newton's method), its spectrum on the leaf, and — for a spin about a principal axis
/// of the quadratic field — Beletsky's threshold where his formula applies and the numerical one.

#include <optional>
#include <string>

#include "newtop/analysis/stability.hpp"
#include "newtop/analysis/stability_spin.hpp"

namespace newtop {

/// What stability_of_* found.
struct StabilityReport {
  State state;                ///< the fixed point analysed
  std::optional<int> axis;    ///< the principal axis of a spin γ = e_axis, ω ∥ e_axis
  PolishedFixedPoint polish;  ///< Newton's polish of the state given
  Spectrum spectrum;          ///< eigenvalues on the leaf and the verdicts
  double residual = 0.0;      ///< fixed_point_residual of `state`
  /// Beletsky's Ω* (axis, quadratic field, M g r0 = 0 and his conditions); nullopt otherwise.
  std::optional<double> threshold_formula;
  /// The Ω above which the spin stays stable (numeric_threshold), with an axis.
  std::optional<double> threshold_numeric;
  /// Why threshold_formula is absent, with an axis: what the formula needs and what the axis is;
  /// empty when it applies.
  std::string formula_note;
};

/// The principal axis i with γ = e_i and ω ∥ e_i (or ω = 0), where the spin family about it is a
/// fixed point for every Ω (M g r0 along e_i); nullopt otherwise.
std::optional<int> spin_axis_of(const QuadraticModel& model, const State& s);

/// The report of a fixed point `state` (checked by the caller) with Newton's `polish` of the state
/// given, and `axis` when it is a spin about that principal axis (the thresholds need the
/// quadratic field).
StabilityReport stability_report(const Model& model, const State& state,
                                 const PolishedFixedPoint& polish, std::optional<int> axis);

/// Why stability_of_equilibrium or stability_of_state found no fixed point to analyse: what()
/// is the library's message; the fields let a caller word it for its own options.
class StabilityChoiceError : public InputError {
 public:
  enum class Reason {
    no_equilibrium,     ///< the model has no isolated equilibrium
    equilibrium_index,  ///< k is not in 1 … count
    not_fixed_point,    ///< the state given is not a fixed point to three digits
  };
  StabilityChoiceError(Reason why, const std::string& message) : InputError(message), reason(why) {}
  Reason reason;
  int count = 0;                   ///< the number of isolated equilibria
  bool every_orientation = false;  ///< every orientation is an equilibrium
  PolishedFixedPoint polish;       ///< Newton's polish that failed (not_fixed_point)
};

/// The spin about principal axis `axis` (0, 1, 2) at rate Ω, pointing at the centre. Throws
/// InputError ("axis: ...") on a field other than the quadratic one or when M g r0 is not along
/// the axis.
StabilityReport stability_of_axis(const Model& model, int axis, double Omega);
/// The k-th (1-based) isolated equilibrium of find_equilibria, at rest. Throws
/// StabilityChoiceError ("equilibrium: ...") when there is none such, or when Newton's polish of
/// it fails.
StabilityReport stability_of_equilibrium(const Model& model, int k);
/// A state given to a few digits, polished by Newton's method (polish_fixed_point). Throws
/// StabilityChoiceError ("state: ...", not_fixed_point) when it is not a fixed point to three
/// digits, InputError for a state that is not valid.
StabilityReport stability_of_state(const Model& model, const State& s);

/// The polish's failure in words: "found residual R of d(m, gamma)/dt, and ..." (the command
/// line's and the library's messages).
std::string polish_failure(const PolishedFixedPoint& p);

}  // namespace newtop
