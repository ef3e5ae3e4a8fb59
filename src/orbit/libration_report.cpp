// The libration report (orbit/libration_report.hpp): resonances, Floquet multipliers and the
// periapsis section of the planar pitch motion on a Kepler orbit.

#include "newtop/orbit/libration_report.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "newtop/core/types.hpp"

namespace newtop {
namespace {

constexpr double kPlanarTolerance = 1e-9;  // of the initial state, as read
constexpr int kMaxIterates = 100000;

void check(const LibrationRequest& r) {
  if (r.iterates < 1 || r.iterates > kMaxIterates) {
    throw InputError("iterates: expected 1 to 100000, found " + std::to_string(r.iterates));
  }
}

void step(const LibrationRequest& r) {
  if (r.on_step) r.on_step(0.0);
}

LibrationResonance resonance_of(const PitchProblem& problem, const SpinOrbitResonance& r,
                                const LibrationRequest& request) {
  LibrationResonance out;
  out.resonance = r;
  out.spin_ratio = double(r.p) / r.q;
  out.strength = resonance_strength(out.spin_ratio, problem.eccentricity);
  out.averaged_half_width = averaged_half_width(problem, out.spin_ratio);
  out.solutions = periodic_solutions(problem, r);
  if (request.asymmetric) {
    out.asymmetric_solutions.emplace();
    for (const PeriodicSolution& s : shoot_periodic_solutions(problem, r)) {
      if (s.symmetry_distance > kSymmetryTolerance) out.asymmetric_solutions->push_back(s);
    }
  }
  return out;
}

}  // namespace

EllipticOrbit pitch_orbit(const std::variant<CircularOrbit, EllipticOrbit>& orbit,
                          const std::string& context) {
  if (const auto* e = std::get_if<EllipticOrbit>(&orbit)) return *e;
  const auto& c = std::get<CircularOrbit>(orbit);
  if (!(c.rate > 0) || c.lambda_ != 3.0 * c.rate * c.rate) {
    throw InputError(context + "[orbit]: expected a Kepler orbit (lambda = 3 rate^2) for " +
                     "the pitch libration, found rate " + format_number(c.rate) + " and lambda " +
                     format_number(c.lambda_));
  }
  return EllipticOrbit::from_mean_motion(c.rate, 0.0, 0.0);
}

LibrationReport libration_report(const Body& body,
                                 const std::variant<CircularOrbit, EllipticOrbit>& orbit,
                                 const OrbitState& initial, const LibrationRequest& request,
                                 const std::string& context) {
  const EllipticOrbit kepler = pitch_orbit(orbit, context);
  // The pitch axis is the principal axis along the orbit normal, whichever it is.
  const PitchFrame frame = pitch_frame(body, initial);
  const PitchProblem problem = pitch_problem(frame.body, kepler);
  check(request);
  // The start, carried to the first periapsis ν = 2πj ≥ ν0.
  const double nu0 = kepler.true_anomaly0;
  const double periapsis = 2 * std::numbers::pi * std::ceil(nu0 / (2 * std::numbers::pi));
  const Vec2 x0 = pitch_advance(
      problem, pitch_state(frame.body, kepler, frame.state, nu0, kPlanarTolerance), nu0, periapsis);
  std::vector<Vec2> starts{x0};
  if (const auto& s = request.spin) {
    for (int i = 0; i < s->n; ++i) {
      const double w = s->n == 1 ? s->lo : s->lo + (s->hi - s->lo) * i / (s->n - 1);
      starts.emplace_back(0.0, dtheta_from_spin(problem.eccentricity, w));
    }
  }
  LibrationReport out;
  out.eccentricity = problem.eccentricity;
  out.k = problem.k;
  out.iterates = request.iterates;
  out.chaos_threshold = chaos_threshold(request.iterates);
  for (const SpinOrbitResonance& r : request.resonances) {
    step(request);
    out.resonances.push_back(resonance_of(problem, r, request));
  }
  for (const Vec2& x : starts) {
    step(request);
    out.starts.push_back(periapsis_section(problem, x[0], x[1], request.iterates));
    out.chaotic_starts += out.starts.back().chaotic;
  }
  return out;
}

}  // namespace newtop
