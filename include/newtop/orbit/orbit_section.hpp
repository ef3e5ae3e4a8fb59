#pragma once
/// \file
/// Poincaré sections of the orbit model (docs/section.md "Orbit scenarios", docs/orbit.md §10):
/// the crossings of a trajectory of (m, γ, n) with a surface g(ω, m, γ, n) = 0, located on the
/// orbit method's own solution by the observer of the body's sections (phase/section_run.hpp),
/// generic in the state type. The run itself continues from the unmodified state. On a circular
/// orbit the independent variable is the time; on an elliptic one the true anomaly ν.

#include <cstdint>
#include <functional>
#include <vector>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "newtop/phase/section.hpp"

namespace newtop {

using OrbitCrossing = phase::BasicCrossing<OrbitState>;

/// Largest |I(x) − I(x0)| over a run of the Jacobi integral (circular orbits only) and of the
/// three Casimirs γ·γ, n·n, γ·n.
struct OrbitSectionDrift {
  bool started = false;
  bool has_jacobi = false;
  double jacobi0 = 0;
  OrbitCasimirs casimirs0{1.0, 1.0, 0.0};
  double jacobi = 0, gamma_gamma = 0, normal_normal = 0, gamma_normal = 0;

  /// `jacobi`: the Jacobi integral at x, or nullptr (elliptic orbit).
  void observe(const OrbitState& x, const double* jacobi);
  /// Takes the larger drift of each from another run (each against its own start).
  void merge(const OrbitSectionDrift& other);
};

/// The crossings of one trajectory on a circular orbit, from (t0, x0) to t1, with `method` (a
/// splitting composition or rkf78, validate_orbit_method), appended to `out`; `drift` follows
/// the Jacobi integral and the Casimirs at every accepted step and crossing. `g` is built with
/// the orbit normal allowed. `on_step(t)` is called at every accepted step (interrupts).
phase::SectionRun orbit_section(const MethodSettings& method, const CircularOrbitModel& model,
                                const phase::SurfaceFunction& g,
                                const phase::SectionSettings& settings, int orbit,
                                const OrbitState& x0, double t0, double t1, std::int64_t max_steps,
                                std::vector<OrbitCrossing>& out, OrbitSectionDrift& drift,
                                const std::function<void(double)>& on_step = {});

/// The same on an elliptic orbit, from the true anomaly ν0 to ν1 (the crossings' t is ν; the
/// drift has the Casimirs only: H_ν is not conserved).
phase::SectionRun orbit_section(const MethodSettings& method, const EllipticOrbitModel& model,
                                const phase::SurfaceFunction& g,
                                const phase::SectionSettings& settings, int orbit,
                                const OrbitState& x0, double nu0, double nu1,
                                std::int64_t max_steps, std::vector<OrbitCrossing>& out,
                                OrbitSectionDrift& drift,
                                const std::function<void(double)>& on_step = {});

/// The section of one start on an orbit.
struct OrbitSectionResult {
  phase::SectionStatus status = phase::SectionStatus::no_crossing;
  Status outcome = Status::finished;  ///< how the integration ended
  double reached = 0.0;               ///< the run's variable reached (t, or ν on an ellipse)
  std::int64_t steps = 0, rejected = 0;
  std::vector<OrbitCrossing> crossings;  ///< t is the run's variable (ν on an ellipse)
  OrbitSectionDrift drift;
  double max_residual = 0.0;  ///< max |g| at the crossings
  double max_relative = 0.0;  ///< max |g| / scale of g's terms
};

/// The crossings of the trajectory from x0 with the request's surface (which may name the orbit
/// normal), from request.t0 to request.t_end (required on an orbit; times, carried to true
/// anomalies by Kepler's equation on an ellipse, where x0 is the state at ν0); the method is a
/// splitting composition or an embedded pair (validate_orbit_method). InputError before any work
/// for a missing or impossible span or a method that does not run on an orbit.
OrbitSectionResult orbit_section(const CircularOrbitModel& model, const OrbitState& x0,
                                 const phase::SectionRequest& request);
OrbitSectionResult orbit_section(const EllipticOrbitModel& model, const OrbitState& x0,
                                 const phase::SectionRequest& request);

/// Coordinates of a crossing in the orbital frame (docs/orbit.md §10): the attitude of the
/// principal axes relative to the orbital frame (e_r, e_t, e_n) as the 3-2-1 angles of the
/// scenario files, R = R_n(ψ) R_t(θ) R_r(φ) (yaw ψ about e_n, pitch θ, roll φ), and the angular
/// velocity relative to that frame, ω − ν̇ n, in body axes. For the planar pitch motion of §4
/// (n = e_z) ψ is Beletsky's angle θ and omega_relative[2] its rate.
struct OrbitFrameCoords {
  Vec3 euler_321 = Vec3::Zero();  ///< (ψ, θ, φ) [rad]
  Vec3 omega_relative = Vec3::Zero();
};

/// `orbit_rate`: ν̇ at the crossing (ω0 on a circular orbit).
OrbitFrameCoords orbit_frame_coords(const Body& body, const OrbitState& x, double orbit_rate);

}  // namespace newtop
