#pragma once
/// \file
/// The orbit of the body's centre of mass about a point centre of parameter μ (docs/orbit.md §1):
/// a circular orbit of rate ω0, or a Kepler ellipse of eccentricity e described by its true
/// anomaly ν, with the relations the attitude equations need: λ = 3μ/R³, the orbit's rate ν̇,
/// dt/dν and the time between two anomalies (Kepler's equation).

#include <string>
#include <vector>

#include "newtop/core/types.hpp"

namespace newtop {

/// Circular orbit: the centre → body line turns about the orbit normal n at the constant rate ω0,
/// and the gravity gradient has the constant strength λ = 3μ/R³ (docs/model.md §3). On a Kepler
/// orbit λ = 3ω0²; `forced` lifts that tie for a centre of mass held on its circle by other forces
/// (and for the limit ω0 → 0 at fixed λ, the fixed-centre model of docs/model.md §4).
struct CircularOrbit {
  double rate = 0.0;     ///< ω0 [1/time], the orbit's angular velocity about n
  double lambda_ = 0.0;  ///< λ = 3μ/R³ [1/time²]

  /// Kepler orbit of radius R about a centre of parameter μ: ω0 = √(μ/R³), λ = 3ω0².
  static CircularOrbit from_mu_radius(double mu, double radius);
  /// Kepler orbit of rate ω0 > 0: λ = 3ω0².
  static CircularOrbit from_rate(double rate);
  /// Any ω0 ≥ 0 and finite λ (not a free orbit unless λ = 3ω0²).
  static CircularOrbit forced(double rate, double lambda);
};

/// Kepler ellipse of eccentricity 0 ≤ e < 1 and mean motion n = √(μ/a³), started at the true
/// anomaly ν0 (the angle from periapsis, positive in the sense of the motion, i.e. about n).
/// Distance R(ν) = a(1 − e²)/(1 + e cos ν); μ and a enter the attitude equations only through n.
struct EllipticOrbit {
  double eccentricity = 0.0;   ///< e
  double mean_motion = 0.0;    ///< n = √(μ/a³) [1/time]
  double true_anomaly0 = 0.0;  ///< ν0 [rad] at the start time t0

  /// From μ > 0, the semi-major axis a > 0, 0 ≤ e < 1 and ν0 (finite).
  static EllipticOrbit from_mu_axis(double mu, double semi_major_axis, double eccentricity,
                                    double true_anomaly);
  /// From the mean motion n > 0, 0 ≤ e < 1 and ν0.
  static EllipticOrbit from_mean_motion(double mean_motion, double eccentricity,
                                        double true_anomaly);
};

/// λ(ν) = 3μ/R³ = 3n² ((1 + e cos ν)/(1 − e²))³.
double lambda_at(const EllipticOrbit& orbit, double nu);

/// The orbit's rate ν̇ = n (1 + e cos ν)² / (1 − e²)^{3/2} (areal velocity / R²).
double anomaly_rate(const EllipticOrbit& orbit, double nu);

/// dt/dν = 1/ν̇ = (1 − e²)^{3/2} / (n (1 + e cos ν)²).
double time_per_anomaly(const EllipticOrbit& orbit, double nu);

/// Eccentric anomaly E(ν) = ν − 2 atan(b sin ν / (1 + b cos ν)), b = e/(1 + √(1 − e²)):
/// continuous in ν, equal to ν at every apsis.
double eccentric_anomaly(double eccentricity, double nu);

/// The time t(ν2) − t(ν1) taken to go from ν1 to ν2 (either order, any number of revolutions),
/// by Kepler's equation M = E − e sin E, n t = M. Whole revolutions count 2π/n each; the rest is
/// formed from half-angle differences, so that a short arc keeps full relative precision.
double elapsed_time(const EllipticOrbit& orbit, double nu1, double nu2);

/// The true anomaly reached a time t after the start (ν(0) = ν0), continuous in t: Kepler's
/// equation solved by Newton's method to round-off.
double true_anomaly_at(const EllipticOrbit& orbit, double t);

/// Earth's μ = GM in m³/s² (IERS) and its equatorial radius in m: the numbers unit mixes are
/// recognised by.
inline constexpr double kEarthMu = 3.986004418e14;
inline constexpr double kEarthRadius = 6.378137e6;

/// The units an orbit's μ implies, in words: "m, s (SI; Earth's mu in m^3/s^2)" or "km, s (Earth's
/// mu in km^3/s^2)" within 1 % of Earth's μ, else "the length unit of radius, the time unit of
/// mu" (newtop is unit-free: times follow from μ and R).
std::string orbit_units(double mu);

/// One line per likely unit mix of an orbit of parameter μ and radius (or semi-major axis) R:
/// a rate √(μ/R³) above 1 rad per time unit (Earth's μ in m³/s² with R in km), a radius below
/// Earth's for Earth's μ (an altitude given as a radius). Empty when the numbers look sane.
std::vector<std::string> orbit_unit_warnings(double mu, double radius);

}  // namespace newtop
