#pragma once
/// \file
/// The potential file of `newtop find-integrals --potential FILE.toml` (docs/cli.md): a general
/// polynomial V(γ) replacing the scenario's field,
///
///     [potential]
///     terms = [[coefficient, i, j, k], ...]   # V(γ) = Σ coefficient γ1^i γ2^j γ3^k

#include <string>

#include "newtop/analysis/find_integrals.hpp"

namespace newtop::io {

/// Largest exponent of one γ component in a term.
inline constexpr int kMaxPotentialExponent = 8;

/// Largest |coefficient|, and largest Σ|c| · kMaxPotentialExponent / min(A, B, C), the bound on
/// |γ × ∂V/∂γ| / min I over the search's points (|γ_i| ≤ 1). The search fits |V| ≤ Σ|c| and sums
/// squares of a few thousand such values, and its condition matrix holds rates of that size:
/// 1e100 leaves every square and sum of squares far from overflow (1.8e308).
inline constexpr double kMaxPotentialCoefficient = 1e100;

/// Parses a potential file for a search with `body`. Every coefficient a finite number (an integer
/// only if a double holds it exactly) of magnitude at most kMaxPotentialCoefficient, every exponent
/// an integer in 0..kMaxPotentialExponent, no two terms with the same exponents, no other key or
/// section. Throws InputError `SOURCE:LINE:COL: [potential] terms: …`, one line.
PolynomialPotential parse_potential(const std::string& text, const std::string& source,
                                    const Body& body);

/// Reads and parses a potential file (a regular file of at most 4 MiB).
PolynomialPotential load_potential(const std::string& path, const Body& body);

}  // namespace newtop::io
