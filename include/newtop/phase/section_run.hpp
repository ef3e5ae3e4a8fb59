#pragma once
/// \file
/// The section's observer and the run of one orbit on a BasicModel<F> (templates; section.hpp
/// declares the run on a Model, compiled once in the library).

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

/// The observer: watches g, locates crossings, keeps the integrals' drift.
template <class Map, class M>
struct SectionObserver {
  SectionObserver(Map m, const M& mod, const SurfaceFunction& gf, const SectionSettings& st, int k,
                  std::vector<Crossing>& o, IntegralsDrift& d, SectionRun& r)
      : map(std::move(m)), model(mod), g(gf), settings(st), orbit(k), out(o), drift(d), run(r) {}
  Map map;
  const M& model;
  const SurfaceFunction& g;
  const SectionSettings& settings;
  int orbit;
  std::vector<Crossing>& out;
  IntegralsDrift& drift;
  SectionRun& run;
  std::int64_t found = 0;
  bool first = true;
  double t_prev = 0, g_prev = 0;
  State x_prev;

  void record(double t, const State& x) {
    out.push_back({orbit, t, x});
    drift.observe(integrals(model, x));
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

  void operator()(double t, const State& x) {
    drift.observe(integrals(model, x));
    const double gx = g(x);
    if (first) {
      first = false;
      t_prev = t;
      x_prev = x;
      g_prev = gx;
      if (settings.start_on_surface) {
        g_prev = 0.0;  // on the surface: the next sign change is the next crossing
        record(t, x);
      }
      return;
    }
    if (kept(g_prev, gx)) locate(t, x);
    t_prev = t;
    x_prev = x;
    g_prev = gx;
  }

  void locate(double t, const State& x) {
    const double h = t - t_prev;
    auto f = [&](double tau) { return g(map(model, x_prev, tau)); };
    const double f_end = f(h);
    if (!((g_prev < 0) == (f_end > 0) || f_end == 0)) {
      record(t, x);  // no bracket in the map's own values (g at round-off): the step's end
      return;
    }
    std::uintmax_t iters = 100;
    const auto tol = boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits);
    const auto r = boost::math::tools::toms748_solve(f, 0.0, h, g_prev, f_end, tol, iters);
    const State a = map(model, x_prev, r.first), b = map(model, x_prev, r.second);
    if (std::abs(g(a)) <= std::abs(g(b))) {
      record(t_prev + r.first, a);
    } else {
      record(t_prev + r.second, b);
    }
  }
};

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
    detail::SectionObserver<OneStepMap<S>, BasicModel<F>> obs(OneStepMap<S>(s), model, g, settings,
                                                              orbit, out, drift, run);
    auto observer = [&](double t, const State& x) {
      if (on_step) on_step(t);
      run.outcome.t = t;
      run.outcome.state = x;
      obs(t, x);
    };
    try {
      run.outcome = integrate(s, model, x0, t0, t1, options, observer);
    } catch (const detail::SectionDone&) {
      run.by_crossings = true;
      run.outcome.status = Status::finished;
    }
  });
  return run;
}

}  // namespace newtop::phase
