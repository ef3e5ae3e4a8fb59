#pragma once
/// \file
/// Numerical search for first integrals polynomial in (ω, γ) (docs/model.md §5): an ansatz
/// I = Σ c_j μ_j(p, q, r, γ1, γ2, γ3) over all monomials of degree 1..D, the condition
/// dI/dt = Σ c_j ∇μ_j · ẋ = 0 imposed at many random phase points, and the null space of that
/// linear system found by SVD. Known integrals (energy, area, geometric, Brun, Lagrange and their
/// products) are recognised by fitting them in the same basis and testing membership in the null
/// space; what remains is reported by its coefficients.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "newtop/model/basic_model.hpp"

namespace newtop {

/// One term c γ1^i γ2^j γ3^k of a polynomial potential.
struct PotentialTerm {
  double coefficient = 0.0;
  std::array<int, 3> power{};
};

/// A general polynomial potential V(γ) = Σ c γ1^i γ2^j γ3^k (a Field), for reproducing the theorem
/// on quadratic integrals of docs/model.md §5.
struct PolynomialPotential {
  std::vector<PotentialTerm> terms;
};

double potential(const Body& body, const PolynomialPotential& v, const Vec3& gamma);
Vec3 grad_gamma(const Body& body, const PolynomialPotential& v, const Vec3& gamma);
/// Highest total degree of the terms (0 for no terms).
int degree(const PolynomialPotential& v);

/// Exponents of p, q, r, γ1, γ2, γ3.
using Monomial = std::array<int, 6>;
/// "p^2*gamma3", "q*r", …
std::string to_string(const Monomial& m);

struct FoundIntegral {
  std::optional<std::string> name;   ///< recognised integral (e.g. "energy", "area*geometric")
  std::vector<double> coefficients;  ///< over IntegralSearch::monomials
};

/// The largest condition matrix a search builds, points × monomials entries (2^24 doubles, 128 MiB;
/// its SVD needs about as much again): at degree 6 (923 monomials) at most 18,176 points, at
/// degree 2 (27 monomials) 621,378 — far more than the rank decision needs (3 × the monomials).
inline constexpr std::int64_t kMaxConditionEntries = std::int64_t{1} << 24;

struct SearchOptions {
  int degree = 2;  ///< highest total degree D ≥ 1
  /// Random phase points (0: 3 × the number of monomials); at most kMaxConditionEntries / the
  /// number of monomials, else InputError.
  int points = 0;
  std::uint64_t seed = 20240601;  ///< the points are reproducible for a given seed
  /// Singular values below threshold × the largest count as zero. The columns are scaled to unit
  /// norm, so true null directions give ~1e-15 and genuine ones stay above ~1e-6 in the cases
  /// tested; 1e-10 sits in the gap (the gap itself is reported).
  double threshold = 1e-10;
};

struct IntegralSearch {
  int degree = 0;
  std::vector<Monomial> monomials;
  std::vector<double> singular_values;  ///< descending, relative to the largest
  int rank = 0;                         ///< numerical rank of the condition matrix
  double gap = 0.0;  ///< σ_rank / σ_(rank+1): the separation at the rank decision (∞ if none)
  std::vector<FoundIntegral> integrals;  ///< a basis of the null space: named first
};

/// Search for the quadratic-field model (recognises energy, area, geometric, brun, lagrange and
/// products of them). Throws InputError for a degree outside 1..6.
IntegralSearch find_integrals(const QuadraticModel& model, const SearchOptions& options = {});
/// Search for a polynomial potential (recognises energy, area, geometric, lagrange and products).
IntegralSearch find_integrals(const BasicModel<PolynomialPotential>& model,
                              const SearchOptions& options = {});

/// The coefficients, over `monomials`, of a function of the state that is a polynomial of degree
/// ≤ D in (ω, γ) up to a constant; std::nullopt when it is not (least-squares residual too large).
/// Used to test whether a formula (e.g. Kovalevskaya's integral) lies in the found null space.
std::optional<std::vector<double>> polynomial_coefficients(
    const std::vector<Monomial>& monomials,
    const std::function<double(const Vec3& omega, const Vec3& gamma)>& f);

/// Relative distance ‖c − Pc‖/‖c‖ of a coefficient vector from the span of the found integrals
/// (P the orthogonal projector on it): ~ε for an integral, O(1) for a non-integral.
double distance_from_integrals(const IntegralSearch& s, const std::vector<double>& coefficients);

}  // namespace newtop
