#pragma once
/// \file
/// The JSON of `newtop analytic` (docs/cli.md): the closed form's own keys for each integrable
/// case, its dense curve and the comparison's samples.

#include <vector>

#include "newtop/analysis/analytic.hpp"
#include "newtop/analysis/analytic_comparison.hpp"
#include "newtop/io/json.hpp"

namespace newtop::io {

/// {"omega", "gamma"} of a state.
Json state_json(const Body& b, const State& s);

/// The case's keys: period, nutation_period, turning_points, and Euler–Poinsot's modulus; the
/// pendulum's kind and closed_form; the Lagrange top's quartic, γ3 and Euler angles at the times;
/// Brun's curve, frequencies, periods and u at the times; the Brun–Prym divisor, torus and checks.
void add_case_details(Json& j, const AnalyticSolution& sol, const std::vector<double>& times);

/// ξ² = N(u) + 2√λ f v, with the coefficients of D = N² − 4λf² P and its roots; null when the
/// level has no such curve (equal moments).
Json brun_spectral_json(const QuadraticModel& model, const State& x0);

/// The closed form on n equally spaced times over [times.front(), times.back()] (analytic_curve):
/// {"t", "omega", "gamma"[, "euler_angles"]}.
Json curve_json(const Body& b, const AnalyticSolution& sol, const std::vector<double>& times,
                int n);

/// [{"t", "analytic": {omega, gamma}, "numeric": {omega, gamma} or null}] of a comparison.
Json samples_json(const Body& b, const AnalyticComparison& c);

}  // namespace newtop::io
