#pragma once
/// \file
/// The JSON and CSV of the libration report (orbit/libration_report.hpp), as `newtop libration`
/// writes them (docs/orbit.md §9).

#include <optional>
#include <ostream>
#include <string>

#include "newtop/io/json.hpp"
#include "newtop/orbit/libration_report.hpp"

namespace newtop::io {

/// scenario, eccentricity, k, iterates, chaos_threshold, resonances [{resonance "p:q",
/// spin_ratio, periods, half_turns, strength, averaged_half_width, solutions [{theta0, dtheta0,
/// spin0, multipliers [[re, im]], trace, stability, residual, max_deviation, symmetry_distance,
/// symmetric}][, asymmetric_solutions]}], starts [{start, theta0, dtheta0, spin0, lyapunov,
/// chaotic}], chaotic_starts[, csv].
Json to_json(const LibrationReport& r, const std::string& scenario,
             const std::optional<std::string>& csv = std::nullopt);

/// The periapsis section `start,orbit,theta,dtheta,spin,lyapunov,chaotic`, one row per point.
void write_csv(std::ostream& os, const LibrationReport& r);

}  // namespace newtop::io
