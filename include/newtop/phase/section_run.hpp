#pragma once
/// \file
/// The section's observer, generic in the state type (a body's State; the orbit model's
/// OrbitState in orbit/orbit_section.hpp), and the run of one orbit on a BasicModel<F> (templates;
/// section.hpp declares the run on a Model, compiled once in the library).

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "newtop/integrate/methods.hpp"
#include "newtop/phase/one_step.hpp"
#include "newtop/phase/section.hpp"

namespace newtop::phase {

namespace detail {

struct SectionDone {};

/// The observer, generic in the state type X (a body's State, an OrbitState): watches g at the
/// accepted steps, locates crossings and hands every accepted state and crossing to `watch` (the
/// integrals' drift). `map(t, x, τ)` is the method's one-step map from (t, x) by τ; `g(x)` and
/// `g.scale(x)` the surface function and the size of its terms.
template <class X, class Map, class G, class Watch>
struct SectionObserver {
  SectionObserver(Map m, const G& gf, Watch w, const SectionSettings& st, int k,
                  std::vector<BasicCrossing<X>>& o, SectionRun& r)
      : map(std::move(m)), g(gf), watch(std::move(w)), settings(st), orbit(k), out(o), run(r) {}
  Map map;
  const G& g;
  Watch watch;
  const SectionSettings& settings;
  int orbit;
  std::vector<BasicCrossing<X>>& out;
  SectionRun& run;
  std::int64_t found = 0;
  bool first = true;
  bool on_surface = false;  ///< the previous point is a seed on the surface
  double t_prev = 0, g_prev = 0;
  X x_prev;

  void record(double t, const X& x) {
    out.push_back({orbit, t, x});
    watch(x);
    const double r = std::abs(g(x));
    run.max_residual = std::max(run.max_residual, r);
    const double sc = g.scale(x);
    if (sc > 0) run.max_relative = std::max(run.max_relative, r / sc);
    if (++found >= settings.max_crossings) throw SectionDone{};
  }

  bool kept(double g0, double g1) const {
    const bool up = g0 < 0 && g1 >= 0, down = g0 > 0 && g1 <= 0;
    switch (settings.direction) {
      case Direction::up:
        return up;
      case Direction::down:
        return down;
      default:
        return up || down;
    }
  }

  void operator()(double t, const X& x) {
    watch(x);
    const double gx = g(x);
    if (first) {
      first = false;
      t_prev = t;
      x_prev = x;
      g_prev = gx;
      if (settings.start_on_surface) {
        g_prev = 0.0;  // on the surface: the next sign change is the next crossing
        on_surface = true;
        record(t, x);
      }
      return;
    }
    if (on_surface) {  // the first step leaves the seed's crossing (backward: 0 ends that step)
      on_surface = false;
      t_prev = t;
      x_prev = x;
      g_prev = gx;
      return;
    }
    // The direction is that of g in time: on a backward run (t < t_prev) g goes from gx at the
    // earlier time to g_prev at the later one.
    if (t > t_prev ? kept(g_prev, gx) : kept(gx, g_prev)) locate(t, x);
    t_prev = t;
    x_prev = x;
    g_prev = gx;
  }

  void locate(double t, const X& x) {
    const double h = t - t_prev;
    auto f = [&](double tau) { return g(map(t_prev, x_prev, tau)); };
    const double f_end = f(h);
    if (!((g_prev < 0) == (f_end > 0) || f_end == 0)) {
      record(t, x);  // no bracket in the map's own values (g at round-off): the step's end
      return;
    }
    std::uintmax_t iters = 100;
    const auto tol = boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits);
    // TOMS 748 takes its bracket in increasing order: [h, 0] on a backward run.
    const auto r = h > 0 ? boost::math::tools::toms748_solve(f, 0.0, h, g_prev, f_end, tol, iters)
                         : boost::math::tools::toms748_solve(f, h, 0.0, f_end, g_prev, tol, iters);
    const X a = map(t_prev, x_prev, r.first), b = map(t_prev, x_prev, r.second);
    if (std::abs(g(a)) <= std::abs(g(b))) {
      record(t_prev + r.first, a);
    } else {
      record(t_prev + r.second, b);
    }
  }
};

/// Runs `drive(observer)` (an integration calling observer(t, x) at its start and every accepted
/// step) with the section's observer; stops at max_crossings. `outcome(t, x)` records the last
/// state seen; `drive` returns the run's status.
template <class X, class Map, class G, class Watch, class Drive, class Seen>
bool observe_section(Map map, const G& g, Watch watch, const SectionSettings& settings, int orbit,
                     std::vector<BasicCrossing<X>>& out, SectionRun& run, Drive&& drive,
                     Seen&& seen) {
  SectionObserver<X, Map, G, Watch> obs(std::move(map), g, std::move(watch), settings, orbit, out,
                                        run);
  try {
    drive([&](double t, const X& x) {
      seen(t, x);
      obs(t, x);
    });
  } catch (const SectionDone&) {
    return true;
  }
  return false;
}

}  // namespace detail

/// The crossings of one orbit from (t0, x0) to t1 with the method of `method`, appended to
/// `out`; `drift` follows the integrals at every accepted step and crossing.
template <Field F>
SectionRun section_orbit(const MethodSettings& method, const BasicModel<F>& model,
                         const SurfaceFunction& g, const SectionSettings& settings, int orbit,
                         const State& x0, double t0, double t1, IntegrateOptions options,
                         std::vector<Crossing>& out, IntegralsDrift& drift,
                         const std::function<void(double)>& on_step = {}) {
  options.step = method.step;
  SectionRun run;
  with_stepper(method, [&](auto& s) {
    using S = std::decay_t<decltype(s)>;
    auto map = [m = OneStepMap<S>(s), &model](double, const State& x, double tau) mutable {
      return m(model, x, tau);
    };
    auto watch = [&](const State& x) { drift.observe(integrals(model, x)); };
    auto seen = [&](double t, const State& x) {
      if (on_step) on_step(t);
      run.outcome.t = t;
      run.outcome.state = x;
    };
    auto drive = [&](auto&& observer) {
      run.outcome = integrate(s, model, x0, t0, t1, options, observer);
    };
    if (detail::observe_section<State>(std::move(map), g, watch, settings, orbit, out, run, drive,
                                       seen)) {
      run.by_crossings = true;
      run.outcome.status = Status::finished;
    }
  });
  return run;
}

}  // namespace newtop::phase
