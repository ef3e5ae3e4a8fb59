#include "newtop/integrate/driver.hpp"

#include <algorithm>

#include "newtop/integrate/output_times.hpp"

namespace newtop {
namespace {

// Output times within this many ulp past t1 are roundings of t1 (OutputTimes::every).
constexpr double kEndSlackUlp = 4.0;

/// "N STEPS (at most 2^53 = … can be counted)"
std::string count_text(double n, const std::string& what) {
  return format_number(n) + " " + what + " (at most 2^53 = " + format_number(kMaxStepCount) +
         " can be counted)";
}

}  // namespace

void check_time_span(double t0, double t1) {
  if (!std::isfinite(t0))
    throw InputError("t0: expected a finite time, found " + format_number(t0));
  if (!std::isfinite(t1)) {
    throw InputError("t_end: expected a finite time, found " + format_number(t1));
  }
  if (!std::isfinite(t1 - t0)) {
    throw InputError("t_end: the span t_end - t0 = " + format_number(t1) + " - " +
                     format_number(t0) + " overflows");
  }
}

std::int64_t fixed_step_count(double t0, double t1, double step) {
  check_time_span(t0, t1);
  if (!(std::isfinite(step) && step > 0)) {
    throw InputError("step: expected a finite step > 0, found " + format_number(step));
  }
  const double n = std::ceil(std::abs(t1 - t0) / step);
  if (!(n <= kMaxStepCount)) {
    throw InputError("step: the run from t0 = " + format_number(t0) +
                     " to t_end = " + format_number(t1) + " at step " + format_number(step) +
                     " would take " + count_text(n, "steps"));
  }
  return static_cast<std::int64_t>(n);
}

void check_options(const IntegrateOptions& opt) {
  if (!(std::isfinite(opt.initial_step) && opt.initial_step >= 0)) {
    throw InputError("initial_step: expected a finite step >= 0 (0: estimated), found " +
                     format_number(opt.initial_step));
  }
  if (!(opt.min_step_factor > 0 && opt.min_step_factor < 1)) {
    throw InputError("min_step_factor: expected a number in (0, 1), found " +
                     format_number(opt.min_step_factor));
  }
  if (opt.max_steps < 1) {
    throw InputError("max_steps: expected an integer >= 1, found " + std::to_string(opt.max_steps));
  }
}

void check_state(const State& x) {
  if (!x.m.allFinite())
    throw InputError("m: expected a finite vector, found " + format_vector(x.m));
  if (!x.gamma.allFinite()) {
    throw InputError("gamma: expected a finite vector, found " + format_vector(x.gamma));
  }
}

void check_state(const OrientedState& x) {
  check_state(static_cast<const State&>(x));
  const double n = x.q.norm();
  if (!(x.q.coeffs().allFinite() && std::abs(n - 1.0) <= kUnitQuaternionTolerance)) {
    const auto q = scalar_first(x.q);
    throw InputError("quaternion: expected a finite unit quaternion (|norm - 1| <= " +
                     format_number(kUnitQuaternionTolerance) + "), found [" + format_number(q[0]) +
                     ", " + format_number(q[1]) + ", " + format_number(q[2]) + ", " +
                     format_number(q[3]) + "]");
  }
}

OutputTimes OutputTimes::every(double D, double t0, double t1) {
  check_time_span(t0, t1);
  if (!(std::isfinite(D) && D > 0)) {
    throw InputError("dt: expected a finite output interval > 0, found " + format_number(D));
  }
  const double resolution =
      kEndSlackUlp * std::numeric_limits<double>::epsilon() * std::max(std::abs(t0), std::abs(t1));
  if (!(D > resolution)) {
    throw InputError("dt: expected an output interval above the resolution " +
                     format_number(resolution) + " of the times (4 ulp), found " +
                     format_number(D));
  }
  OutputTimes o;
  o.t0_ = t0, o.t1_ = t1, o.D_ = D, o.dir_ = t1 < t0 ? -1.0 : 1.0;
  const double span = std::abs(t1 - t0);
  double n = std::floor(span / D);
  if (!(n + 1 <= kMaxStepCount)) {
    throw InputError("dt: the run from t0 = " + format_number(t0) +
                     " to t_end = " + format_number(t1) + " at output interval " +
                     format_number(D) + " would give " + count_text(n + 1, "output times"));
  }
  // The division may round either way: settle n on the times as they are computed.
  auto at = [&](double k) { return t0 + o.dir_ * k * D; };
  while (n > 0 && o.dir_ * (at(n) - t1) > 0) n -= 1;
  while (o.dir_ * (at(n + 1) - t1) <= 0) n += 1;
  const double slack = kEndSlackUlp * std::numeric_limits<double>::epsilon() * std::abs(t1);
  if (o.dir_ * (at(n + 1) - t1) <= slack && at(n) != t1) {
    n += 1;
    o.last_is_t1_ = true;
  }
  o.n_ = static_cast<std::int64_t>(n) + 1;
  return o;
}

OutputTimes OutputTimes::list(std::vector<double> times, double t0, double t1) {
  check_time_span(t0, t1);
  OutputTimes o;
  o.t0_ = t0, o.t1_ = t1, o.dir_ = t1 < t0 ? -1.0 : 1.0;
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    if (!(std::isfinite(t) && t >= lo && t <= hi)) {
      throw InputError("times: expected times in the run [" + format_number(lo) + ", " +
                       format_number(hi) + "], found " + format_number(t));
    }
    if (i > 0 && !(o.dir_ * (t - times[i - 1]) > 0)) {
      throw InputError(std::string("times: expected strictly ") +
                       (o.dir_ > 0 ? "increasing" : "decreasing") + " times, found " +
                       format_number(t) + " after " + format_number(times[i - 1]));
    }
  }
  o.n_ = static_cast<std::int64_t>(times.size());
  o.list_ = std::move(times);
  return o;
}

double OutputTimes::operator[](std::int64_t k) const {
  if (!list_.empty()) return list_[static_cast<std::size_t>(k)];
  if (last_is_t1_ && k == n_ - 1) return t1_;
  return t0_ + dir_ * static_cast<double>(k) * D_;
}

}  // namespace newtop
