#pragma once
/// \file
/// The variational equations with the embedded Runge–Kutta pairs (dopri5, rkf78, dop853): the state
/// and the tangent vectors integrated together as one system of 6 + 36 equations, with the pair's
/// error control (odeint's, or Dop853Core's) over all of them (the indicators renormalise the
/// vectors to norm 1 after every accepted step, so that the tolerance applies to O(1) numbers; the
/// step sequence therefore differs from `simulate`'s, which controls the state alone).

#include <array>

#include "newtop/integrate/dop853.hpp"
#include "newtop/phase/tangent.hpp"

namespace newtop::phase {

/// The extended state: m, γ, then up to 6 tangent vectors (unused ones zero).
using TangentOdeState = std::array<double, 42>;

/// (x, V) as the extended state.
inline TangentOdeState to_tangent_ode(const State& x, const Tangent& V) {
  TangentOdeState y{};
  for (int i = 0; i < 3; ++i) {
    y[i] = x.m[i];
    y[3 + i] = x.gamma[i];
  }
  Eigen::Map<Eigen::Matrix<double, 6, Eigen::Dynamic>>(y.data() + 6, 6, V.cols()) = V;
  return y;
}

/// The extended state back into (x, V) (V keeps its number of columns).
inline void from_tangent_ode(const TangentOdeState& y, State& x, Tangent& V) {
  x = State{Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5])};
  V = Eigen::Map<const Eigen::Matrix<double, 6, Eigen::Dynamic>>(y.data() + 6, 6, V.cols());
}

/// The variational system of the model with n tangent vectors: ẋ = f(x), Ẇ = Df(x) W.
template <Field F>
auto tangent_system(const BasicModel<F>& model, Eigen::Index n) {
  return [&model, n](const TangentOdeState& y, TangentOdeState& dydt, double) {
    const State s{Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5])};
    const State d = rhs(model, s);
    dydt.fill(0.0);
    for (int i = 0; i < 3; ++i) {
      dydt[i] = d.m[i];
      dydt[3 + i] = d.gamma[i];
    }
    const Eigen::Matrix<double, 6, 6> J = rhs_jacobian(model, s);
    const Eigen::Map<const Eigen::Matrix<double, 6, Eigen::Dynamic>> W(y.data() + 6, 6, n);
    Eigen::Map<Eigen::Matrix<double, 6, Eigen::Dynamic>> dW(dydt.data() + 6, 6, n);
    dW = J * W;
  };
}

/// An embedded pair on the extended system: EY the odeint error stepper on TangentOdeState, EState
/// the same pair on the state alone (for the first trial step).
template <class EY, class EState, int Order>
class TangentAdaptiveStepper {
 public:
  using Y = TangentOdeState;

  TangentAdaptiveStepper(double abs_tol, double rel_tol)
      : abs_tol_(abs_tol),
        rel_tol_(rel_tol),
        controlled_(boost::numeric::odeint::make_controlled(abs_tol, rel_tol, EY())) {}
  int order() const { return Order; }

  /// The first trial step: that of the plain pair on the state (EmbeddedRkStepper::initial_step).
  template <Field F>
  double initial_step(const BasicModel<F>& model, const State& x, double t0, double t1) const {
    EmbeddedRkStepper<EState, Order> plain(abs_tol_, rel_tol_);
    return plain.initial_step(model, x, t0, t1);
  }

  /// One trial step as AdaptiveStepper::try_step, carrying V.
  template <Field F>
  bool try_step(const BasicModel<F>& model, State& x, Tangent& V, double& t, double& dt) {
    Y y = to_tangent_ode(x, V);
    reset_first_same_as_last();  // y is a new point (V renormalised since the last step)
    const auto sys = tangent_system(model, V.cols());
    if (controlled_.try_step(sys, y, t, dt) != boost::numeric::odeint::success) return false;
    from_tangent_ode(y, x, V);
    return true;
  }

 private:
  void reset_first_same_as_last() {
    if constexpr (requires { controlled_.reset(); }) controlled_.reset();
  }
  double abs_tol_, rel_tol_;
  typename boost::numeric::odeint::result_of::make_controlled<EY>::type controlled_;
};

using TangentDopri5Stepper =
    TangentAdaptiveStepper<boost::numeric::odeint::runge_kutta_dopri5<TangentOdeState>,
                           boost::numeric::odeint::runge_kutta_dopri5<OdeState>, 5>;
using TangentFehlberg78Stepper =
    TangentAdaptiveStepper<boost::numeric::odeint::runge_kutta_fehlberg78<TangentOdeState>,
                           boost::numeric::odeint::runge_kutta_fehlberg78<OdeState>, 8>;

/// Dormand–Prince 8(5,3) on the extended system (Dop853Stepper's pair and error control over the
/// state and the tangent vectors together).
class TangentDop853Stepper {
 public:
  TangentDop853Stepper(double abs_tol, double rel_tol)
      : abs_tol_(abs_tol), rel_tol_(rel_tol), core_(abs_tol, rel_tol) {}
  int order() const { return newtop::detail::Dop853Core<TangentOdeState>::kOrder; }

  /// The first trial step: that of the plain pair on the state (Dop853Stepper::initial_step).
  template <Field F>
  double initial_step(const BasicModel<F>& model, const State& x, double t0, double t1) const {
    Dop853Stepper plain(abs_tol_, rel_tol_);
    return plain.initial_step(model, x, t0, t1);
  }

  /// One trial step as AdaptiveStepper::try_step, carrying V.
  template <Field F>
  bool try_step(const BasicModel<F>& model, State& x, Tangent& V, double& t, double& dt) {
    TangentOdeState y = to_tangent_ode(x, V);
    if (!core_.try_step(tangent_system(model, V.cols()), y, t, dt)) return false;
    from_tangent_ode(y, x, V);
    return true;
  }

 private:
  double abs_tol_, rel_tol_;
  newtop::detail::Dop853Core<TangentOdeState> core_;
};

}  // namespace newtop::phase
