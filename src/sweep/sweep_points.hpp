#pragma once
// Internal: the checks of every point of a sweep, before any work (sweep_points.cpp), and the
// pieces of a point that the orbit scenarios share with the fixed point (sweep_orbit.cpp).

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "newtop/orbit/orbit_section.hpp"
#include "newtop/sweep/sweep.hpp"

namespace newtop::sweep {

/// Builds the scenario of every point and checks that each quantity applies to it (a stability
/// quantity needs a fixed point); fills s.input_files. Throws InputError naming the point.
void check_points(SweepFile& s);

/// The base scenario's text with the swept scenario keys of point `index` written in place (the
/// inertia ratios body.k_R, body.k_Y as the three moments of [body] inertia).
std::string set_keys(const SweepFile& s, std::size_t index);

/// "point 3 (orbit.eccentricity = 0.2, ...)".
std::string point_label(const SweepFile& s, std::size_t index);

/// Whether the sweep computes the quantity q.
bool wants(const SweepFile& s, const std::string& q);

/// An InputError of the point's scenario, rethrown naming the sweep file and the point (the
/// scenario's line and column dropped: the column may have moved where a value was rewritten).
[[noreturn]] void rethrow_for_point(const SweepFile& s, std::size_t index, const InputError& e);

/// Refuses a quantity, [level] or key that does not apply to the base scenario's model (one line
/// naming it and the model), before any point is built.
void check_model(const SweepFile& s);

/// The orbit scenarios (sweep_orbit.cpp): the columns of the quantities on an orbit, the checks
/// of one point (InputError without the point's label) and its evaluation.
std::vector<std::string> orbit_quantity_columns(const SweepFile& s);
void check_orbit_point(const SweepFile& s, const io::OrbitScenario& sc);
PointResult evaluate_orbit_point(const SweepFile& s, std::size_t index);

/// One run of an orbit point's scenario (final_state, drift): the outcome in the run's variable
/// (t, or ν on an ellipse), the time reached (on an ellipse, from the anomaly by Kepler's
/// equation) and the largest drift of the Jacobi integral (circular orbit) and of the Casimirs
/// γ·γ, n·n, γ·n (the orbit's drift observer, from the start and after every accepted step).
struct OrbitRun {
  OrbitOutcome outcome;
  double t = 0.0;
  OrbitSectionDrift drift;
};
/// evaluate_orbit_point's result of a sweep whose quantities are final_state and drift only.
PointResult orbit_run_result(const SweepFile& s, const io::OrbitScenario& sc, const OrbitRun& run);

/// The points of an orbit sweep of final_state and drift only (or of megno and lyapunov_max only:
/// orbit_chaos's tangent runs) whose runs share method taylor and
/// its tolerances, the kind of orbit, the run's start and end (t, or ν on an ellipse) and the
/// step limit, four or more, advanced together by the orbit's Taylor ensemble
/// (newtop/orbit/orbit_taylor_ensemble.hpp): out[slot] set for each (evaluate_orbit_point's result,
/// bit for bit), the others left empty; `runs` counts the groups (sweep_orbit_ensemble.cpp).
void evaluate_orbit_taylor_points(const SweepFile& s, std::span<const std::size_t> indices,
                                  std::vector<std::optional<PointResult>>& out, std::size_t* runs);

/// θ′(0) of the odd synchronous (1:1) periodic solution of Beletsky's equation (θ(0) = 0,
/// θ(π) = 0) at (e, k), followed in e from the equilibrium θ ≡ 0 of e = 0 (natural continuation,
/// Newton's method on θ(π) = 0); nullopt where that family has folded back before e
/// (sweep_synchronous.cpp).
std::optional<double> synchronous_odd_rate(double eccentricity, double k);

}  // namespace newtop::sweep
