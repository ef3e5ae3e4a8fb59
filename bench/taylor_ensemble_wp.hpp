#pragma once
// The Taylor ensemble's work–precision (bench_taylor_ensemble.cpp,
// heyoka/taylor_ensemble_heyoka.cpp): the CPU time per trajectory of newtop's scalar Taylor run and
// of its ensemble (N copies of the regime's start, one per lane) at a ladder of tolerances, and the
// time at a target state error interpolated in log–log between the two tolerances that bracket it.

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "newtop/integrate/taylor_ensemble.hpp"
#include "newtop/phase/chaos.hpp"
#include "newtop/phase/tangent_vectors.hpp"
#include "wp_support.hpp"

namespace wp {

/// One setting of a method: its state error at T and its CPU time per trajectory.
struct WpPoint {
  double tol, error, cpu;
};

/// The tolerances tried: 1e-6 to 1e-15 by factors of √10.
inline std::vector<double> tolerance_ladder() {
  std::vector<double> t;
  for (int i = 12; i <= 30; ++i) t.push_back(std::pow(10.0, -0.5 * i));
  return t;
}

/// The CPU time at `error`, interpolated in log–log between the two settings whose errors bracket
/// it (nullopt when none do).
inline std::optional<double> time_at(const std::vector<WpPoint>& p, double error) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const double e0 = p[i].error, e1 = p[i + 1].error;
    if ((e0 - error) * (e1 - error) <= 0 && e0 != e1 && e0 > 0 && e1 > 0) {
      const double s = (std::log(error) - std::log(e0)) / (std::log(e1) - std::log(e0));
      return std::exp(std::log(p[i].cpu) + s * (std::log(p[i + 1].cpu) - std::log(p[i].cpu)));
    }
  }
  return std::nullopt;
}

/// Best of `rounds` CPU times of fn().
template <class Fn>
double best_cpu(int rounds, Fn&& fn) {
  double best = 1e300;
  for (int k = 0; k < rounds; ++k) {
    const double c0 = cpu_seconds();
    fn();
    best = std::min(best, cpu_seconds() - c0);
  }
  return best;
}

/// newtop's scalar Taylor run of the regime at tol: its final state and CPU time.
inline WpPoint scalar_taylor(const Regime& r, const LState& ref, double tol, int rounds) {
  Outcome out;
  const double cpu = best_cpu(rounds, [&] {
    TaylorStepper s(tol, tol);
    out = integrate(s, r.model, r.x0, 0.0, r.T, IntegrateOptions{});
  });
  return {tol, state_error(out.state, ref), cpu};
}

/// The Taylor ensemble on n copies of the regime's start at tol: the error of lane 0 and the CPU
/// time per trajectory. `same_bits` is set false if a lane differs from the scalar run.
inline WpPoint ensemble_taylor(const Regime& r, const LState& ref, double tol, std::size_t n,
                               int rounds, const State& scalar, bool& same_bits) {
  TaylorEnsemble e(tol, tol);
  const std::vector<State> x(n, r.x0);
  const std::vector<QuadraticModel> models{r.model};
  std::vector<Outcome> out;
  const double cpu = best_cpu(rounds, [&] { out = e.integrate(models, x, 0.0, r.T); });
  for (const Outcome& o : out) {
    same_bits = same_bits && o.state.m == scalar.m && o.state.gamma == scalar.gamma;
  }
  return {tol, state_error(out[0].state, ref), cpu / static_cast<double>(n)};
}

/// The same with one tangent vector and the chaos indicators (newtop chaos's run, phase::chaos with
/// method taylor): the final state's error and the CPU time.
inline WpPoint scalar_taylor_tangent(const Regime& r, const LState& ref, double tol, int rounds,
                                     State& final_state) {
  phase::ChaosResult out;
  const double cpu = best_cpu(rounds, [&] {
    out = phase::chaos(Model(r.model), r.x0,
                       {.method = MethodSettings("taylor", 0.0, tol, tol), .t_end = r.T});
  });
  final_state = out.outcome.state;
  return {tol, state_error(out.outcome.state, ref), cpu};
}

/// The Taylor ensemble's tangent runs on n copies of the start, the indicators observed per lane.
inline WpPoint ensemble_taylor_tangent(const Regime& r, const LState& ref, double tol,
                                       std::size_t n, int rounds, const State& scalar,
                                       bool& same_bits) {
  TaylorEnsemble e(tol, tol);
  const std::vector<State> x(n, r.x0);
  const std::vector<QuadraticModel> models{r.model};
  const std::vector<TangentVector> v0{phase::initial_tangent(1).col(0)};
  std::vector<Outcome> out;
  const double cpu = best_cpu(rounds, [&] {
    std::vector<phase::ChaosIndicators> ind(n, phase::ChaosIndicators(0.0, 1));
    out = e.integrate_tangent(models, x, v0, 0.0, r.T, IntegrateOptions{},
                              [&](std::size_t p, double t, const State&, TangentVector& v) {
                                phase::Tangent V = v;
                                ind[p](t, V);
                                v = V.col(0);
                              });
  });
  for (const Outcome& o : out) {
    same_bits = same_bits && o.state.m == scalar.m && o.state.gamma == scalar.gamma;
  }
  return {tol, state_error(out[0].state, ref), cpu / static_cast<double>(n)};
}

}  // namespace wp
