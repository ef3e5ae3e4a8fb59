#pragma once
// Test helper: times at which a scalar function of the state crosses zero upwards, found on the
// dense output of Dormand–Prince 5(4) and refined by bisection: an event-detected period that is
// independent of the analytic solutions under test.

#include <functional>
#include <vector>

#include "newtop/integrate/runge_kutta.hpp"

namespace newtop::test {

inline std::vector<double> upward_crossings(const QuadraticModel& model, const State& x0,
                                            double t_end,
                                            const std::function<double(const State&)>& f,
                                            double tol = 1e-13) {
  Dopri5Dense<QuadraticField> dense(model, tol, tol);
  dense.initialize(x0, 0.0, 1e-3);
  std::vector<double> times;
  while (dense.current_time() < t_end) {
    const auto [a, b] = dense.do_step();
    double fa = f(dense.calc_state(a)), fb = f(dense.calc_state(b));
    if (fa < 0 && fb >= 0) {
      double lo = a, hi = b;
      for (int i = 0; i < 80 && hi - lo > 1e-15 * (1 + hi); ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(dense.calc_state(mid)) < 0 ? lo : hi) = mid;
      }
      times.push_back(0.5 * (lo + hi));
    }
  }
  return times;
}

}  // namespace newtop::test
