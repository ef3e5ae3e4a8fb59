#pragma once
/// \file
/// The checks of a state that the library makes where a run or an analysis starts, with the words
/// of the scenario reader: C++, Python and the command line refuse the same input alike.

#include "newtop/model/basic_model.hpp"

namespace newtop {

/// γ must be a unit vector to this accuracy: a file that writes 15 significant digits passes, a
/// hand-typed approximation such as [0.6, 0.8, 0.01] does not.
inline constexpr double kUnitGammaTolerance = 1e-12;

/// |γ| without overflow or underflow (the norm of γ scaled by its largest component).
double gamma_norm(const Vec3& gamma);

/// Checks γ: finite and of unit length to kUnitGammaTolerance. Throws InputError, "gamma: expected
/// finite numbers, found [..]", "gamma: expected a unit vector, found [0, 0, 0]" or "gamma:
/// expected a unit vector (|gamma| = 1 to 1e-12), found |gamma| = X" (the scenario reader's
/// message).
void check_unit_gamma(const Vec3& gamma);

/// γ rescaled to unit length (as [initial] normalize = true); throws InputError for a zero or
/// non-finite γ.
Vec3 normalized_gamma(const Vec3& gamma);

/// Checks a state where a run or an analysis starts: m finite ("m: expected finite numbers, found
/// [..]") and γ as check_unit_gamma. Every compiled entry point (run_method, phase::chaos,
/// section_orbit, the analyses on a Model) calls it, so the library refuses what the command line
/// refuses, with the same words.
void validate(const State& x);

}  // namespace newtop
