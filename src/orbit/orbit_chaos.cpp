// Chaos indicators on an orbit (orbit_chaos.hpp): the variational equations of the orbit model
// as one more model of the engine (a state of its own, a right-hand side bound to odeint's
// numbers), run by the engine's embedded pairs or by Taylor's method through the one driver.

#include "newtop/orbit/orbit_chaos.hpp"

#include <Eigen/QR>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "newtop/integrate/dop853.hpp"
#include "newtop/integrate/runge_kutta.hpp"
#include "newtop/orbit/orbit_stability.hpp"
#include "newtop/orbit/orbit_taylor.hpp"

namespace newtop {
namespace {

/// The orbit state with K tangent vectors (columns) and the logs of the factors by which the
/// last step's renormalisation shrank them.
template <int K>
struct TangentState {
  OrbitState x;
  Eigen::Matrix<double, 9, K> V = Eigen::Matrix<double, 9, K>::Zero();
  std::array<double, 6> growth{};
};

template <int K>
struct TangentOutcome {
  Status status = Status::finished;
  double t = 0.0;
  TangentState<K> state;
  std::int64_t steps = 0;
  std::int64_t rejected = 0;
  double last_step = 0.0;
};

template <int K>
void check_state(const TangentState<K>& s) {
  check_state(s.x);
}
template <int K>
bool is_finite(const TangentState<K>& s) {
  return is_finite(s.x) && s.V.allFinite();
}

/// The variational equations of an orbit model M: (x, V)′ = (f(x), J(x) V).
template <class M, int K>
struct TangentModel {
  using state_type = TangentState<K>;
  const M* model;
};

template <int K>
using TangentNumbers = std::array<double, 9 + 9 * K>;

template <int K>
TangentNumbers<K> to_numbers(const OrbitState& x, const Eigen::Matrix<double, 9, K>& V) {
  TangentNumbers<K> y;
  for (int i = 0; i < 3; ++i) y[i] = x.m[i], y[3 + i] = x.gamma[i], y[6 + i] = x.normal[i];
  Eigen::Map<Eigen::Matrix<double, 9, K>>(y.data() + 9) = V;
  return y;
}

template <int K>
TangentState<K> from_numbers(const TangentNumbers<K>& y) {
  TangentState<K> s;
  s.x = {Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5]), Vec3(y[6], y[7], y[8])};
  s.V = Eigen::Map<const Eigen::Matrix<double, 9, K>>(y.data() + 9);
  return s;
}

template <class M, int K>
struct TangentSystem {
  const TangentModel<M, K>* tangent;
  void operator()(const TangentNumbers<K>& y, TangentNumbers<K>& d, double t) const {
    const TangentState<K> s = from_numbers<K>(y);
    const M& model = *tangent->model;
    if constexpr (std::is_same_v<M, EllipticOrbitModel>) {
      d = to_numbers<K>(rhs(model, s.x, t), jacobian(model, s.x, t) * s.V);
    } else {
      d = to_numbers<K>(rhs(model, s.x), jacobian(model, s.x) * s.V);
    }
  }
};

}  // namespace

template <int K>
struct OutcomeFor<TangentState<K>> {
  using type = TangentOutcome<K>;
};

template <class M, int K, class Y>
struct OdeBinding<TangentModel<M, K>, Y> {
  using state_type = TangentState<K>;
  using system = TangentSystem<M, K>;
  static Y to(const state_type& s) { return to_numbers<K>(s.x, s.V); }
  static state_type from(const Y& y) { return from_numbers<K>(y); }
};

namespace {

/// One vector to unit length, or Benettin's QR (signs making R_ii > 0); the logs of the factors.
template <int K>
std::array<double, 6> renormalise(Eigen::Matrix<double, 9, K>& V) {
  std::array<double, 6> g{};
  if constexpr (K == 1) {
    const double norm = V.norm();
    g[0] = std::log(norm);
    V /= norm;
  } else {
    const Eigen::HouseholderQR<Eigen::Matrix<double, 9, K>> qr(V);
    const Eigen::Matrix<double, 9, 9> Q = qr.householderQ();
    for (int i = 0; i < K; ++i) {
      const double r = qr.matrixQR()(i, i);
      g[i] = std::log(std::abs(r));
      V.col(i) =
          r < 0 ? Eigen::Matrix<double, 9, 1>(-Q.col(i)) : Eigen::Matrix<double, 9, 1>(Q.col(i));
    }
  }
  return g;
}

/// An embedded pair on the tangent model that renormalises the tangent vectors after each
/// accepted step (when asked), recording the factors in the state.
template <class S, int K>
class Renormalising {
 public:
  Renormalising(double abs_tol, double rel_tol, bool on) : inner_(abs_tol, rel_tol), on_(on) {}
  int order() const { return inner_.order(); }
  template <class M>
  double initial_step(const M& model, const TangentState<K>& x, double t0, double t1) {
    return inner_.initial_step(model, x, t0, t1);
  }
  template <class M>
  bool try_step(const M& model, TangentState<K>& x, double& t, double& dt) {
    if (!inner_.try_step(model, x, t, dt)) return false;
    if (on_ && K == 1) {
      Eigen::Matrix<double, 9, 1> v = x.V.col(0);
      x.growth = {};
      x.growth[0] = detail::orbit_leaf_renormalise(x.x, v);
      x.V.col(0) = v;
    } else if (on_) {
      // The exact tangent flow keeps the vectors on the leaf; the step's error does not, and a
      // component across it (exponent 0) would swamp the contracting directions: projected back.
      const OrbitLeafBasis Q = leaf_basis(x.x);
      x.V = Q * (Q.transpose() * x.V);
      x.growth = renormalise<K>(x.V);
    }
    return true;
  }

