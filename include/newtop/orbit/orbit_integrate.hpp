#pragma once
/// \file
/// Integrators of the orbit model (docs/orbit.md §5): a Lie–Poisson splitting whose sub-flows are
/// exact — rotations of (m, γ, n) about the body axes, the gravity-gradient kick and the orbital
/// rotation of γ about n — composed to order 2, 4, 6 or 8 by the project's composition tables;
/// and the embedded Runge–Kutta pairs (Fehlberg 7(8), Dormand–Prince 5(4)) with error control and
/// dense output. Every run goes through the engine's one driver (integrate/driver.hpp) and its
/// sampled output (integrate/sampled.hpp): the orbit brings only its sub-flows and its right-hand
/// side. On a circular orbit the independent variable is the time t; on an elliptic orbit it is
/// the true anomaly ν.

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/integrate/outcome.hpp"
#include "newtop/integrate/output_times.hpp"
#include "newtop/orbit/orbit_model.hpp"

namespace newtop {

/// The engine's checks of an orbit state: finite (m, γ, n), else InputError naming the vector.
void check_state(const OrbitState& x);
inline bool is_finite(const OrbitState& x) {
  return x.m.allFinite() && x.gamma.allFinite() && x.normal.allFinite();
}

/// Exact flow of ½(m_a − k_a)²/I_a over a time τ: m, γ and n turn about the body axis e_a by
/// the angle θ = τ (m_a − k_a)/I_a, each as x ← x rotated by −θ about e_a (ẋ = x × θ̇ e_a).
void rotate_about_body_axis(const Body& body, OrbitState& x, int axis, double tau);

/// Exact flow of ½λ γ·Iγ with ∫λ dt = impulse: m += impulse · γ × Iγ (γ and n fixed).
void gravity_gradient_kick(const Body& body, OrbitState& x, double impulse);

/// Exact flow of −ω0 n·m over an orbital angle φ = ω0 τ (or Δν): γ turns about n by +φ
/// (Rodrigues' formula); m and n fixed.
void orbital_rotation(OrbitState& x, double angle);

/// One stage of the splitting program: the "free" part A (the body-axis rotations, Strang-split
/// over the axes, and the orbital rotation, which commutes with them) or the kick B, for the
/// fraction `fraction` of the step.
struct OrbitStage {
  bool kick;
  double fraction;
};

/// The splitting integrator of any order given by a composition table. The symmetric base is
/// A(h/2) B(h) A(h/2) (kick inside) or B(h/2) A(h) B(h/2) (kick outside, adjacent kicks of
/// consecutive stages merged); within A the free body is T_i(τ/2) T_j(τ/2) T_k(τ) T_j(τ/2)
/// T_i(τ/2) with i the least-moment axis and k the largest, followed by the orbital rotation.
/// Each sub-flow is a Poisson map preserving γ·γ, n·n and γ·n, so any composition keeps the
/// Casimirs to round-off.
///
/// Elliptic orbit (independent variable ν): A advances ν exactly — the body-axis rotations use
/// the elapsed time τ = t(ν + Δν) − t(ν) (Kepler) and the orbital rotation the angle Δν — and B
/// kicks with σλ evaluated at the current ν; the base remains symmetric, so the compositions keep
/// their order.
class OrbitSplittingStepper {
 public:
  /// Kick inside for the second-order base, outside (kicks merged) for the compositions.
  explicit OrbitSplittingStepper(const CompositionTable& table);
  OrbitSplittingStepper(const CompositionTable& table, bool kick_outside);

  int order() const { return order_; }
  const std::vector<OrbitStage>& program() const { return program_; }

  /// Circular orbit: advances x by the time h.
  void step(const CircularOrbitModel& model, OrbitState& x, double h) const;
  /// Elliptic orbit (non-autonomous in ν: the driver passes the anomaly at the start of the
  /// step): advances x from the true anomaly nu by h (in ν).
  void step(const EllipticOrbitModel& model, OrbitState& x, double nu, double h) const;

