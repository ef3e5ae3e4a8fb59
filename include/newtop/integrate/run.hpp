#pragma once
/// \file
/// Runs of any method on any model, compiled once in the library: the entry points for programs
/// that run integrations. Declarations only — no stepper, no Boost.Odeint; methods.hpp holds the
/// templates these are made of (run_method on a BasicModel<F> and a stepper of one's own).

#include <cstdint>
#include <functional>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/integrate/outcome.hpp"
#include "newtop/integrate/output_times.hpp"
#include "newtop/model/model.hpp"

namespace newtop {

/// Called at t0 and after every accepted step with (t, state).
template <class X>
using StepObserver = std::function<void(double t, const X& x)>;
/// Called at each output time t_k, in order, with (k, t_k, state at t_k).
template <class X>
using SampleObserver = std::function<void(std::int64_t k, double t, const X& x)>;

/// Runs the named method (settings validated) on the model's own field from (t0, x) to t1; the
/// observer, if any, sees every accepted step. The same steps, bits and Outcome as the template
/// run_method of methods.hpp on the model's BasicModel<F>.
Outcome run_method(const MethodSettings& method, const Model& model, const State& x, double t0,
                   double t1, IntegrateOptions options = {},
                   const StepObserver<State>& observer = {});
/// The same with the attitude carried (OrientedState): the Outcome holds the final attitude.
Outcome run_method(const MethodSettings& method, const Model& model, const OrientedState& x,
                   double t0, double t1, IntegrateOptions options = {},
                   const StepObserver<OrientedState>& observer = {});

/// Runs as run_method and reports the state at every output time to sample (integrate_sampled of
/// sampled.hpp: the adaptive methods' continuous extension; fixed-step methods land on each time).
Outcome run_method_sampled(const MethodSettings& method, const Model& model, const State& x,
                           double t0, double t1, const OutputTimes& times, IntegrateOptions options,
                           const SampleObserver<State>& sample,
                           const StepObserver<State>& observer = {});
/// The same with the attitude carried.
Outcome run_method_sampled(const MethodSettings& method, const Model& model, const OrientedState& x,
                           double t0, double t1, const OutputTimes& times, IntegrateOptions options,
                           const SampleObserver<OrientedState>& sample,
                           const StepObserver<OrientedState>& observer = {});

}  // namespace newtop
