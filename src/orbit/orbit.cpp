#include "newtop/orbit/orbit.hpp"

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

namespace newtop {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void check_positive(const char* name, double x) {
  if (!std::isfinite(x) || !(x > 0)) {
    throw InputError(std::string(name) + ": expected a finite number > 0, found " +
                     format_number(x));
  }
}

void check_finite(const char* name, double x) {
  if (!std::isfinite(x)) {
    throw InputError(std::string(name) + ": expected a finite number, found " + format_number(x));
  }
}

void check_eccentricity(double e) {
  if (!std::isfinite(e) || e < 0.0 || e >= 1.0) {
    throw InputError("eccentricity: expected 0 <= e < 1 (a closed orbit), found " +
                     format_number(e));
  }
}

/// b = e/(1 + √(1 − e²)), the parameter of the series between E and ν.
double half_parameter(double e) { return e / (1.0 + std::sqrt((1.0 - e) * (1.0 + e))); }

}  // namespace

CircularOrbit CircularOrbit::from_mu_radius(double mu, double radius) {
  check_positive("mu", mu);
  check_positive("radius", radius);
  const double rate = std::sqrt(mu / (radius * radius * radius));
  return {rate, 3.0 * rate * rate};
}

CircularOrbit CircularOrbit::from_rate(double rate) {
  check_positive("rate", rate);
  return {rate, 3.0 * rate * rate};
}

CircularOrbit CircularOrbit::forced(double rate, double lambda) {
  if (!std::isfinite(rate) || rate < 0.0) {
    throw InputError("rate: expected a finite number >= 0, found " + format_number(rate));
  }
  check_finite("lambda", lambda);
  return {rate, lambda};
}

EllipticOrbit EllipticOrbit::from_mu_axis(double mu, double semi_major_axis, double eccentricity,
                                          double true_anomaly) {
  check_positive("mu", mu);
  check_positive("semi_major_axis", semi_major_axis);
  const double a = semi_major_axis;
  return from_mean_motion(std::sqrt(mu / (a * a * a)), eccentricity, true_anomaly);
}

EllipticOrbit EllipticOrbit::from_mean_motion(double mean_motion, double eccentricity,
                                              double true_anomaly) {
  check_positive("mean_motion", mean_motion);
  check_eccentricity(eccentricity);
  check_finite("true_anomaly", true_anomaly);
  return {eccentricity, mean_motion, true_anomaly};
}

double lambda_at(const EllipticOrbit& o, double nu) {
  const double e = o.eccentricity;
  const double x = (1.0 + e * std::cos(nu)) / ((1.0 - e) * (1.0 + e));
  return 3.0 * o.mean_motion * o.mean_motion * x * x * x;
}

double anomaly_rate(const EllipticOrbit& o, double nu) { return 1.0 / time_per_anomaly(o, nu); }

double time_per_anomaly(const EllipticOrbit& o, double nu) {
  const double e = o.eccentricity;
  const double one_minus_e2 = (1.0 - e) * (1.0 + e);
  const double d = 1.0 + e * std::cos(nu);
  return one_minus_e2 * std::sqrt(one_minus_e2) / (o.mean_motion * d * d);
}

double eccentric_anomaly(double e, double nu) {
  const double b = half_parameter(e);
  return nu - 2.0 * std::atan(b * std::sin(nu) / (1.0 + b * std::cos(nu)));
}