 private:
  int order_;
  std::vector<OrbitStage> program_;
};

/// How a run ended, where, after how many steps (the independent variable is t on a circular
/// orbit, ν on an elliptic one).
struct OrbitOutcome {
  Status status = Status::finished;
  double t = 0.0;  ///< independent variable reached (t or ν)
  OrbitState state;
  std::int64_t steps = 0;
  std::int64_t rejected = 0;
  double last_step = 0.0;  ///< size of the last accepted step
};

/// The driver's outcome on the orbit model.
template <>
struct OutcomeFor<OrbitState> {
  using type = OrbitOutcome;
};

/// Called at the start and after every accepted step with (t or ν, state).
using OrbitObserver = std::function<void(double, const OrbitState&)>;
/// Called at each output time, in order, with (k, t_k or ν_k, state there).
using OrbitSample = std::function<void(std::int64_t, double, const OrbitState&)>;

/// Fixed-step run from t0 to t1 (ν0 to ν1 on an elliptic orbit) in n = ceil(|t1 − t0|/step) equal
/// steps, landing exactly on t1: the engine's driver with this stepper. Throws InputError for a
/// step that is not finite and > 0 or non-finite ends.
OrbitOutcome integrate(const OrbitSplittingStepper& stepper, const CircularOrbitModel& model,
                       OrbitState x, double t0, double t1, double step,
                       const OrbitObserver& observer = {});
OrbitOutcome integrate(const OrbitSplittingStepper& stepper, const EllipticOrbitModel& model,
                       OrbitState x, double nu0, double nu1, double step,
                       const OrbitObserver& observer = {});

/// Error control of the adaptive reference: odeint's err_i / (abs_tol + rel_tol (|y_i| + h |y'_i|))
/// ≤ 1 in the max norm.
struct OrbitAdaptiveOptions {
  double abs_tol = 1e-12;
  double rel_tol = 1e-12;
  double initial_step = 0.0;  ///< first trial step (0: |t1 − t0| / 1000)
  /// A step below min_step_factor · max(|t|, |t1 − t0|) is an underflow.
  double min_step_factor = 1e-13;
  std::int64_t max_steps = 100'000'000;  ///< accepted + rejected trials
};

/// Fehlberg 7(8) (the engine's embedded pair on the orbit state) from t0 to t1 (ν0 to ν1 on an
/// elliptic orbit) with the engine's adaptive driver, landing exactly on t1. It does not keep the
/// Casimirs: they drift at the tolerance.
OrbitOutcome integrate_adaptive(const CircularOrbitModel& model, OrbitState x, double t0, double t1,
                                const OrbitAdaptiveOptions& options,
                                const OrbitObserver& observer = {});
OrbitOutcome integrate_adaptive(const EllipticOrbitModel& model, OrbitState x, double nu0,
                                double nu1, const OrbitAdaptiveOptions& options,
                                const OrbitObserver& observer = {});

/// One step of Fehlberg 7(8)'s propagated formula from (t, x) by h (from ν by h on an elliptic
/// orbit) without error control: the formula every accepted step of integrate_adaptive applies
/// (the right-hand side evaluated afresh at x). Event location lands on the solution with it.
OrbitState rkf78_step(const CircularOrbitModel& model, const OrbitState& x, double t, double h);
OrbitState rkf78_step(const EllipticOrbitModel& model, const OrbitState& x, double nu, double h);
/// The same for any adaptive method of the orbit ("rkf78", "dopri5", "dop853", "taylor"): its
/// propagated formula (Taylor's: the series through x, of the order of the method's tolerances).
OrbitState adaptive_formula_step(const MethodSettings& method, const CircularOrbitModel& model,
                                 const OrbitState& x, double t, double h);
OrbitState adaptive_formula_step(const MethodSettings& method, const EllipticOrbitModel& model,
                                 const OrbitState& x, double nu, double h);

/// The adaptive method on an orbit (the default there when only a tolerance is given).
inline constexpr std::string_view kOrbitAdaptiveMethod = "rkf78";

/// Whether a method name is one of the orbit's adaptive methods ("rkf78", "dopri5", "dop853").
bool is_orbit_adaptive_method(std::string_view name);

/// Checks that a method runs on the orbit model: a splitting composition of composition_tables()
/// (with settings.step > 0), "rkf78", "dopri5" or "dop853" (with tolerances > 0); throws InputError
/// naming `method` (listing the names that do) or the step or tolerance otherwise.
void validate_orbit_method(const MethodSettings& settings);

/// Runs a method by name on a circular orbit from t0 to t1 (OrbitSplittingStepper with the named
/// table, or integrate_adaptive with the tolerances; max_steps bounds the adaptive run).
OrbitOutcome run_orbit_method(const MethodSettings& settings, const CircularOrbitModel& model,
                              const OrbitState& x, double t0, double t1, std::int64_t max_steps,
                              const OrbitObserver& observer = {});
/// The same on an elliptic orbit, from the true anomaly ν0 to ν1 (the step is in ν).
OrbitOutcome run_orbit_method(const MethodSettings& settings, const EllipticOrbitModel& model,
                              const OrbitState& x, double nu0, double nu1, std::int64_t max_steps,
                              const OrbitObserver& observer = {});

/// Runs as run_orbit_method and reports the state at every output time (in the run's variable: t,
/// or ν on an ellipse) to sample: the engine's integrate_sampled (the adaptive methods' continuous
/// extension; fixed-step methods land on each output time).
OrbitOutcome run_orbit_method_sampled(const MethodSettings& settings,
                                      const CircularOrbitModel& model, const OrbitState& x,
                                      double t0, double t1, const OutputTimes& times,
                                      std::int64_t max_steps, const OrbitSample& sample,
                                      const OrbitObserver& observer = {});
OrbitOutcome run_orbit_method_sampled(const MethodSettings& settings,
                                      const EllipticOrbitModel& model, const OrbitState& x,
                                      double nu0, double nu1, const OutputTimes& times,
                                      std::int64_t max_steps, const OrbitSample& sample,
                                      const OrbitObserver& observer = {});

}  // namespace newtop
