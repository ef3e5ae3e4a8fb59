#pragma once
/// \file
/// An integrable case's solution against a high-accuracy numerical run (`newtop analytic`): the
/// closed form at the sample times beside rkf78 at kAnalyticReferenceTol, and their largest
/// difference in ω and γ.

#include <cstdint>
#include <optional>
#include <vector>

#include "newtop/analysis/analytic.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/integrate/outcome.hpp"

namespace newtop {

/// Tolerance of the numerical reference: its global error (~1e-12 over a few periods) stays well
/// below the 1e-10 at which the analytic solutions are validated.
inline constexpr double kAnalyticReferenceTol = 1e-13;

/// The period the solution repeats with (the nutation period for the Lagrange case); nullopt when
/// it has none (equilibrium, separatrix, steady precession, Brun's quasi-periodic motion).
std::optional<double> solution_period(const AnalyticSolution& sol);

struct AnalyticComparison {
  std::vector<double> times;                  ///< the sample times, ascending
  std::vector<State> analytic;                ///< the closed form at each time
  std::vector<std::optional<State>> numeric;  ///< the reference, where it reached the time
  /// max over compared samples of max(|Δω|∞, |Δγ|∞); nullopt when none was compared.
  std::optional<double> max_abs_error;
  Outcome reference;          ///< the reference run (rkf78 at kAnalyticReferenceTol)
  std::int64_t compared = 0;  ///< samples the reference reached
  /// Wall-clock seconds of one closed-form state, averaged over the samples (a measurement, so it
  /// varies from run to run; everything else is deterministic).
  double seconds_per_sample = 0;
};

/// The solution `sol` of the model's motion from (0, x0) at the ascending times ≥ 0, against
/// rkf78 at kAnalyticReferenceTol from 0 to the last time (dense output); options.max_steps
/// bounds the reference. Empty times: nothing is run.
AnalyticComparison compare_analytic(const QuadraticModel& model, const State& x0,
                                    const AnalyticSolution& sol, const std::vector<double>& times,
                                    IntegrateOptions options = {});

/// The closed form at n equally spaced times from t0 to t1 (n >= 2), each time computed as
/// t0 + k (t1 − t0)/(n − 1): a curve dense enough to draw where the samples of a comparison are a
/// spin period or more apart.
struct AnalyticCurve {
  std::vector<double> t;
  std::vector<State> state;
};
AnalyticCurve analytic_curve(const AnalyticSolution& sol, double t0, double t1, int n);

}  // namespace newtop
