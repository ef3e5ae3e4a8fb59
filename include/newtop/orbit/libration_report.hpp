#pragma once
/// \file
/// The libration report (docs/orbit.md §9): the planar pitch motion of a body on a Kepler orbit
/// (Beletsky's equation) — the p:q spin–orbit resonances as periodic solutions with their Floquet
/// multipliers, and the periapsis section with a finite-time Lyapunov exponent per start — as one
/// function of the body, the orbit and the initial state, with a plain result.

#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "newtop/orbit/libration.hpp"
#include "newtop/orbit/orbit_model.hpp"
#include "newtop/orbit/spin_orbit.hpp"

namespace newtop {

/// The section starts at periapsis (θ = 0) with spin rates θ̇/n from lo to hi (n of them, ends
/// included; one start at lo when n = 1).
struct SpinStarts {
  double lo = 0, hi = 0;
  int n = 1;
};

/// What the report computes.
struct LibrationRequest {
  /// The resonances p:q (spin:orbit); by default 1:2, 1:1, 3:2, 2:1, 5:2.
  std::vector<SpinOrbitResonance> resonances{resonance(1, 2), resonance(1, 1), resonance(3, 2),
                                             resonance(2, 1), resonance(5, 2)};
  /// Section starts besides the initial state's (carried to the first periapsis).
  std::optional<SpinStarts> spin;
  int iterates = 200;       ///< orbits per start, 1 to 100000
  bool asymmetric = false;  ///< also the 2-D shooting without the symmetry assumption
  /// Called before each resonance and each start (throws to stop the report).
  std::function<void(double)> on_step;
};

/// One resonance: its symmetric periodic solutions (and with `asymmetric` the others).
struct LibrationResonance {
  SpinOrbitResonance resonance;
  double spin_ratio = 0;           ///< p/q
  double strength = 0;             ///< H(p/q, e), resonance_strength
  double averaged_half_width = 0;  ///< in θ̇/n
  std::vector<PeriodicSolution> solutions;
  std::optional<std::vector<PeriodicSolution>> asymmetric_solutions;
};

struct LibrationReport {
  double eccentricity = 0;
  double k = 0;  ///< (B − A)/C about the pitch axis
  int iterates = 0;
  double chaos_threshold = 0;
  std::vector<LibrationResonance> resonances;
  std::vector<SectionOrbit> starts;  ///< the initial state's first, then the spin starts
  int chaotic_starts = 0;
};

/// The pitch orbit of a Kepler orbit: the ellipse itself, or a circular one as e = 0 with its true
/// anomaly counted from the start. InputError for a forced circular orbit (λ ≠ 3ω0²), which has
/// no Beletsky equation; `context` prefixes the message (a file name).
EllipticOrbit pitch_orbit(const std::variant<CircularOrbit, EllipticOrbit>& orbit,
                          const std::string& context = "");

/// The report of the body on the orbit from `initial` (planar to 1e-9: the pitch axis is the
/// principal axis along the orbit normal). InputError before any work for bad input.
LibrationReport libration_report(const Body& body,
                                 const std::variant<CircularOrbit, EllipticOrbit>& orbit,
                                 const OrbitState& initial, const LibrationRequest& request,
                                 const std::string& context = "");

}  // namespace newtop
