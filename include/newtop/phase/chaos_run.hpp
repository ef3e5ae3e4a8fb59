#pragma once
/// \file
/// The tangent runs (fixed-step and adaptive) and the chaos indicators on a BasicModel<F>
/// (templates; chaos.hpp declares them on a Model, compiled once in the library).

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <type_traits>

#include "newtop/integrate/driver.hpp"
#include "newtop/phase/chaos.hpp"
#include "newtop/phase/one_step.hpp"
#include "newtop/phase/tangent_of.hpp"

namespace newtop::phase {

/// A state with its tangent vectors: the state the engine's driver advances for a tangent run.
/// V is mutable so that an observer, which the driver hands the state as const, renormalises the
/// vectors of the running state (Benettin's method) in place.
struct TangentPoint {
  State x;
  mutable Tangent V;
};

struct TangentOutcome {
  Status status = Status::finished;
  double t = 0.0;
  TangentPoint state;
  std::int64_t steps = 0;
  std::int64_t rejected = 0;
  double last_step = 0.0;
};

inline void check_state(const TangentPoint& p) { newtop::check_state(p.x); }
inline bool is_finite(const TangentPoint& p) { return newtop::is_finite(p.x) && p.V.allFinite(); }

}  // namespace newtop::phase

namespace newtop {
template <>
struct OutcomeFor<phase::TangentPoint> {
  using type = phase::TangentOutcome;
};
}  // namespace newtop

namespace newtop::phase {

/// The tangent flow of a BasicModel<F> as a model of the driver (integrate/driver.hpp).
template <Field F>
struct TangentFlow {
  using state_type = TangentPoint;
  const BasicModel<F>* model;
};

/// A tangent stepper (step(model, x, V, h), or try_step(model, x, V, t, dt) and initial_step) in
/// the driver's interface on TangentFlow.
template <class S>
class TangentFlowStepper {
  /// Adaptive when S has try_step (then the driver runs its adaptive loop, else the fixed one).
  template <Field F>
  static constexpr bool kAdaptive = requires(S s, const BasicModel<F>& m, State& x, Tangent& V,
                                             double& t) {
    s.try_step(m, x, V, t, t);
  };

 public:
  explicit TangentFlowStepper(S& s) : s_(s) {}
  int order() const { return s_.order(); }
  template <Field F>
  requires(!kAdaptive<F>) void step(const TangentFlow<F>& f, TangentPoint& p, double h) {
    s_.step(*f.model, p.x, p.V, h);
  }
  template <Field F>
  requires kAdaptive<F>
  bool try_step(const TangentFlow<F>& f, TangentPoint& p, double& t, double& dt) {
    return s_.try_step(*f.model, p.x, p.V, t, dt);
  }
  template <Field F>
  double initial_step(const TangentFlow<F>& f, const TangentPoint& p, double t0, double t1) {
    return s_.initial_step(*f.model, p.x, t0, t1);
  }

