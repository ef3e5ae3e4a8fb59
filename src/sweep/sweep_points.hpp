#pragma once
// Internal: the checks of every point of a sweep, before any work (sweep_points.cpp), and the
// pieces of a point that the orbit scenarios share with the fixed point (sweep_orbit.cpp).

#include <optional>
#include <string>
#include <vector>

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

/// θ′(0) of the odd synchronous (1:1) periodic solution of Beletsky's equation (θ(0) = 0,
/// θ(π) = 0) at (e, k), followed in e from the equilibrium θ ≡ 0 of e = 0 (natural continuation,
/// Newton's method on θ(π) = 0); nullopt where that family has folded back before e
/// (sweep_synchronous.cpp).
std::optional<double> synchronous_odd_rate(double eccentricity, double k);

}  // namespace newtop::sweep
