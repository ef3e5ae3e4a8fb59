// Fehlberg 7(8) reference for the orbit model, through Boost.Odeint (kept out of public headers).

#include <array>
#include <cmath>
#include <string>

#include "newtop/orbit/orbit_integrate.hpp"

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace newtop {
namespace {

namespace odeint = boost::numeric::odeint;
using Ode9 = std::array<double, 9>;

Ode9 to_ode(const OrbitState& s) {
  return {s.m[0],     s.m[1],      s.m[2],      s.gamma[0], s.gamma[1],
          s.gamma[2], s.normal[0], s.normal[1], s.normal[2]};
}

OrbitState from_ode(const Ode9& y) {
  return {Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5]), Vec3(y[6], y[7], y[8])};
}

bool finite(const Ode9& y) {
  for (double v : y) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

void check_options(const OrbitAdaptiveOptions& o, double t0, double t1) {
  auto positive = [](const char* name, double x) {
    if (!std::isfinite(x) || !(x > 0)) {
      throw InputError(std::string(name) + ": expected a finite number > 0, found " +
                       format_number(x));
    }
  };
  positive("abs_tol", o.abs_tol);
  positive("rel_tol", o.rel_tol);
  if (!std::isfinite(o.initial_step) || o.initial_step < 0) {
    throw InputError("initial_step: expected a finite number >= 0, found " +
                     format_number(o.initial_step));
  }
  if (!std::isfinite(t0) || !std::isfinite(t1)) {
    throw InputError("time span: expected finite ends, found [" + format_number(t0) + ", " +
                     format_number(t1) + "]");
  }
}

/// Controlled Fehlberg 7(8) on any right-hand side f(y, t) of the 9 components, landing on t1.
template <class Rhs>
OrbitOutcome run_adaptive(const Rhs& f, OrbitState x, double t0, double t1,
                          const OrbitAdaptiveOptions& opt, const OrbitObserver& obs) {
  check_options(opt, t0, t1);
  OrbitOutcome out{Status::finished, t0, x, 0, 0};
  if (!finite(to_ode(x))) {
    out.status = Status::non_finite;
    return out;
  }
  if (obs) obs(t0, x);
  const double span = t1 - t0;
  if (span == 0.0) return out;
  const double dir = span > 0 ? 1.0 : -1.0;
  auto system = [&](const Ode9& y, Ode9& dydt, double t) { dydt = to_ode(f(from_ode(y), t)); };
  auto controlled =
      odeint::make_controlled(opt.abs_tol, opt.rel_tol, odeint::runge_kutta_fehlberg78<Ode9>());
  Ode9 y = to_ode(x);
  double t = t0;
  double dt = opt.initial_step > 0 ? dir * opt.initial_step : span / 1000.0;
  const double min_step = opt.min_step_factor * std::max(std::abs(t0), std::abs(span));
  while (dir * (t1 - t) > 0) {
    if (out.steps + out.rejected >= opt.max_steps) {
      out.status = Status::step_limit;
      return out;
    }
    const bool last = dir * (t + dt - t1) >= 0;
    double trial = last ? t1 - t : dt;
    const double t_before = t;
    const Ode9 y_before = y;
    auto r = controlled.try_step(system, y, t, trial);
    if (r == odeint::success && !finite(y)) {
      // A step so long that the state overflowed: its error estimate is NaN and odeint accepts
      // it. Reject it and retry a tenth as long.
      y = y_before;
      t = t_before;
      trial = 0.1 * (last ? t1 - t : dt);
      r = odeint::fail;
    }
    if (r != odeint::success) {
      ++out.rejected;
      dt = trial;
      if (std::abs(dt) < min_step) {
        out.status = Status::step_size_underflow;
        return out;
      }
      continue;
    }
    if (last) t = t1;
    const OrbitState s = from_ode(y);
    ++out.steps;
    out.t = t;
    out.state = s;
    if (obs) obs(t, s);
    if (!last) dt = trial;
    if (std::abs(t - t_before) < min_step && !last) {
      out.status = Status::step_size_underflow;
      return out;
    }
  }
  return out;
}

/// One step of the propagated formula of the pair that run_adaptive controls.
template <class Rhs>
OrbitState one_step(const Rhs& f, const OrbitState& x, double t, double h) {
  auto system = [&](const Ode9& y, Ode9& dydt, double s) { dydt = to_ode(f(from_ode(y), s)); };
  Ode9 y = to_ode(x);
  odeint::runge_kutta_fehlberg78<Ode9>().do_step(system, y, t, h);
  return from_ode(y);
}

}  // namespace

OrbitState rkf78_step(const CircularOrbitModel& model, const OrbitState& x, double t, double h) {
  return one_step([&](const OrbitState& s, double) { return rhs(model, s); }, x, t, h);
}

OrbitState rkf78_step(const EllipticOrbitModel& model, const OrbitState& x, double nu, double h) {
  return one_step([&](const OrbitState& s, double v) { return rhs(model, s, v); }, x, nu, h);
}

OrbitOutcome integrate_adaptive(const CircularOrbitModel& model, OrbitState x, double t0, double t1,
                                const OrbitAdaptiveOptions& options,
                                const OrbitObserver& observer) {
  return run_adaptive([&](const OrbitState& s, double) { return rhs(model, s); }, x, t0, t1,
                      options, observer);
}

OrbitOutcome integrate_adaptive(const EllipticOrbitModel& model, OrbitState x, double nu0,
                                double nu1, const OrbitAdaptiveOptions& options,
                                const OrbitObserver& observer) {
  return run_adaptive([&](const OrbitState& s, double nu) { return rhs(model, s, nu); }, x, nu0,
                      nu1, options, observer);
}

}  // namespace newtop
