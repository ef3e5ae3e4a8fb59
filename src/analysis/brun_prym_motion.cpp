// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <algorithm>
#include <cmath>

#include "newtop/analysis/brun_prym.hpp"
#include "newtop/core/types.hpp"
#include "newtop/integrate/methods.hpp"

namespace newtop {
namespace {

// The reference motion between interval ends (the rkf78 at 1e-14).
constexpr double kReferenceTol = 1e-14;
// Longest interval of one Abel–Prym increment, and the fixed splitting8 steps that give the states
// inside it as a smooth function of t (h ≤ 1/64: error ~1e-15 at the speeds of a unit-size body).
constexpr double kInterval = 0.5;
constexpr int kInnerSteps = 32;
// Agreement asked of two bisection levels of an interval's quadrature.
constexpr double kQuadrature = 1e-12;

}  // namespace

std::vector<std::array<std::complex<double>, 2>> brun_prym_sums_along(
    const QuadraticModel& model, const State& x0, std::span<const double> times) {
  const BrunCurve k = brun_level(model, x0);
  std::vector<std::array<std::complex<double>, 2>> out;
  out.reserve(times.size());
  State start = x0;
  double t_start = 0;
  MethodSettings inner;
  inner.name = "splitting8";
  const BrunMotion motion = [&](double t) {
    if (t == t_start) return start;
    MethodSettings m = inner;
    m.step = (t - t_start) / kInnerSteps;
    return run_method(m, model, start, t_start, t).state;
  };
  std::array<std::complex<double>, 2> sum{};
  for (double t : times) {
    if (!(t >= t_start)) {
      throw InputError("Brun Abel-Prym sums: expected ascending times >= 0, found " +
                       std::to_string(t));
    }
    while (t_start < t) {
      const double t1 = std::min(t, t_start + kInterval);
      const auto inc = brun_prym_abel_increment(k, motion, t_start, t1, kQuadrature);
      sum[0] += inc[0], sum[1] += inc[1];
      Fehlberg78Stepper s(kReferenceTol, kReferenceTol);
      start = integrate(s, model, start, t_start, t1, {}).state;
      t_start = t1;
    }
    out.push_back(sum);
  }
  return out;
}

}  // namespace newtop
