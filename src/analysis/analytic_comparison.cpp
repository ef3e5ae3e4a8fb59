#include "newtop/analysis/analytic_comparison.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

#include "newtop/integrate/run.hpp"
#include "newtop/model/state_checks.hpp"

namespace newtop {

std::optional<double> solution_period(const AnalyticSolution& sol) {
  const double T = std::visit(
      [](const auto& s) -> double {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, LagrangeCase>) {
          return s.nutation_period;
        } else if constexpr (std::is_same_v<S, BrunCase> || std::is_same_v<S, BrunPrymSolution>) {
          return std::numeric_limits<double>::quiet_NaN();
        } else {
          return s.period;
        }
      },
      sol);
  if (std::isfinite(T) && T > 0) return T;
  return std::nullopt;
}

AnalyticComparison compare_analytic(const QuadraticModel& model, const State& x0,
                                    const AnalyticSolution& sol, const std::vector<double>& times,
                                    IntegrateOptions options) {
  validate(x0);
  if (const auto* brun = std::get_if<BrunCase>(&sol)) {
    for (const double t : times) brun_check_time(*brun, t);  // every time refused before any work
  }
  AnalyticComparison c;
  c.times = times;
  if (times.empty()) return c;
  const Body& b = model.body;
  c.numeric.resize(times.size());
  const MethodSettings ref{"rkf78", 0.0, kAnalyticReferenceTol, kAnalyticReferenceTol};
  c.reference = run_method_sampled(
      ref, Model(model), x0, 0.0, times.back(), OutputTimes::list(times, 0.0, times.back()),
      options, [&](std::int64_t k, double, const State& x) { c.numeric[k] = x; });
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto start = std::chrono::steady_clock::now();
    const State an = analytic_state(sol, times[k]);
    c.seconds_per_sample +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
        static_cast<double>(times.size());
    c.analytic.push_back(an);
    if (const auto& x = c.numeric[k]) {
      const double err = std::max((omega(b, an) - omega(b, *x)).cwiseAbs().maxCoeff(),
                                  (an.gamma - x->gamma).cwiseAbs().maxCoeff());
      c.max_abs_error = std::max(c.max_abs_error.value_or(0.0), err);
      ++c.compared;
    }
  }
  return c;
}

AnalyticCurve analytic_curve(const AnalyticSolution& sol, double t0, double t1, int n) {
  if (n < 2) throw InputError("curve: expected at least 2 points, found " + std::to_string(n));
  if (!(std::isfinite(t0) && std::isfinite(t1))) {
    throw InputError("curve: expected a finite time span");
  }
  AnalyticCurve c;
  for (int k = 0; k < n; ++k) {
    const double t = k == n - 1 ? t1 : t0 + (t1 - t0) * k / (n - 1);
    c.t.push_back(t);
    c.state.push_back(analytic_state(sol, t));
  }
  return c;
}

}  // namespace newtop
