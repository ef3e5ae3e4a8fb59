#pragma once
/// \file
/// Poincaré sections (docs/section.md): the crossings of a trajectory with a surface g = 0,
/// located on the method's own solution. An observer of the driver watches the sign of g at the
/// accepted steps; when it changes in the kept direction between x_{n−1} and x_n, the root τ* of
/// τ ↦ g(Φ_τ(x_{n−1})) on [0, t_n − t_{n−1}] is found by TOMS748 (Boost.Math) to the last bit of
/// τ, Φ_τ being the method's one-step map (one_step.hpp). The crossing is Φ_τ*(x_{n−1}): a point
/// of the method's solution with step τ*, on the surface to the rounding of g. The run itself
/// continues from x_n untouched, so locating crossings never perturbs the trajectory.

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "newtop/integrate/methods.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/phase/one_step.hpp"
#include "newtop/phase/surface.hpp"

namespace newtop::phase {

/// Which crossings are kept: up (g from negative to non-negative), down, or both.
enum class Direction { up, down, both };

/// "up", "down", "both".
const char* to_string(Direction d);
/// Parses "up", "down" or "both"; InputError naming `field` otherwise.
Direction parse_direction(std::string_view s, std::string_view field = "--direction");

struct Crossing {
  int orbit = 0;
  double t = 0.0;
  State x;
};

/// The Andoyer–Deprit variables of the reduced motion (docs/section.md): G = |m|, L = m3,
/// l = atan2(m1, m2) (m1 = √(G² − L²) sin l, m2 = √(G² − L²) cos l), and g the angle, in the
/// plane normal to m and about m, from the node γ × m to the node e3 × m. H = m·γ is the area
/// integral. An angle whose nodes vanish (m ∥ e3 or m ∥ γ) is reported as 0.
struct AndoyerDeprit {
  double l = 0, L = 0, g = 0, G = 0, H = 0;
};
AndoyerDeprit andoyer_deprit(const State& x);

/// The momentum conjugate to γ on the cotangent bundle of the sphere: p = m × γ, so that
/// m = γ × p + (m·γ) γ (docs/section.md).
inline Vec3 gamma_momentum(const State& x) { return x.m.cross(x.gamma); }

/// For a surface γ_k = c (one γ coefficient, nothing else): k (0, 1, 2); −1 otherwise.
int gamma_plane_axis(const Surface& s);

/// Largest |I(x) − I(x0)| of each integral that holds (energy, area, geometric, Brun, Lagrange).
struct IntegralsDrift {
  IntegralValues initial, max_drift;
  bool started = false;
  void observe(const IntegralValues& v);
  /// Takes the larger drift of each integral from another run (each against its own start).
  void merge(const IntegralsDrift& other);
};

struct SectionSettings {
  Direction direction = Direction::up;
  std::int64_t max_crossings = 1000;  ///< per orbit
  /// The initial state lies on the surface and is the first crossing (a seeded orbit).
  bool start_on_surface = false;
};

/// What one orbit's run gave.
struct SectionRun {
  Outcome outcome;
  bool by_crossings = false;  ///< stopped at max_crossings (else at t_end or failed)
  double max_residual = 0.0;  ///< max |g| at the crossings
  double max_relative = 0.0;  ///< max |g| / scale of g's terms (in units of 1, not ε)
};

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

/// The levels of the seeded orbits: energy h and area f = m·γ.
struct Levels {
  double energy = 0, area = 0;
};

/// K initial conditions on a surface of γ alone, on the levels (docs/section.md): γ_j evenly
/// spaced in angle on the circle where the plane meets the sphere, φ_j = 2π(j + ½)/K, and
/// m_j = f γ_j + a_j t_j with t_j the unit tangent of the circle at γ_j (the direction of ω that
/// crosses the plane fastest) and a_j the root of the energy equation that crosses in the kept
/// direction (up for both). Points where the energy level misses are left out; an empty result
/// is an empty level. Throws InputError for a surface that is not of γ alone.
std::vector<State> seed_orbits(const Model& model, const Surface& surface, const Levels& levels,
                               int K, Direction direction);

}  // namespace newtop::phase
