#pragma once
/// \file
/// The options of a run and the checks every run makes before its first step: plain declarations,
/// without any stepper (driver.hpp runs them).

#include <cstdint>

#include "newtop/model/attitude.hpp"

namespace newtop {

struct IntegrateOptions {
  /// Fixed-step methods: the nominal step h > 0. The run takes n = ceil((t1 − t0)/h) equal steps
  /// of (t1 − t0)/n, so that it ends exactly at t1; t_n = t0 + n h is computed, never accumulated.
  double step = 0.0;
  /// Adaptive methods: first trial step (0: the stepper's estimate from the problem,
  /// AdaptiveStepper::initial_step).
  double initial_step = 0.0;
  /// Adaptive methods: a trial or accepted step below min_step_factor · max(|t|, |t1 − t0|) is an
  /// underflow: finishing would take over 1e12 steps, or the tolerance is below what round-off
  /// allows (the error estimate then vanishes at tiny steps and the run would creep on forever).
  double min_step_factor = 1e-12;
  /// Both: at most this many accepted steps (adaptive: also counts rejected trials).
  std::int64_t max_steps = 1'000'000'000;
};

/// The largest number of steps a run may take: 2^53, beyond which the step index is no longer an
/// exact double and t0 + i·h would repeat times.
inline constexpr double kMaxStepCount = 9007199254740992.0;

/// Throws InputError unless t0, t1 and t1 − t0 are finite (`t0`/`t_end`: expected a finite time).
void check_time_span(double t0, double t1);

/// The number n = ceil(|t1 − t0| / h) of equal steps of a fixed-step run. Throws InputError for a
/// step that is not a finite number > 0, for non-finite times, and for a count beyond
/// kMaxStepCount (the message gives the count).
std::int64_t fixed_step_count(double t0, double t1, double step);

/// Throws InputError for options no run can use (negative or non-finite initial_step,
/// min_step_factor outside (0, 1), max_steps < 1).
void check_options(const IntegrateOptions& opt);

/// Throws InputError naming m or gamma when the state is not finite.
void check_state(const State& x);
/// The same, and `quaternion` unless q is finite and of norm 1 within kUnitQuaternionTolerance.
void check_state(const OrientedState& x);

/// Whether every component of the state (and of the attitude) is finite.
inline bool is_finite(const State& s) { return s.m.allFinite() && s.gamma.allFinite(); }
inline bool is_finite(const OrientedState& s) {
  return is_finite(static_cast<const State&>(s)) && s.q.coeffs().allFinite();
}

/// A quaternion handed to a run is a unit one to this tolerance on |‖q‖ − 1| (it is normalised).
inline constexpr double kUnitQuaternionTolerance = 1e-6;

}  // namespace newtop
