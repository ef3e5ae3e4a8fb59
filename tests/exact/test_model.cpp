// Model, whatever its field: the body is the mass model's, the free functions dispatch to the
// field's own V, ∂V/∂γ, ∂²V/∂γ², L and ∂L/∂γ (checked against 50/100-digit references and finite
// differences), and the integrals are those of the field itself.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "bodies.hpp"
#include "newtop/exact/model_fields.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/model/model.hpp"

namespace newtop {
namespace test_model {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const Vec3 kGamma = Vec3(0.3, -0.5, 0.8).normalized();

// At R = 4r the closed forms lose at most 100 ε (R/r)² ≈ 3.6e-13 of V and of the Hessian
// (tests/exact/test_hessian.cpp), the series and the sums a few ε: 1e-12 relative bounds both.
constexpr double kValueTol = 1e-12;

TEST(Model, ExactFieldAccessorGivesTheFieldOfItsKindOnly) {
  const std::vector<test::Case> all = test::cases();
  const test::Case& c = all.front();
  const double R = 4.0 * max_radius(*c.model);
  const Model exact = Model::exact(c.model, 2.5, R);
  const Model multipole = Model::multipole(c.model, 3, 2.5, R);
  const Model quadratic = quadratic_approximation(exact);
  ASSERT_NE(exact_field(exact), nullptr);
  EXPECT_EQ(exact_field(exact)->R, R);
  EXPECT_EQ(exact_field(exact)->mass_model, c.model);
  // The field the steppers run on, the same object.
  EXPECT_EQ(&exact_model(exact).field, exact_field(exact));
  EXPECT_EQ(potential(exact_model(exact), kGamma), potential(exact, kGamma));
  EXPECT_EQ(exact_field(multipole), nullptr);
  EXPECT_EQ(exact_field(quadratic), nullptr);
  ASSERT_NE(multipole_field(multipole), nullptr);
  EXPECT_EQ(multipole_field(multipole)->order, 3);
  EXPECT_THROW(exact_model(multipole), InputError);
}

TEST(Model, ExactFieldIsTheMassModelsFieldInThePrincipalAxes) {
  const double mu = 2.5;
  for (const test::Case& c : test::cases()) {
    const double R = 4.0 * max_radius(*c.model);
    const Model m = Model::exact(c.model, mu, R);
    ASSERT_EQ(m.kind(), FieldKind::exact);
    // One source of mass properties: the body is the mass model's.
    const MassProperties mp = mass_properties(*c.model);
    EXPECT_EQ(m.body().mass(), mp.mass) << c.name;
    const Mat3& P = m.body().principal_axes();
    EXPECT_LE((P * m.body().center_of_mass() - mp.center_of_mass).norm(),
              1e-14 * (1 + mp.center_of_mass.norm()))
        << c.name;
    // Values at a body-frame γ are the mass model's at Pγ (the reference's frame).
    const test::Values ref = c.reference(mu, R, P * kGamma);
    EXPECT_NEAR(potential(m, kGamma), ref.potential, kValueTol * std::abs(ref.potential)) << c.name;
    EXPECT_LE((P * grad_gamma(m, kGamma) - ref.grad_gamma).norm(),
              kValueTol * ref.grad_gamma.norm())
        << c.name;
    EXPECT_LE((P * hessian_gamma(m, kGamma) * P.transpose() - ref.hessian).norm(),
              kValueTol * ref.hessian.norm())
        << c.name;
    // The moment: |δL| ≤ kValueTol |∂V/∂γ| (its normal part cancels in γ × ∂V/∂γ).
    EXPECT_LE((P * moment(m, kGamma) - ref.moment).norm(), kValueTol * ref.grad_gamma.norm())
        << c.name;
  }
}

TEST(Model, QuadraticApproximationHasGAndLambdaOfMuAndR) {
  const auto mm = test::cases()[3].model;  // offset box
  const Model m = Model::exact(mm, 3.0, 10.0);
  const QuadraticModel q = quadratic_approximation(m);
  EXPECT_DOUBLE_EQ(q.field.g, 3.0 / 100.0);
  EXPECT_DOUBLE_EQ(q.field.lambda_, 9.0 / 1000.0);
  EXPECT_EQ(q.body.inertia(), m.body().inertia());
  const Model quad = Model(Body::from_principal(Vec3(1.0, 2.0, 2.5), 1.0, Vec3(0.1, 0.0, 0.2)),
                           QuadraticField::from_mu_R(1.0, 5.0));
  EXPECT_EQ(quadratic_approximation(quad).field.lambda_, quad.quadratic().field.lambda_);
}

/// Central differences of f at γ, column by column, and the bound of their error: Richardson's
/// truncation estimate (doubled) plus the round-off δ|f|/h. h = ε^(1/3)·ℓ.
template <class F>
void expect_derivative(F&& f, const Mat3& df, double ell, double delta, const std::string& what) {
  auto cd = [&](double h) {
    Mat3 d;
    for (int j = 0; j < 3; ++j) {
      const Vec3 e = h * Vec3::Unit(j);
      d.col(j) = (f(kGamma + e) - f(kGamma - e)) / (2 * h);
    }
    return d;
  };
  const double h = std::cbrt(kEps) * ell;
  const Mat3 d1 = cd(h), d2 = cd(2 * h);
  const double tol = 2 * (d2 - d1).norm() / 3 + delta * f(kGamma).norm() / h;
  EXPECT_LE((df - d1).norm(), tol) << what;
  EXPECT_LT(tol, 1e-6 * df.norm()) << what;  // the check can fail
}

TEST(Model, HessianAndMomentJacobianAgainstFiniteDifferencesInEveryField) {
  const auto points = test::cases()[1].model;  // four points, r0 ≠ 0
  const auto box = test::cases()[3].model;     // offset box
  const double r = max_radius(*box);
  const std::vector<std::pair<std::string, Model>> models{
      {"quadratic", Model(body_of(*box), QuadraticField::coulomb(0.7, -1.3))},
      {"exact points", Model::exact(points, 2.0, 3.0 * max_radius(*points))},
      {"exact box", Model::exact(box, 2.0, 2.0 * r)},
      {"multipole box", Model::multipole(box, 6, 2.0, 3.0 * r)},
  };
  for (const auto& [name, m] : models) {
    const double ell = 0.5;      // (R − r)/R ≥ 1/2 for all of them: the scale on which V varies
    const double delta = 1e-13;  // relative accuracy of ∂V/∂γ and L here (≤ 100 ε (R/r)²)
    const Model& model = m;
    expect_derivative([&](const Vec3& g) -> Vec3 { return grad_gamma(model, g); },
                      hessian_gamma(model, kGamma), ell, delta, name + " hessian");
    expect_derivative([&](const Vec3& g) -> Vec3 { return moment(model, g); },
                      moment_jacobian(model, kGamma), ell, delta * 10, name + " moment_jacobian");
  }
}

TEST(Model, IntegralsAreThoseOfTheFieldItself) {
  const auto box = test::cases()[2].model;  // centred box: r0 = 0, k = 0
  const double mu = 2.0, R = 3.0 * max_radius(*box);
  const Model m = Model::exact(box, mu, R);
  const State s = state_from_omega(m.body(), Vec3(0.2, -0.1, 0.3), kGamma);
  const Vec3 w = omega(m.body(), s);
  const Mat3& P = m.body().principal_axes();
  const double V = test::cases()[2].reference(mu, R, P * kGamma).potential;
  const IntegralValues v = integrals(m, s);
  EXPECT_NEAR(v.energy, 0.5 * w.dot(m.body().inertia().cwiseProduct(w)) + V,
              kValueTol * std::abs(V));
  // Brun's integral is the quadratic field's (r0 = 0): not claimed in the exact field.
  EXPECT_FALSE(v.brun.has_value());
  EXPECT_EQ(conserved_integrals(m), (std::vector<std::string>{"energy", "area", "geometric"}));
  const IntegralValues q = integrals(Model(quadratic_approximation(m)), s);
  EXPECT_TRUE(q.brun.has_value());
  // The energies differ by the field's γ-independent part −μM/R and its octupole and beyond.
  EXPECT_GT(std::abs(q.energy - v.energy), 1e-3 * std::abs(v.energy));
}

}  // namespace
}  // namespace test_model
}  // namespace newtop