 private:
  S inner_;
  bool on_;
};

/// Taylor's method on the state and its tangent vectors (docs/orbit.md §5): a step sums the series
/// of both at h, h the smaller of the step asked for and the rule's step over the coefficients of
/// the state and the vectors together; dt becomes that step (as the fixed point's
/// TangentTaylorStepper). Never rejected unless a series is not finite.
template <int K>
class TangentTaylor {
 public:
  TangentTaylor(double abs_tol, double rel_tol)
      : abs_tol_(abs_tol),
        rel_tol_(rel_tol),
        order_(OrbitTaylorStepper(abs_tol, rel_tol).order()) {}
  int order() const { return order_; }

  template <class M>
  double initial_step(const TangentModel<M, K>& m, const TangentState<K>& x, double t0, double) {
    expand(*m.model, x, t0);
    return detail::orbit_tangent_step(series_, tangent_, abs_tol_, rel_tol_);
  }

  template <class M>
  bool try_step(const TangentModel<M, K>& m, TangentState<K>& x, double& t, double& dt) {
    expand(*m.model, x, t);
    const double h_max = detail::orbit_tangent_step(series_, tangent_, abs_tol_, rel_tol_);
    if (!(h_max > 0.0)) {  // NaN: a series is not finite
      dt *= kNonFiniteShrink;
      return false;
    }
    const double h = std::abs(dt) <= h_max ? dt : (dt < 0 ? -h_max : h_max);
    x.x = detail::orbit_taylor_sum(series_, h);
    for (int c = 0; c < K; ++c) {
      const std::array<double, 9> v = detail::orbit_tangent_sum(tangent_, c, h);
      x.V.col(c) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(v.data());
    }
    t += h;
    dt = h < 0 ? -h_max : h_max;
    return true;
  }

 private:
  template <class M>
  void expand(const M& model, const TangentState<K>& x, double t) {
    tangent_.columns = K;
    for (int c = 0; c < K; ++c) {
      for (int i = 0; i < 9; ++i) {
        tangent_.v[static_cast<std::size_t>(c)][0][static_cast<std::size_t>(i)] = x.V(i, c);
      }
    }
    if constexpr (std::is_same_v<M, EllipticOrbitModel>) {
      detail::orbit_taylor_expand(model, x.x, t, order_, series_);
      detail::orbit_taylor_expand_tangent(model, series_, t, tangent_);
    } else {
      detail::orbit_taylor_expand(model, x.x, order_, series_);
      detail::orbit_taylor_expand_tangent(model, series_, tangent_);
    }
  }