double elapsed_time(const EllipticOrbit& o, double nu1, double nu2) {
  const double e = o.eccentricity;
  // Whole revolutions take 2π/n each; the remainder r ∈ [−π, π] is measured from ν1.
  const double turns = std::round((nu2 - nu1) / kTwoPi);
  const double r = (nu2 - nu1) - kTwoPi * turns;
  const double nu2r = nu1 + r;
  // tan(E/2) = β tan(ν/2): the difference of half-angles as one atan2 (same quadrant rule as the
  // half-angles, |ΔE| < 2π), so that ΔE carries no cancellation for short arcs.
  const double beta = std::sqrt((1.0 - e) / (1.0 + e));
  const double s1 = std::sin(0.5 * nu1), c1 = std::cos(0.5 * nu1);
  const double s2 = std::sin(0.5 * nu2r), c2 = std::cos(0.5 * nu2r);
  const double dE = 2.0 * std::atan2(beta * std::sin(0.5 * r), c1 * c2 + beta * beta * s1 * s2);
  // ΔM = ΔE − e (sin E2 − sin E1) = ΔE − 2e cos(E1 + ΔE/2) sin(ΔE/2).
  const double E_mid = eccentric_anomaly(e, nu1) + 0.5 * dE;
  const double dM = dE - 2.0 * e * std::cos(E_mid) * std::sin(0.5 * dE);
  return (kTwoPi * turns + dM) / o.mean_motion;
}

double true_anomaly_at(const EllipticOrbit& o, double t) {
  const double e = o.eccentricity;
  const double E0 = eccentric_anomaly(e, o.true_anomaly0);
  const double M = E0 - e * std::sin(E0) + o.mean_motion * t;
  if (!std::isfinite(M)) {
    throw InputError("t: expected a time whose mean anomaly n*t is finite, found t = " +
                     format_number(t));
  }
  // Whole turns apart: Kepler's equation is solved for the mean anomaly Mr ∈ [−π, π], so that the
  // bracket [Mr − e, Mr + e] stays an interval however large n t is, and ν = 2πk + νr.
  const double turns = std::round(M / kTwoPi);
  const double Mr = M - kTwoPi * turns;
  // Kepler's equation E − e sin E = Mr has its root in [Mr − e, Mr + e]; Newton safeguarded by it.
  auto f = [&](double E) {
    return std::make_tuple(E - e * std::sin(E) - Mr, 1.0 - e * std::cos(E));
  };
  std::uintmax_t iterations = 100;
  const double E =
      e == 0.0 ? Mr
               : boost::math::tools::newton_raphson_iterate(f, Mr, Mr - e, Mr + e, 52, iterations);
  const double b = half_parameter(e);
  return kTwoPi * turns + (E + 2.0 * std::atan(b * std::sin(E) / (1.0 - b * std::cos(E))));
}

namespace {

/// Earth's μ in m³/s² (scale 1) or in km³/s² (scale 1e-9), within 1 %.
bool is_earth_mu(double mu, double scale) { return std::abs(mu / (kEarthMu * scale) - 1.0) < 0.01; }

}  // namespace

std::string orbit_units(double mu) {
  if (is_earth_mu(mu, 1.0)) return "m, s (SI; Earth's mu in m^3/s^2)";
  if (is_earth_mu(mu, 1e-9)) return "km, s (Earth's mu in km^3/s^2)";
  return "the length unit of the radius and the time unit implied by mu";
}

std::vector<std::string> orbit_unit_warnings(double mu, double radius) {
  std::vector<std::string> w;
  const double rate = std::sqrt(mu / (radius * radius * radius));
  if (rate > 1.0) {
    w.push_back("orbit: rate sqrt(mu/R^3) = " + format_number(rate) +
                " rad per time unit (a period of " + format_number(2 * std::numbers::pi / rate) +
                "): mu and the radius look like a unit mix (mu in m^3/s^2 with R in km?)");
  }
  for (const double scale : {1.0, 1e-9}) {
    const double earth = kEarthRadius * (scale == 1.0 ? 1.0 : 1e-3);
    if (is_earth_mu(mu, scale) && radius < earth) {
      w.push_back("orbit: radius " + format_number(radius) + " is below Earth's (" +
                  format_number(earth) +
                  ") for Earth's mu: an altitude given as a radius? (radius = Earth's radius + "
                  "altitude)");
    }
  }
  return w;
}

}  // namespace newtop
