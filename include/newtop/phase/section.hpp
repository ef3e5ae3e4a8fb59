#pragma once
/// \file
/// Poincaré sections (docs/section.md): the crossings of a trajectory with a surface g = 0,
/// located on the method's own solution. An observer of the driver watches the sign of g at the
/// accepted steps; when it changes in the kept direction between x_{n−1} and x_n, the root τ* of
/// τ ↦ g(Φ_τ(x_{n−1})) on [0, t_n − t_{n−1}] is found by TOMS748 (Boost.Math) to the last bit of
/// τ, Φ_τ being the method's one-step map (one_step.hpp). The crossing is Φ_τ*(x_{n−1}): a point
/// of the method's solution with step τ*, on the surface to the rounding of g. The run itself
/// continues from x_n untouched, so locating crossings never perturbs the trajectory.
/// Declarations only; the observer and the run on a BasicModel<F> are in section_run.hpp.

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/integrate/outcome.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/model/model.hpp"
#include "newtop/phase/surface.hpp"

namespace newtop::phase {

/// Which crossings are kept: up (g from negative to non-negative), down, or both.
enum class Direction { up, down, both };

/// "up", "down", "both".
const char* to_string(Direction d);
/// Parses "up", "down" or "both"; InputError naming `field` otherwise.
Direction parse_direction(std::string_view s, std::string_view field = "--direction");

/// A located crossing of orbit `orbit` at the independent variable t (the time; the true anomaly
/// on an elliptic orbit) with the state x (a body's State, or an OrbitState).
template <class X>
struct BasicCrossing {
  int orbit = 0;
  double t = 0.0;
  X x;
};
using Crossing = BasicCrossing<State>;

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

/// The drift of the integrals over a run: the model's one observer (model/integrals.hpp).
using newtop::IntegralsDrift;

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

/// The crossings of one orbit from (t0, x0) to t1 with the method of `method`, appended to
/// `out`; `drift` follows the integrals at every accepted step and crossing. Compiled once for
/// every field (section_run.hpp holds the template on a BasicModel<F>).
SectionRun section_orbit(const MethodSettings& method, const Model& model, const SurfaceFunction& g,
                         const SectionSettings& settings, int orbit, const State& x0, double t0,
                         double t1, IntegrateOptions options, std::vector<Crossing>& out,
                         IntegralsDrift& drift, const std::function<void(double)>& on_step = {});

/// How a section of one start ended.
enum class SectionStatus {
  crossings,    ///< max_crossings reached
  t_end,        ///< the run reached t_end
  cap,          ///< no t_end: the run hit its step cap before max_crossings
  no_crossing,  ///< the run ended (at t_end or the cap) without a single crossing
  failed,       ///< the integration stopped (non-finite state, step limit, step underflow)
};

/// "crossings", "t_end", "cap", "no_crossing", "failed".
const char* to_string(SectionStatus s);

/// Everything a section of one start needs.
struct SectionRequest {
  MethodSettings method{};
  Surface surface{};  ///< parse_surface's result (of ω, m and γ on a body)
  Direction direction = Direction::up;
  std::int64_t max_crossings = 1000;
  /// The start lies on the surface and is the first crossing (a seeded orbit).
  bool start_on_surface = false;
  double t0 = 0.0;
  /// None: forward until max_crossings, at most options.max_steps steps (a fixed-step run is
  /// given twice that span, an adaptive one a span of 10^12 whose step-underflow floor stays that
  /// of a run of span 1).
  std::optional<double> t_end{};
  IntegrateOptions options{};  ///< max_steps, min_step_factor (the step is the method's)
  int orbit = 0;               ///< the label of the crossings
  /// Called after every accepted step with the time (throws to stop the run).
  std::function<void(double)> on_step{};
};

/// The section of one start.
struct SectionResult {
  SectionStatus status = SectionStatus::no_crossing;
  Outcome outcome;
  std::vector<Crossing> crossings;
  IntegralsDrift drift;       ///< against the start
  double max_residual = 0.0;  ///< max |g| at the crossings
  double max_relative = 0.0;  ///< max |g| / scale of g's terms
};

/// The crossings of the trajectory from x0 with the request's surface (InputError for a state,
/// surface or span that is not valid, before any work).
SectionResult section(const Model& model, const State& x0, const SectionRequest& request);

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