  double abs_tol_, rel_tol_;
  int order_;
  detail::OrbitTaylorSeries series_;
  detail::OrbitTangentSeries tangent_;
};

namespace odeint = boost::numeric::odeint;

/// Calls fn(stepper) with the named pair on K tangent vectors.
template <int K, class Fn>
decltype(auto) with_pair(const MethodSettings& m, bool renormalise_on, Fn&& fn) {
  using Y = TangentNumbers<K>;
  if (m.name == "taylor") {
    Renormalising<TangentTaylor<K>, K> s(m.abs_tol, m.rel_tol, renormalise_on);
    return fn(s);
  }
  if (m.name == "dopri5") {
    Renormalising<EmbeddedRkOn<odeint::runge_kutta_dopri5<Y>, 5>, K> s(m.abs_tol, m.rel_tol,
                                                                       renormalise_on);
    return fn(s);
  }
  if (m.name == "dop853") {
    Renormalising<Dop853On<Y>, K> s(m.abs_tol, m.rel_tol, renormalise_on);
    return fn(s);
  }
  Renormalising<EmbeddedRkOn<odeint::runge_kutta_fehlberg78<Y>, 8>, K> s(m.abs_tol, m.rel_tol,
                                                                         renormalise_on);
  return fn(s);
}

IntegrateOptions tangent_options(std::int64_t max_steps, double a, double b) {
  IntegrateOptions o;
  o.max_steps = max_steps;
  o.initial_step = std::abs(b - a) / 1000.0;  // as the orbit's runs
  return o;
}

void check_pair(const MethodSettings& method) {
  if (!is_orbit_adaptive_method(method.name)) {
    throw InputError(
        "method: chaos on an orbit integrates the variational equations with a tolerance: "
        "expected rkf78, dopri5, dop853 or taylor (with --tol), found '" +
        method.name + "'");
  }
  validate_orbit_method(method);
}

/// The chaos run from a to b in the model's variable; `time(v)` maps it to the time.
template <int K, class M, class Time>
OrbitChaosResult chaos_on(const M& model, const OrbitState& x0, double a, double b,
                          const OrbitChaosSettings& st, Time&& time) {
  TangentState<K> s;
  s.x = x0;
  if constexpr (K == 1) {
    s.V = detail::orbit_chaos_start(x0);
  } else {
    s.V = leaf_basis(x0);
  }
  const TangentModel<M, K> tangent{&model};
  phase::ChaosIndicators ind(st.t0, K);
  std::int64_t count = 0;
  bool started = false;
  auto obs = [&](double v, const TangentState<K>& x) {
    if (!started) {  // the driver's call at the start
      started = true;
      return;
    }
    const double t = time(v);
    if (st.on_step) st.on_step(t);
    ind.accumulate(t, x.growth);
    if (st.history && ++count % st.every == 0) st.history(ind.sample());
  };
  const TangentOutcome<K> out = with_pair<K>(st.method, true, [&](auto& stepper) {
    return integrate(stepper, tangent, s, a, b, tangent_options(st.max_steps, a, b), obs);
  });
  OrbitChaosResult r;
  r.outcome = {out.status, out.t, out.state.x, out.steps, out.rejected, out.last_step};
  r.t = time(out.t);
  r.indicators = ind.sample();
  if (st.history && count % st.every != 0) st.history(r.indicators);
  return r;
}

template <class M>
Eigen::Matrix<double, 9, 9> tangent_map(const MethodSettings& method, const M& model,
                                        const OrbitState& x, double a, double b) {
  check_pair(method);
  TangentState<9> s;
  s.x = x;
  s.V.setIdentity();
  const TangentModel<M, 9> tangent{&model};
  const TangentOutcome<9> out = with_pair<9>(method, false, [&](auto& stepper) {
    return integrate(stepper, tangent, s, a, b, tangent_options(100'000'000, a, b));
  });
  if (out.status != Status::finished) {
    throw InputError("orbit_tangent_map: the run ended " + std::string(to_string(out.status)));
  }
  return out.state.V;
}

}  // namespace

namespace detail {

double orbit_leaf_renormalise(const OrbitState& x, Eigen::Matrix<double, 9, 1>& v) {
  // The exact tangent flow keeps the vector on the leaf; the step's error does not, and a
  // component across it (exponent 0) would swamp the contracting directions: projected back.
  const OrbitLeafBasis Q = leaf_basis(x);
  v = Q * (Q.transpose() * v);
  const double norm = v.norm();
  v /= norm;
  return std::log(norm);
}

Eigen::Matrix<double, 9, 1> orbit_chaos_start(const OrbitState& x0) {
  return leaf_basis(x0) * Eigen::Matrix<double, 6, 1>::Constant(1.0 / std::sqrt(6.0));
}

}  // namespace detail

void check_orbit_chaos_settings(const OrbitChaosSettings& settings) {
  check_pair(settings.method);
  if (!std::isfinite(settings.t0) || !std::isfinite(settings.t1) || !(settings.t1 > settings.t0)) {
    throw InputError("t_end: chaos on an orbit expected a finite t_end > t0 = " +
                     format_number(settings.t0) + ", found " + format_number(settings.t1));
  }
  if (settings.every < 1) {
    throw InputError("every: expected an integer >= 1, found " + std::to_string(settings.every));
  }
}

OrbitChaosResult orbit_chaos(const CircularOrbitModel& model, const OrbitState& x0,
                             const OrbitChaosSettings& settings) {
  check_orbit_chaos_settings(settings);
  auto time = [](double t) { return t; };
  if (settings.spectrum) return chaos_on<6>(model, x0, settings.t0, settings.t1, settings, time);
  return chaos_on<1>(model, x0, settings.t0, settings.t1, settings, time);
}

OrbitChaosResult orbit_chaos(const EllipticOrbitModel& model, const OrbitState& x0,
                             const OrbitChaosSettings& settings) {
  check_orbit_chaos_settings(settings);
  const EllipticOrbit& e = model.orbit();
  const double nu0 = e.true_anomaly0, nu1 = true_anomaly_at(e, settings.t1 - settings.t0);
  auto time = [&](double nu) { return settings.t0 + elapsed_time(e, nu0, nu); };
  if (settings.spectrum) return chaos_on<6>(model, x0, nu0, nu1, settings, time);
  return chaos_on<1>(model, x0, nu0, nu1, settings, time);
}

Eigen::Matrix<double, 9, 9> orbit_tangent_map(const MethodSettings& method,
                                              const CircularOrbitModel& model, const OrbitState& x,
                                              double a, double b) {
  return tangent_map(method, model, x, a, b);
}

Eigen::Matrix<double, 9, 9> orbit_tangent_map(const MethodSettings& method,
                                              const EllipticOrbitModel& model, const OrbitState& x,
                                              double a, double b) {
  return tangent_map(method, model, x, a, b);
}

}  // namespace newtop
