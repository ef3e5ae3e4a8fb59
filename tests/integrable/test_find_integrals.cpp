// Numerical search for polynomial first integrals (docs/model.md §5): the expected number of
// independent integrals in the generic, Brun, Lagrange and uniform-gravity cases, the theorem on
// quadratic integrals for polynomial potentials, and Kovalevskaya's quartic integral, which the
// search was not built around.

#include <gtest/gtest.h>

#include <algorithm>

#include "newtop/analysis/find_integrals.hpp"

namespace newtop {
namespace test_find_integrals {
namespace {

// A vector in the span of the found integrals lies there to rounding (~1e-12 after the SVD); a
// non-integral is O(1) away.
constexpr double kInSpan = 1e-8;
constexpr double kOutOfSpan = 1e-2;

int named_count(const IntegralSearch& s) {
  return static_cast<int>(std::count_if(s.integrals.begin(), s.integrals.end(),
                                        [](const FoundIntegral& i) { return i.name.has_value(); }));
}
bool has(const IntegralSearch& s, const std::string& name) {
  return std::any_of(s.integrals.begin(), s.integrals.end(),
                     [&](const FoundIntegral& i) { return i.name == name; });
}

TEST(FindIntegrals, GenericBodyHasOnlyTheClassicalThree) {
  const QuadraticModel m{Body::from_principal({1.0, 1.7, 2.3}, 1.0, {0.2, -0.1, 0.3}),
                         QuadraticField::coulomb(1.3, 0.8)};
  const IntegralSearch s = find_integrals(m);
  EXPECT_EQ(s.integrals.size(), 3u);
  EXPECT_EQ(named_count(s), 3);
  EXPECT_TRUE(has(s, "energy") && has(s, "area") && has(s, "geometric"));
  EXPECT_GT(s.gap, 1e3);  // a clear rank decision
}

TEST(FindIntegrals, BrunCaseHasAFourthQuadraticIntegral) {
  const QuadraticModel m{Body::from_principal({1.0, 1.7, 2.3}, 1.0, Vec3::Zero()),
                         QuadraticField::coulomb(0.0, 0.8)};
  const IntegralSearch s = find_integrals(m);
  EXPECT_EQ(s.integrals.size(), 4u);
  EXPECT_TRUE(has(s, "brun"));
}

TEST(FindIntegrals, LagrangeCaseFindsRAndItsSquare) {
  const QuadraticModel m{Body::from_principal({2.0, 2.0, 1.0}, 1.0, {0.0, 0.0, 0.5}),
                         QuadraticField::coulomb(2.0, 0.7)};
  const IntegralSearch s = find_integrals(m);
  EXPECT_EQ(s.integrals.size(), 5u);
  EXPECT_TRUE(has(s, "lagrange") && has(s, "lagrange*lagrange"));
  EXPECT_EQ(named_count(s), 5);
}

TEST(FindIntegrals, UniformGravityHeavyBodyHasNothingNew) {
  const QuadraticModel m{Body::from_principal({1.0, 1.7, 2.3}, 1.0, {0.2, 0.4, -0.3}),
                         QuadraticField::uniform(9.81)};
  EXPECT_EQ(find_integrals(m).integrals.size(), 3u);
  // At degree 3 only products appear, none of them cubic: still the same three.
  EXPECT_EQ(find_integrals(m, {.degree = 3}).integrals.size(), 3u);
}

TEST(FindIntegrals, KovalevskayaQuarticIntegralAppearsAtDegreeFour) {
  // λ = 0, A = B = 2C, centre of mass in the equatorial plane (x0 ≠ 0).
  const double C = 1.0, Mg_x0 = 1.5;
  const QuadraticModel m{Body::from_principal({2 * C, 2 * C, C}, 1.0, {Mg_x0, 0.0, 0.0}),
                         QuadraticField::uniform(1.0)};
  const IntegralSearch s = find_integrals(m, {.degree = 4});
  // Products of energy, area and geometric up to degree 4 give 9; one more is new.
  EXPECT_EQ(named_count(s), 9);
  ASSERT_EQ(s.integrals.size(), 10u);
  EXPECT_FALSE(s.integrals.back().name.has_value());
  // K = (p² − q² − ν γ1)² + (2pq − ν γ2)², ν = Mg x0 / C, lies in the span found.
  const double nu = Mg_x0 / C;
  const auto K = polynomial_coefficients(s.monomials, [&](const Vec3& w, const Vec3& g) {
    return std::pow(w.x() * w.x() - w.y() * w.y() - nu * g.x(), 2) +
           std::pow(2 * w.x() * w.y() - nu * g.y(), 2);
  });
  ASSERT_TRUE(K.has_value());
  EXPECT_LT(distance_from_integrals(s, *K), kInSpan);
  // A wrong sign of ν is not an integral: the check can fail.
  const auto K_wrong = polynomial_coefficients(s.monomials, [&](const Vec3& w, const Vec3& g) {
    return std::pow(w.x() * w.x() - w.y() * w.y() + nu * g.x(), 2) +
           std::pow(2 * w.x() * w.y() - nu * g.y(), 2);
  });
  EXPECT_GT(distance_from_integrals(s, *K_wrong), kOutOfSpan);
}

TEST(FindIntegrals, QuadraticIntegralOnlyForTheNewtonianQuadraticPotential) {
  // Theorem of docs/model.md §5: V = ½ Σ λ_i γ_i² admits A²p² + B²q² + C²r² + F(γ) only for λ_i = λ
  // I_i.
  const Vec3 I(1.0, 1.7, 2.3);
  const double lambda = 0.9;
  auto quadratic = [&](const Vec3& L) {
    PolynomialPotential v;
    for (int i = 0; i < 3; ++i) {
      std::array<int, 3> e{};
      e[i] = 2;
      v.terms.push_back({0.5 * L[i], e});
    }
    return BasicModel<PolynomialPotential>{Body::from_principal(I, 1.0, Vec3::Zero()), v};
  };
  const auto newtonian = find_integrals(quadratic(lambda * I));
  EXPECT_EQ(newtonian.integrals.size(), 4u);
  const auto brun_coeffs =
      polynomial_coefficients(newtonian.monomials, [&](const Vec3& w, const Vec3& g) {
        return I.cwiseProduct(w).squaredNorm() - lambda * I.prod() * g.dot(g.cwiseQuotient(I));
      });
  EXPECT_LT(distance_from_integrals(newtonian, *brun_coeffs), kInSpan);
  EXPECT_EQ(find_integrals(quadratic(Vec3(0.9, 2.0, 1.1))).integrals.size(), 3u);
  EXPECT_EQ(find_integrals(quadratic(lambda * I + Vec3(0.0, 0.05, 0.0))).integrals.size(), 3u);
}

TEST(FindIntegrals, RejectsBadDegree) {
  const QuadraticModel m{Body::from_principal({1.0, 1.7, 2.3}, 1.0, Vec3::Zero()),
                         QuadraticField{}};
  EXPECT_THROW(find_integrals(m, {.degree = 0}), InputError);
  EXPECT_THROW(find_integrals(m, {.degree = 9}), InputError);
}

}  // namespace
}  // namespace test_find_integrals
}  // namespace newtop
