#pragma once
/// \file
/// The one-step map x ↦ Φ_h(x) of a stepper of the conformance suite, for any h: a fixed-step
/// method's own step; for an embedded Runge–Kutta pair, one step of the pair's propagated formula
/// with no error control (the formula every accepted step of the adaptive run applies;
/// Dormand–Prince 8(5,3) likewise; Taylor's series summed at h). Event location lands on a surface
/// with it, so that a located point lies on the method's own solution.

#include <limits>

#include "newtop/integrate/dop853.hpp"
#include "newtop/integrate/runge_kutta.hpp"
#include "newtop/integrate/taylor.hpp"

namespace newtop::phase {

/// A fixed-step method: a copy of the stepper, stepping by h.
template <class S>
class OneStepMap {
 public:
  explicit OneStepMap(const S& s) : s_(s) {}
  template <Field F>
  State operator()(const BasicModel<F>& model, State x, double h) {
    s_.step(model, x, h);
    return x;
  }

 private:
  S s_;
};

/// An embedded Runge–Kutta pair: one step of its formula, f(x) evaluated afresh (never a stale
/// first-same-as-last value).
template <class E, int Order>
class OneStepMap<EmbeddedRkStepper<E, Order>> {
 public:
  explicit OneStepMap(const EmbeddedRkStepper<E, Order>&) {}
  template <Field F>
  State operator()(const BasicModel<F>& model, const State& x, double h) {
    const OdeSystem<F> sys{&model};
    OdeState y = to_ode(x), dydt;
    sys(y, dydt, 0.0);
    e_.do_step(sys, y, dydt, 0.0, h);
    return from_ode(y);
  }

 private:
  E e_;
};

/// Taylor's method: the series through x summed at h (its own solution inside a step); a span
/// longer than the step the method takes from x is crossed in its steps.
template <>
class OneStepMap<TaylorStepper> {
 public:
  explicit OneStepMap(const TaylorStepper& s) : s_(s.abs_tol(), s.rel_tol(), s.order()) {}
  template <Field F>
  State operator()(const BasicModel<F>& model, State x, double h) {
    double left = h;
    while (left != 0.0) {
      double t = 0.0, dt = left;
      if (!s_.try_step(model, x, t, dt)) {
        x.m.setConstant(std::numeric_limits<double>::quiet_NaN());
        return x;
      }
      left = t == left ? 0.0 : left - t;
    }
    return x;
  }

 private:
  TaylorStepper s_;
};

/// Dormand–Prince 8(5,3): one step of its order-8 formula (Dop853Core::step).
template <>
class OneStepMap<Dop853Stepper> {
 public:
  explicit OneStepMap(const Dop853Stepper& s) : core_(s.abs_tol(), s.rel_tol()) {}
  template <Field F>
  State operator()(const BasicModel<F>& model, const State& x, double h) {
    return from_ode(core_.step(OdeSystem<F>{&model}, to_ode(x), 0.0, h));
  }

 private:
  newtop::detail::Dop853Core<OdeState> core_;
};

}  // namespace newtop::phase
