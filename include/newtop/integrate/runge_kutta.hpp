#pragma once
/// \file
/// Runge–Kutta methods through Boost.Odeint on the Euler–Poisson right-hand side (spec §4):
/// classical RK4 (fixed step, the baseline) and the embedded pairs Dormand–Prince 5(4) and
/// Fehlberg 7(8) with absolute and relative tolerances.

#include <array>
// Odeint's steppers copy their (not yet sized) scratch arrays on construction, which GCC 12 flags
// as uninitialized use inside Boost's headers; silence that for Boost's lines only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/dense_output_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "newtop/model/model.hpp"

namespace newtop {

/// The state as odeint sees it: (m1, m2, m3, γ1, γ2, γ3).
using OdeState = std::array<double, 6>;

inline OdeState to_ode(const State& s) {
  return {s.m[0], s.m[1], s.m[2], s.gamma[0], s.gamma[1], s.gamma[2]};
}
inline State from_ode(const OdeState& y) {
  return {Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5])};
}

/// The Euler–Poisson vector field in odeint's calling convention.
template <Field F>
struct OdeSystem {
  const BasicModel<F>* model;
  void operator()(const OdeState& y, OdeState& dydt, double /*t*/) const {
    const State d = rhs(*model, from_ode(y));
    dydt = to_ode(d);
  }
};

/// Any odeint stepper run at a fixed step (its error estimate, if any, unused).
template <class OdeintStepper, int Order>
class OdeintFixedStepper {
 public:
  int order() const { return Order; }
  template <Field F>
  void step(const BasicModel<F>& model, State& x, double h) {
    OdeState y = to_ode(x);
    stepper_.do_step(OdeSystem<F>{&model}, y, 0.0, h);
    x = from_ode(y);
  }

 private:
  OdeintStepper stepper_;
};

/// Classical fourth-order Runge–Kutta, fixed step (odeint's runge_kutta4): the baseline.
using Rk4Stepper = OdeintFixedStepper<boost::numeric::odeint::runge_kutta4<OdeState>, 4>;

/// An embedded Runge–Kutta pair with odeint's standard error control:
/// err_i / (abs_tol + rel_tol (|y_i| + h |y'_i|)) ≤ 1 in the max norm.
template <class ErrorStepper, int Order>
class EmbeddedRkStepper {
 public:
  EmbeddedRkStepper(double abs_tol, double rel_tol)
      : controlled_(boost::numeric::odeint::make_controlled(abs_tol, rel_tol, ErrorStepper())) {}

  int order() const { return Order; }

  template <Field F>
  bool try_step(const BasicModel<F>& model, State& x, double& t, double& dt) {
    OdeState y = to_ode(x);
    const auto r = controlled_.try_step(OdeSystem<F>{&model}, y, t, dt);
    if (r == boost::numeric::odeint::success) {
      x = from_ode(y);
      return true;
    }
    return false;
  }

 private:
  typename boost::numeric::odeint::result_of::make_controlled<ErrorStepper>::type controlled_;
};

/// Dormand–Prince 5(4) (odeint's runge_kutta_dopri5), order 5.
using Dopri5Stepper = EmbeddedRkStepper<boost::numeric::odeint::runge_kutta_dopri5<OdeState>, 5>;
/// Runge–Kutta–Fehlberg 7(8) (odeint's runge_kutta_fehlberg78): 13 stages, propagates the
/// 8th-order solution, 7th-order error estimate.
using Fehlberg78Stepper =
    EmbeddedRkStepper<boost::numeric::odeint::runge_kutta_fehlberg78<OdeState>, 8>;

/// Dense output of Dormand–Prince 5(4) (odeint's dense_output_runge_kutta): steps freely and
/// interpolates the state at any time inside the last step with the method's continuous extension.
template <Field F>
class Dopri5Dense {
 public:
  Dopri5Dense(const BasicModel<F>& model, double abs_tol, double rel_tol)
      : model_(&model),
        dense_(boost::numeric::odeint::make_dense_output(
            abs_tol, rel_tol, boost::numeric::odeint::runge_kutta_dopri5<OdeState>())) {}

  void initialize(const State& x, double t, double dt) { dense_.initialize(to_ode(x), t, dt); }
  /// One accepted step; returns (t_old, t_new).
  std::pair<double, double> do_step() { return dense_.do_step(OdeSystem<F>{model_}); }
  double current_time() const { return dense_.current_time(); }
  State current_state() const { return from_ode(dense_.current_state()); }
  /// The interpolated state at t in [t_old, t_new] of the last step.
  State calc_state(double t) const {
    OdeState y;
    dense_.calc_state(t, y);
    return from_ode(y);
  }

 private:
  const BasicModel<F>* model_;
  typename boost::numeric::odeint::result_of::make_dense_output<
      boost::numeric::odeint::runge_kutta_dopri5<OdeState>>::type dense_;
};

}  // namespace newtop