 private:
  S& s_;
};

namespace detail {

/// The driver's run of a tangent stepper, observer(t, x, V) after each step (not at the start).
template <class S, Field F, class Obs>
Outcome run_tangent(S& stepper, const BasicModel<F>& model, const State& x, const Tangent& V,
                    double t0, double t1, const IntegrateOptions& opt, Obs& observer) {
  TangentFlowStepper<S> s(stepper);
  bool started = false;
  auto obs = [&](double t, const TangentPoint& p) {
    if (!started) {  // the driver's call at the start
      started = true;
      return;
    }
    observer(t, p.x, p.V);
  };
  const TangentOutcome o =
      integrate(s, TangentFlow<F>{&model}, TangentPoint{x, V}, t0, t1, opt, obs);
  Outcome out;
  out.status = o.status;
  out.t = o.t;
  out.state = o.state.x;
  out.steps = o.steps;
  out.rejected = o.rejected;
  out.last_step = o.last_step;
  return out;
}

}  // namespace detail

/// n equal steps of a tangent stepper from (t0, x, V) to t1 (n = fixed_step_count(t0, t1, h)) on
/// the engine's driver, observer(t, x, V) after each (it may renormalise V); stops at a
/// non-finite state or tangent.
template <class S, Field F, class Obs>
Outcome integrate_tangent(S& stepper, const BasicModel<F>& model, State x, Tangent V, double t0,
                          double t1, const IntegrateOptions& opt, Obs&& observer) {
  return detail::run_tangent(stepper, model, x, V, t0, t1, opt, observer);
}

/// The same with an adaptive tangent stepper: the driver's adaptive loop (accepted steps from t0
/// to t1, the last one shortened to land on t1), observer after each accepted step.
template <class S, Field F, class Obs>
requires requires(S s, const BasicModel<F>& m, State& x, Tangent& V, double& t) {
  s.try_step(m, x, V, t, t);
}
Outcome integrate_tangent_adaptive(S& stepper, const BasicModel<F>& model, State x, Tangent V,
                                   double t0, double t1, const IntegrateOptions& opt,
                                   Obs&& observer) {
  return detail::run_tangent(stepper, model, x, V, t0, t1, opt, observer);
}

/// The indicators of the trajectory from (request.t0, x0) to request.t_end (chaos.hpp), on a
/// BasicModel<F>: the request is checked (check_chaos_request), the state is not (the compiled
/// chaos on a Model validates it).
template <Field F>
ChaosResult chaos(const BasicModel<F>& model, const State& x0, const ChaosRequest& request) {
  check_chaos_request(request);
  const MethodSettings& method = request.method;
  IntegrateOptions options = request.options;
  options.step = method.step;
  const double t0 = request.t0, t1 = request.t_end;
  const int vectors = request.spectrum ? 6 : 1;
  const std::int64_t every = history_interval(request);
  const auto& history = request.history;
  const auto& on_step = request.on_step;
  return with_tangent_stepper(method, [&](auto& s) {
    ChaosIndicators ind(t0, vectors);
    std::int64_t count = 0;
    auto obs = [&](double t, const State&, Tangent& V) {
      if (on_step) on_step(t);
      ind(t, V);
      if (history && ++count % every == 0) history(ind.sample());
    };
    ChaosResult r;
    using S = std::decay_t<decltype(s)>;
    if constexpr (requires(S & st, State & x, Tangent & V, double& t) {
                    st.try_step(model, x, V, t, t);
                  }) {
      r.outcome =
          integrate_tangent_adaptive(s, model, x0, initial_tangent(vectors), t0, t1, options, obs);
    } else {
      r.outcome = integrate_tangent(s, model, x0, initial_tangent(vectors), t0, t1, options, obs);
    }
    r.indicators = ind.sample();
    if (history && count % every != 0) history(r.indicators);
    return r;
  });
}

/// A state and its companion, advanced together (two_trajectory_lyapunov); the companion is
/// mutable so that the driver's observer pulls it back in place.
struct StatePair {
  State x;
  mutable State y;
};

struct StatePairOutcome {
  Status status = Status::finished;
  double t = 0.0;
  StatePair state;
  std::int64_t steps = 0;
  std::int64_t rejected = 0;
  double last_step = 0.0;
};

inline void check_state(const StatePair& p) { newtop::check_state(p.x); }
inline bool is_finite(const StatePair& p) {
  return newtop::is_finite(p.x) && newtop::is_finite(p.y);
}

/// The flow of a BasicModel<F> on a pair of states, as a model of the driver.
template <Field F>
struct PairFlow {
  using state_type = StatePair;
  const BasicModel<F>* model;
};

/// A plain stepper's one-step map on both states of a pair.
template <class S>
class PairStepper {
 public:
  explicit PairStepper(S& s) : map1_(s), map2_(s), order_(s.order()) {}
  int order() const { return order_; }
  template <Field F>
  void step(const PairFlow<F>& f, StatePair& p, double h) {
    p.x = map1_(*f.model, p.x, h);
    p.y = map2_(*f.model, p.y, h);
  }

 private:
  OneStepMap<S> map1_, map2_;
  int order_;
};

}  // namespace newtop::phase

namespace newtop {
template <>
struct OutcomeFor<phase::StatePair> {
  using type = phase::StatePairOutcome;
};
}  // namespace newtop

namespace newtop::phase {

/// Benettin's two-trajectory estimate of λ_max: a companion started at distance d0 along
/// initial_tangent(1) (in the max norm of the state), both advanced by the plain stepper of the
/// method in the engine's fixed-step driver, the companion pulled back to distance d0 every
/// `renorm` steps and at the end; Σ ln(d/d0)/(t − t0).
template <Field F>
double two_trajectory_lyapunov(const MethodSettings& method, const BasicModel<F>& model,
                               const State& x0, double t0, double t1, double d0 = 1e-8,
                               int renorm = 10) {
  IntegrateOptions opt;
  opt.step = method.step;
  opt.max_steps = std::numeric_limits<std::int64_t>::max();
  return with_stepper(method, [&](auto& s) {
    using S = std::decay_t<decltype(s)>;
    PairStepper<S> pair(s);
    const Tangent v = initial_tangent(1);
    const StatePair p0{x0, {x0.m + d0 * v.col(0).head<3>(), x0.gamma + d0 * v.col(0).tail<3>()}};
    double sum = 0;
    std::int64_t i = -1;  // the driver's first call is the start
    auto pull_back = [&](double t, const StatePair& p) {
      if (++i == 0 || (i % renorm != 0 && t != t1)) return;
      Eigen::Matrix<double, 6, 1> d;
      d << p.y.m - p.x.m, p.y.gamma - p.x.gamma;
      const double dn = d.norm();
      sum += std::log(dn / d0);
      const Eigen::Matrix<double, 6, 1> e = (d0 / dn) * d;
      p.y = {p.x.m + e.head<3>(), p.x.gamma + e.tail<3>()};
    };
    integrate(pair, PairFlow<F>{&model}, p0, t0, t1, opt, pull_back);
    return sum / (t1 - t0);
  });
}

}  // namespace newtop::phase
