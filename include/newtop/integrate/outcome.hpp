#pragma once
/// \file
/// The result of a run of the driver: how it ended, where and after how many steps.

#include <cstdint>
#include <optional>
#include <string_view>

#include "newtop/model/attitude.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// How an integration ended. Expected numerical outcomes are returned, never thrown.
enum class Status {
  finished,             ///< reached t1
  non_finite,           ///< a fixed step produced NaN or inf; integration stopped at once
  step_size_underflow,  ///< the adaptive step fell below the smallest admissible step (also when
                        ///< every trial down to it gave NaN or inf: those are rejected steps)
  step_limit,           ///< the maximum number of steps was taken before t1
};

std::string_view to_string(Status s);

struct Outcome {
  Status status = Status::finished;
  double t = 0.0;             ///< time reached: the time of `state`
  State state;                ///< the last accepted (finite) state
  std::int64_t steps = 0;     ///< accepted steps
  std::int64_t rejected = 0;  ///< rejected trial steps (adaptive methods)
  double last_step = 0.0;     ///< size of the last accepted step
  /// The attitude of `state` (body → inertial), when the run carried one.
  std::optional<Quaternion> attitude{};
  /// The largest renormalisation |‖q‖ − 1| of the attitude in one step (0 without an attitude).
  double attitude_projection = 0.0;
};

}  // namespace newtop
