#pragma once
/// \file
/// The stepper concepts every integrator satisfies (checked with static_assert in the tests).

#include <concepts>

#include "newtop/model/attitude.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// A fixed-step one-step method: `order()` and `step(model, x, h)` advancing x by h in place (x a
/// State, or an OrientedState when X says so, or the state of a model with one of its own); a
/// stepper of a non-autonomous model takes the independent variable at the start of the step,
/// `step(model, x, t, h)`.
template <class S, class M, class X = State>
concept FixedStepper = requires(S s, const S cs, const M& model, X& x, double t, double h) {
  { cs.order() } -> std::convertible_to<int>;
  requires requires { s.step(model, x, h); } || requires {
    s.step(model, x, t, h);
  };
};

/// Adaptive methods: a trial step that gives NaN or inf is rejected and retried this much shorter
/// (the largest decrease odeint's step controller applies to a rejected step).
inline constexpr double kNonFiniteShrink = 0.2;

/// An adaptive (error-controlled) method: `try_step(model, x, t, dt)` attempts a step of dt from
/// (t, x); on success it advances x and t and returns true; on failure it leaves them and returns
/// false. In both cases dt is replaced by the suggested next step. `initial_step(model, x, t0, t1)`
/// is a first trial step |h| > 0 estimated from the problem (the right-hand side, the state and
/// the tolerances), never from the span alone.
template <class S, class M, class X = State>
concept AdaptiveStepper = requires(S s, const S cs, const M& model, X& x, double& t, double& dt) {
  { cs.order() } -> std::convertible_to<int>;
  { s.try_step(model, x, t, dt) } -> std::same_as<bool>;
  { s.initial_step(model, x, t, t) } -> std::convertible_to<double>;
};

}  // namespace newtop
