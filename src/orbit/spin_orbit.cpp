// Spin–orbit resonances of Beletsky's equation: symmetric periodic solutions by shooting, their
// Floquet multipliers, and the Goldreich–Peale averaged strengths (docs/orbit.md §9).

#include "newtop/orbit/spin_orbit.hpp"

#include <boost/math/quadrature/trapezoidal.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>

namespace newtop {

namespace {
// Newton steps on the shooting condition after TOMS 748, and the step below which they stop.
constexpr int kNewtonSteps = 8;
constexpr double kNewtonStop = 1e-14;
// Pieces of the period over which the deviation from the uniform rotation is sampled.
constexpr int kDeviationSamples = 128;
}  // namespace

SpinOrbitResonance resonance(int p, int q) {
  if (q < 1 || q > 12) {
    throw InputError("resonance " + std::to_string(p) + ":" + std::to_string(q) +
                     ": expected an orbit count q from 1 to 12, found " + std::to_string(q));
  }
  if (p < 0 || p > 12 * q) {
    throw InputError("resonance " + std::to_string(p) + ":" + std::to_string(q) +
                     ": expected a spin count p from 0 to 12q, found " + std::to_string(p));
  }
  // M/(2N) = (p − q)/q  ⇔  M/N = 2(p − q)/q, in lowest terms.
  const int num = 2 * (p - q);
  const int g = std::gcd(std::abs(num), q);
  return {p, q, q / g, num / g};
}

const char* to_string(FloquetStability s) {
  switch (s) {
    case FloquetStability::stable:
      return "stable";
    case FloquetStability::unstable:
      return "unstable";
    case FloquetStability::parabolic:
      return "parabolic";
  }
  return "?";
}

namespace {

/// Multipliers and verdict of a monodromy matrix (2×2, det ≈ 1).
void floquet(PeriodicSolution& s) {
  const double t = s.monodromy.trace(), d = s.monodromy.determinant();
  const std::complex<double> root = std::sqrt(std::complex<double>(t * t / 4 - d));
  s.multipliers[0] = t / 2 + root;
  s.multipliers[1] = t / 2 - root;
  s.stability = std::abs(t) < 2 - kParabolicTrace   ? FloquetStability::stable
                : std::abs(t) > 2 + kParabolicTrace ? FloquetStability::unstable
                                                    : FloquetStability::parabolic;
}

}  // namespace

PeriodicSolution periodic_solution_at(const PitchProblem& p, const SpinOrbitResonance& r,
                                      double theta0, double dtheta0) {
  PeriodicSolution s;
  s.resonance = r;
  s.theta0 = theta0;
  s.dtheta0 = dtheta0;
  const double period = 2 * std::numbers::pi * r.periods;
  const double slope = r.half_turns / (2.0 * r.periods);
  Vec2 x(theta0, dtheta0);
  Mat2 phi = Mat2::Identity();
  for (int i = 0; i < kDeviationSamples; ++i) {
    const double a = period * i / kDeviationSamples, b = period * (i + 1) / kDeviationSamples;
    const PitchFlow f = pitch_flow(p, x, a, b);
    x = f.x;
    phi = f.phi * phi;
    s.max_deviation = std::max(s.max_deviation, std::abs(x[0] - theta0 - slope * b));
  }
  s.monodromy = phi;
  s.residual = (x - Vec2(theta0 + r.half_turns * std::numbers::pi, dtheta0)).norm();
  floquet(s);
  // The reversibility points ν = πj of the period: θ there a multiple of π/2 for a symmetric
  // solution (docs/orbit.md §9).
  Vec2 y(theta0, dtheta0);
  s.symmetry_distance = std::abs(std::remainder(theta0, std::numbers::pi / 2));
  for (int j = 1; j < 2 * r.periods; ++j) {
    y = pitch_advance(p, y, std::numbers::pi * (j - 1), std::numbers::pi * j);
    s.symmetry_distance =
        std::min(s.symmetry_distance, std::abs(std::remainder(y[0], std::numbers::pi / 2)));
  }
  return s;
}

std::vector<PeriodicSolution> periodic_solutions(const PitchProblem& p, const SpinOrbitResonance& r,
                                                 const ResonanceSearch& search) {
  if (search.samples < 2)
    throw InputError("samples: expected >= 2, found " + std::to_string(search.samples));
  const double w =
      search.half_window > 0 ? search.half_window : std::max(0.5, 2 * std::sqrt(3 * std::abs(p.k)));
  const double centre = r.half_turns / (2.0 * r.periods);
  const double half = std::numbers::pi * r.periods;  // ν = πN, the second reversibility point
  std::vector<PeriodicSolution> found;
  for (const double theta0 : {0.0, std::numbers::pi / 2}) {
    const double target = theta0 + r.half_turns * std::numbers::pi / 2;
    auto F = [&](double s) { return pitch_advance(p, Vec2(theta0, s), 0.0, half)[0] - target; };
    double s_prev = centre - w, f_prev = F(s_prev);
    for (int i = 1; i <= search.samples; ++i) {
      const double s_next = centre - w + 2 * w * i / search.samples;
      const double f_next = F(s_next);
      // A zero on a sample is taken once, as the left end of the next bracket.
      if (f_prev == 0 || (f_next != 0 && (f_prev < 0) != (f_next < 0))) {
        double root = s_prev;
        if (f_prev != 0) {
          std::uintmax_t iterations = 200;
          const auto bracket = boost::math::tools::toms748_solve(
              F, s_prev, s_next, f_prev, f_next, boost::math::tools::eps_tolerance<double>(50),
              iterations);
          root = 0.5 * (bracket.first + bracket.second);
        }
        // Newton on the same condition, ∂θ(πN)/∂θ′(0) = Φ₀₁(πN, 0).
        for (int n = 0; n < kNewtonSteps; ++n) {
          const PitchFlow f = pitch_flow(p, Vec2(theta0, root), 0.0, half);
          if (f.phi(0, 1) == 0) break;
          const double step = (f.x[0] - target) / f.phi(0, 1);
          if (!std::isfinite(step) || std::abs(step) > (s_next - s_prev)) break;
          root -= step;
          if (std::abs(step) < kNewtonStop) break;
        }
        found.push_back(periodic_solution_at(p, r, theta0, root));
      }
      s_prev = s_next;
      f_prev = f_next;
    }
  }
  return found;
}

double resonance_strength(double spin_ratio, double eccentricity) {
  const EllipticOrbit orbit = EllipticOrbit::from_mean_motion(1.0, eccentricity, 0.0);
  const double e = eccentricity;
  // H(p, e) = (1/2π) ∫ (a/R)³ cos(2pM − 2ν) dM over a period of the mean anomaly M (n = 1: M = t).
  auto integrand = [&](double m) {
    const double nu = true_anomaly_at(orbit, m);
    const double a_over_r = (1 + e * std::cos(nu)) / (1 - e * e);
    return a_over_r * a_over_r * a_over_r * std::cos(2 * spin_ratio * m - 2 * nu);
  };
  return boost::math::quadrature::trapezoidal(integrand, 0.0, 2 * std::numbers::pi, 1e-14) /
         (2 * std::numbers::pi);
}

double averaged_half_width(const PitchProblem& p, double spin_ratio) {
  return std::sqrt(3 * std::abs(p.k) * std::abs(resonance_strength(spin_ratio, p.eccentricity)));
}

namespace {

/// True when the start (θc, θ′) keeps librating about the centre θc of a resonance of N orbits:
/// after each period θ returns near θc (mod π) and the phase difference, unwrapped, stays within π.
bool librates(const PitchProblem& p, int orbits, double theta_c, double dtheta, int periods) {
  Vec2 x(theta_c, dtheta);
  double unwrapped = 0.0, previous = 0.0;
  for (int j = 0; j < periods; ++j) {
    x = pitch_advance(p, x, 0.0, 2 * std::numbers::pi * orbits);
    const double d = std::remainder(x[0] - theta_c, std::numbers::pi);
    unwrapped += std::remainder(d - previous, std::numbers::pi);
    previous = d;
    if (std::abs(unwrapped) > std::numbers::pi) return false;
  }
  return true;
}

}  // namespace

double measured_half_width(const PitchProblem& p, const PeriodicSolution& centre, int periods) {
  constexpr int kBisections = 30;
  const double e = p.eccentricity;
  const double to_spin = (1 + e) * (1 + e) / std::pow(1 - e * e, 1.5);
  // The averaged half-width bounds the search from above with a wide margin.
  const double ratio = double(centre.resonance.p) / centre.resonance.q;
  const double reach = 3 * std::max(averaged_half_width(p, ratio), 1e-6) / to_spin;
  double edges = 0.0;
  for (const double sign : {1.0, -1.0}) {
    double lo = 0.0, hi = reach;
    for (int i = 0; i < kBisections; ++i) {
      const double mid = 0.5 * (lo + hi);
      const bool inside = librates(p, centre.resonance.periods, centre.theta0,
                                   centre.dtheta0 + sign * mid, periods);
      (inside ? lo : hi) = mid;
    }
    edges += 0.5 * (lo + hi);
  }
  return 0.5 * edges * to_spin;
}

double chaos_threshold(int iterates) {
  const double j = std::max(iterates, 1);
  return (std::log(j) + 5.0) / j;
}

SectionOrbit periapsis_section(const PitchProblem& p, double theta0, double dtheta0, int iterates) {
  if (iterates < 1) throw InputError("iterates: expected >= 1, found " + std::to_string(iterates));
  SectionOrbit o;
  o.theta0 = theta0;
  o.dtheta0 = dtheta0;
  // The equation is 2π-periodic in ν and π-periodic in θ: each orbit is the map over [0, 2π]
  // from θ reduced to [−π/2, π/2).
  Vec2 x(theta0 - std::numbers::pi * std::floor((theta0 + std::numbers::pi / 2) / std::numbers::pi),
         dtheta0);
  Vec2 v = Vec2(1.0, 1.0).normalized();
  double log_growth = 0.0;
  o.points.reserve(static_cast<std::size_t>(iterates));
  for (int j = 0; j < iterates; ++j) {
    const PitchFlow f = pitch_flow(p, x, 0.0, 2 * std::numbers::pi);
    x = f.x;
    x[0] -= std::numbers::pi * std::floor((x[0] + std::numbers::pi / 2) / std::numbers::pi);
    v = f.phi * v;
    const double g = v.norm();
    log_growth += std::log(g);
    v /= g;
    o.points.push_back(x);
  }
  o.lyapunov = log_growth / iterates;
  o.chaotic = o.lyapunov > chaos_threshold(iterates);
  return o;
}

double dtheta_from_spin(double eccentricity, double spin) {
  const double e = eccentricity;
  return spin * std::pow(1 - e * e, 1.5) / ((1 + e) * (1 + e)) - 1;
}

double spin_from_dtheta(double eccentricity, double dtheta) {
  const double e = eccentricity;
  return (1 + dtheta) * (1 + e) * (1 + e) / std::pow(1 - e * e, 1.5);
}

}  // namespace newtop
