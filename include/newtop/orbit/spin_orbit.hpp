#pragma once
/// \file
/// Spin–orbit resonances of Beletsky's equation (docs/orbit.md §9): the p:q resonance (the body
/// turns p times in inertial space while the orbit turns q times, on average) is a periodic
/// solution θ(ν + 2πN) = θ(ν) + Mπ with M/(2N) = (p − q)/q in lowest terms (the body is symmetric
/// under a half turn about z). Symmetric solutions (θ(−ν) = 2θ0 − θ(ν), θ0 ∈ {0, π/2}) are found by
/// bracketing θ(πN) − θ0 − Mπ/2 in θ′(0) and solving with TOMS 748, then Newton's method on the
/// same condition with the variational equation; the monodromy matrix over 2πN gives the Floquet
/// multipliers. Solutions without the symmetry are found by 2-D shooting (Newton's method on both
/// initial values; spin_orbit_shooting.cpp). The periapsis section samples (θ mod π, θ′) every
/// orbit, with a finite-time Lyapunov exponent per start.

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "newtop/orbit/libration.hpp"

namespace newtop {

/// A resonance p:q, reduced to its period N (orbits) and advance M (half turns of θ per period).
struct SpinOrbitResonance {
  int p = 1, q = 1;    ///< spin : orbit, as given (p ≥ 0, q ≥ 1)
  int periods = 1;     ///< N
  int half_turns = 0;  ///< M, θ(ν + 2πN) = θ(ν) + Mπ
};

/// p:q with p ≥ 0, 1 ≤ q ≤ 12 (InputError otherwise); N and M from (p − q)/q in lowest terms.
SpinOrbitResonance resonance(int p, int q);

/// Floquet verdict from the monodromy matrix's trace T (det = 1): elliptic |T| < 2 (`stable`,
/// linearly), hyperbolic |T| > 2 (`unstable`), `parabolic` within kParabolicTrace of ±2.
enum class FloquetStability { stable, unstable, parabolic };
inline constexpr double kParabolicTrace = 1e-9;
const char* to_string(FloquetStability s);

/// One periodic solution of the resonance.
struct PeriodicSolution {
  SpinOrbitResonance resonance;
  /// θ(0) at periapsis: ∈ {0, π/2} (the reversibility line it starts on) for the symmetric
  /// search; any value for the 2-D shooting (reduced to [−π/2, π/2)).
  double theta0 = 0.0;
  double dtheta0 = 0.0;               ///< θ′(0)
  Mat2 monodromy = Mat2::Identity();  ///< Φ(2πN, 0)
  std::complex<double> multipliers[2];
  FloquetStability stability = FloquetStability::stable;
  double residual = 0.0;  ///< |x(2πN) − x(0) − (Mπ, 0)|, the periodicity check over a full period
  double max_deviation = 0.0;  ///< max over ν ∈ [0, 2πN] of |θ(ν) − θ0 − Mν/(2N)|
  /// min over j = 0 … 2N − 1 of the distance of θ(πj) to the nearest multiple of π/2: zero (to the
  /// integration's accuracy) exactly when the solution is symmetric (spin_orbit_shooting.cpp).
  double symmetry_distance = 0.0;
};

/// The full period from (θ(0), θ′(0)) = (theta0, dtheta0): monodromy, multipliers, periodicity
/// residual, deviation and symmetry distance.
PeriodicSolution periodic_solution_at(const PitchProblem& p, const SpinOrbitResonance& r,
                                      double theta0, double dtheta0);

/// Search settings: θ′(0) is scanned over M/(2N) ± half_window in `samples` steps on each line.
struct ResonanceSearch {
  double half_window = 0.0;  ///< 0: max(0.5, 2√(3|k|))
  int samples = 400;
};

/// Every symmetric periodic solution of the resonance found in the scan window, on both lines.
std::vector<PeriodicSolution> periodic_solutions(const PitchProblem& p, const SpinOrbitResonance& r,
                                                 const ResonanceSearch& search = {});

/// 2-D shooting without the symmetry assumption (docs/orbit.md §9): Newton's method on
/// F(x0) = x(2πN; x0) − x0 − (Mπ, 0) over both initial values x0 = (θ(0), θ′(0)), with the
/// Jacobian Φ(2πN, 0) − I from the variational equation; steps longer than `max_step` are
/// shortened to it, then halved until |F| decreases (backtracking). Converged when max |F| ≤
/// tolerance; nullopt when it does not converge within max_iterations, no halving decreases |F|,
/// or Φ − I is singular (a multiplier 1).
struct ShootingSettings {
  int max_iterations = 40;
  double tolerance = 1e-11;
  double max_step = 0.3;
};
std::optional<PeriodicSolution> shoot_periodic(const PitchProblem& p, const SpinOrbitResonance& r,
                                               const Vec2& guess,
                                               const ShootingSettings& settings = {});

/// A solution is called symmetric when its symmetry_distance is below this (the shooting and
/// integration tolerances are 1e-11 and 1e-13; an asymmetric solution's distance is O(1)).
inline constexpr double kSymmetryTolerance = 1e-7;

/// Every periodic solution that 2-D shooting reaches from a grid of starts: θ(0) at `theta_samples`
/// points of [−π/2, π/2), θ′(0) at `rate_samples` points of M/(2N) ± half_window (0: as in
/// ResonanceSearch); duplicates (θ(0) mod π and θ′(0) within 1e-7) kept once.
struct ShootingGrid {
  int theta_samples = 12;
  int rate_samples = 12;
  double half_window = 0.0;
};
std::vector<PeriodicSolution> shoot_periodic_solutions(const PitchProblem& p,
                                                       const SpinOrbitResonance& r,
                                                       const ShootingGrid& grid = {});

/// Goldreich & Peale (1966) strength H(p, e) of the resonance p (spin/orbit ratio, a multiple of
/// 1/2): the Fourier coefficient (a/R)³ e^{2i(ν − pM)} averaged over the mean anomaly M, by the
/// trapezoidal rule (exponentially convergent for this periodic integrand).
double resonance_strength(double spin_ratio, double eccentricity);

/// The averaged (pendulum) half-width of the resonance in the spin rate θ̇/n, √(3k|H(p, e)|),
/// which is also its small-libration frequency in units of n (Goldreich & Peale 1966).
double averaged_half_width(const PitchProblem& p, double spin_ratio);

/// The resonance's half-width in θ̇/n measured on the map over its period 2πN: from the stable
/// periodic solution `centre`, θ′(0) is moved up and down (bisection, 30 steps) to the edge where
/// the start stops librating about it within `periods` periods (its phase relative to the centre,
/// taken mod π, accumulates more than π); the mean of the two edges, converted to θ̇/n at
/// periapsis. Meaningful where the separatrix's chaotic layer is thin (small k).
double measured_half_width(const PitchProblem& p, const PeriodicSolution& centre, int periods);

/// One start of the periapsis section and what became of it.
struct SectionOrbit {
  double theta0 = 0.0, dtheta0 = 0.0;  ///< at ν = 0 (periapsis)
  std::vector<Vec2> points;  ///< (θ mod π in [−π/2, π/2), θ′) at ν = 2πj, j = 1..iterates
  double lyapunov = 0.0;     ///< finite-time Lyapunov exponent per orbit, (1/J) ln |Φ(2πJ, 0) v|
  bool chaotic = false;      ///< lyapunov > chaos_threshold(J)
};

/// The exponent above which a start is called chaotic after J orbits: a regular orbit's tangent
/// vector grows at most linearly (shear), ln(c J)/J with ln c ≲ 5 on the problems of interest.
double chaos_threshold(int iterates);

/// Iterates the periapsis map `iterates` times from (θ0, θ′0) at ν = 0.
SectionOrbit periapsis_section(const PitchProblem& p, double theta0, double dtheta0, int iterates);

/// θ′ at periapsis for the inertial spin rate θ̇ = s n there: θ′ = s (1 − e²)^{3/2}/(1 + e)² − 1,
/// and its inverse.
double dtheta_from_spin(double eccentricity, double spin);
double spin_from_dtheta(double eccentricity, double dtheta);

}  // namespace newtop
