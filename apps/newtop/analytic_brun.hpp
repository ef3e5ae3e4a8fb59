#pragma once
// newtop analytic on Brun's case: the JSON of the level f = 0 solution, of the spectral curve on
// any level, and of the Prym divisor with its Abel-Prym sums along the numerical motion.

#include <vector>

#include "newtop/analysis/brun_case.hpp"
#include "newtop/io/json.hpp"

namespace newtop::app {

/// Brun's case on f = 0: the genus-2 curve w² = R(u), the ranges of u1, u2 and the torus
/// frequencies, and u1, u2 at the sample times.
void add_brun_details(io::Json& j, const BrunCase& b, const std::vector<double>& times);

/// The spectral curve of the level, v² = P(u), ξ² = N(u) + 2√λ f v (null without one).
io::Json brun_spectral_json(const QuadraticModel& model, const State& x0);

/// The Prym divisor of the start (brun_prym.hpp), the round trip state → divisor → state, the
/// rates of the Abel-Prym sums at the start, and the sums along the numerical motion at the sample
/// times against the linear law (−2i t/κ, 0); null without a level (equal moments).
io::Json brun_prym_json(const QuadraticModel& model, const State& x0,
                        const std::vector<double>& times);

/// The human summary of brun_prym_json.
void print_brun_prym(const io::Json& prym);

}  // namespace newtop::app
