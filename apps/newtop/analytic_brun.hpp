#pragma once
// newtop analytic on Brun's case: the JSON of the level f = 0 solution, of the spectral curve on
// any level, and of the Prym divisor and torus of the solution on f != 0.

#include <vector>

#include "newtop/analysis/brun_case.hpp"
#include "newtop/analysis/brun_prym_inversion.hpp"
#include "newtop/io/json.hpp"

namespace newtop::app {

/// Brun's case on f = 0: the genus-2 curve w² = R(u), the ranges of u1, u2 and the torus
/// frequencies, and u1, u2 at the sample times.
void add_brun_details(io::Json& j, const BrunCase& b, const std::vector<double>& times);

/// The spectral curve of the level, v² = P(u), ξ² = N(u) + 2√λ f v (null without one).
io::Json brun_spectral_json(const QuadraticModel& model, const State& x0);

/// Brun's case on f ≠ 0 (brun_prym_inversion.hpp): `"prym"` with the divisor of the start, the
/// round trip state → divisor → state, the rates of the Abel-Prym sums at the start against the
/// law (−2i/κ, 0), the torus lattice and frequencies and the table of the inversion; the
/// frequencies also at the top level, as on f = 0.
void add_brun_prym_details(io::Json& j, const BrunPrymSolution& s);

/// The human summary of the "prym" of add_brun_prym_details.
void print_brun_prym(const io::Json& prym);

}  // namespace newtop::app
