#pragma once
/// \file
/// The times at which a user asks for output: t0 + k·D, or a list (sampled.hpp runs to them).

#include <cstdint>
#include <vector>

namespace newtop {

/// The times at which a run reports its state, in the direction of the run.
class OutputTimes {
 public:
  /// t0 + k·D·sign(t1 − t0) for k = 0, 1, …, n, every such time up to t1. Each is one product and
  /// one sum, never accumulated. When t0 + (n + 1)·D lies past t1 by no more than 4 ulp of t1 (a
  /// rounding of a time meant to be t1, as 3 · 0.1 = 0.30000000000000004 for t1 = 0.3), the last
  /// time is t1 itself. Throws InputError for D not a finite number > 0, non-finite times, or more
  /// than kMaxStepCount times.
  static OutputTimes every(double D, double t0, double t1);
  /// The given times: finite, inside [t0, t1] (or [t1, t0]) and strictly ordered in the run's
  /// direction; throws InputError naming the first one that is not.
  static OutputTimes list(std::vector<double> times, double t0, double t1);

  std::int64_t size() const { return n_; }
  double operator[](std::int64_t k) const;
  /// D for OutputTimes::every, 0 for a list.
  double interval() const { return D_; }

 private:
  double t0_ = 0, t1_ = 0, D_ = 0, dir_ = 1;
  std::int64_t n_ = 0;
  bool last_is_t1_ = false;
  std::vector<double> list_;
};

}  // namespace newtop
