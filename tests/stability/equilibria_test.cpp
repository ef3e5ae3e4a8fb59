// Equilibria of docs/model.md §7: the secular polynomial against a brute-force multistart search,
// the Brun case with its six equilibria, the count rule and the degenerate families.

#include "newtop/analysis/equilibria.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <set>

#include "support.hpp"

namespace newtop {
namespace test_equilibria_test {
namespace {

using stability_test::kEps;
using stability_test::random_unit;
using stability_test::uniform;

// γ × ∂V/∂γ at a computed equilibrium, relative to |∂V/∂γ|: the root is polished by Newton to
// round-off, γ is built from a few divisions and a normalisation: a few tens of ulps (measured up
// to 67 ulps, clang 14 at -O1; 64 was exceeded there): 128 ε.
constexpr double kResidual = 128 * kEps;
// Two equilibria are the same point when this close: the brute-force Newton solution and the
// polished root each sit within ~1e-14 of the exact point; 1e-9 leaves room and still separates
// points that are O(1e-3) apart in the random cases.
constexpr double kSamePoint = 1e-9;

double residual(const QuadraticModel& model, const Vec3& gamma) {
  const Vec3 grad = grad_gamma(model, gamma);
  return gamma.cross(grad).norm() / grad.norm();
}

// At an equilibrium ∂V/∂γ = b + λIγ = κγ can be much shorter than its two terms (κ small): the
// residual, relative to |∂V/∂γ|, carries the terms' rounding relative to that shorter vector.
double residual_bound(const QuadraticModel& model, const Vec3& g) {
  const Vec3 b = model.body.mass() * model.field.g * model.body.center_of_mass();
  const Vec3 d = model.field.lambda_ * model.body.inertia();
  const double terms = b.norm() + d.cwiseProduct(g).norm();
  return kResidual * std::max(1.0, terms / grad_gamma(model, g).norm());
}

/// Brute force: Newton on (b + λIγ − κγ = 0, ½(γ·γ − 1) = 0) from `starts` random points on the
/// sphere; the distinct converged solutions.
std::vector<Vec3> multistart(const QuadraticModel& model, std::mt19937& rng, int starts) {
  const Vec3 b = model.body.mass() * model.field.g * model.body.center_of_mass();
  const Vec3 d = model.field.lambda_ * model.body.inertia();
  std::vector<Vec3> found;
  for (int k = 0; k < starts; ++k) {
    Eigen::Vector4d x;
    x.head<3>() = random_unit(rng);
    x[3] = x.head<3>().dot(b + d.cwiseProduct(x.head<3>()));
    for (int it = 0; it < 60; ++it) {
      const Vec3 g = x.head<3>();
      Eigen::Vector4d F;
      F.head<3>() = b + d.cwiseProduct(g) - x[3] * g;
      F[3] = 0.5 * (g.squaredNorm() - 1.0);
      Eigen::Matrix4d J = Eigen::Matrix4d::Zero();
      J.topLeftCorner<3, 3>() = Mat3(d.asDiagonal()) - x[3] * Mat3::Identity();
      J.block<3, 1>(0, 3) = -g;
      J.block<1, 3>(3, 0) = g.transpose();
      x -= J.fullPivLu().solve(F);
    }
    const Vec3 g = x.head<3>();
    if (!x.allFinite() || std::abs(g.norm() - 1) > 1e-12 || residual(model, g) > kResidual) {
      continue;
    }
    bool seen = false;
    for (const auto& f : found) seen = seen || (f - g).norm() <= kSamePoint;
    if (!seen) found.push_back(g);
  }
  return found;
}

/// Independent type check: V on a small circle around γ on the sphere against V(γ).
EquilibriumType type_by_sampling(const QuadraticModel& model, const Vec3& gamma) {
  const Vec3 t1 =
      gamma.cross(std::abs(gamma.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
  const Vec3 t2 = gamma.cross(t1);
  const double v0 = potential(model, gamma);
  int above = 0, below = 0;
  for (int k = 0; k < 64; ++k) {
    const double phi = 2 * M_PI * k / 64;
    const Vec3 g = (gamma + 1e-4 * (std::cos(phi) * t1 + std::sin(phi) * t2)).normalized();
    (potential(model, g) > v0 ? above : below)++;
  }
  if (below == 0) return EquilibriumType::minimum;
  if (above == 0) return EquilibriumType::maximum;
  return EquilibriumType::saddle;
}

TEST(Equilibria, BrunCaseHasSixEquilibriaWithTypesByMoment) {
  // r0 = 0 (docs/model.md §7): ±e_x, ±e_y, ±e_z; λ > 0: least moment minimum, middle saddle,
  // largest maximum; λ < 0 reversed. Moments deliberately not sorted by axis.
  const Body body = Body::from_principal(Vec3(1.5, 2.2, 1.0), 1.0, Vec3::Zero());
  for (double lambda : {0.7, -0.7}) {
    const EquilibriumSet set =
        find_equilibria(QuadraticModel{body, QuadraticField::coulomb(1.0, lambda)});
    ASSERT_EQ(set.equilibria.size(), 6u);
    EXPECT_TRUE(set.count_rule_holds());
    for (const auto& e : set.equilibria) {
      Eigen::Index axis;
      const Vec3 abs_gamma = e.gamma.cwiseAbs();
      EXPECT_NEAR(abs_gamma.maxCoeff(&axis), 1.0, kResidual);
      const double I = body.inertia()[axis];
      const EquilibriumType by_moment = I == body.inertia().minCoeff()   ? EquilibriumType::minimum
                                        : I == body.inertia().maxCoeff() ? EquilibriumType::maximum
                                                                         : EquilibriumType::saddle;
      const EquilibriumType expected =
          lambda > 0                              ? by_moment
          : by_moment == EquilibriumType::minimum ? EquilibriumType::maximum
          : by_moment == EquilibriumType::maximum ? EquilibriumType::minimum
                                                  : EquilibriumType::saddle;
      EXPECT_EQ(e.type, expected) << "axis " << axis << " lambda " << lambda;
      EXPECT_DOUBLE_EQ(e.kappa, lambda * I);
    }
  }
}

TEST(Equilibria, RandomParametersAgreeWithMultistartSearch) {
  std::mt19937 rng(20240607);
  std::set<std::size_t> counts;
  for (int trial = 0; trial < 60; ++trial) {
    // r0 from tiny to large against λ(I_max − I_min), so that 2, 4 and 6 equilibria all occur;
    // every fourth trial has a zero component of r0 (the degenerate branch κ = λ I_i).
    Vec3 r0 = std::pow(10.0, uniform(rng, -2.5, 0.3)) * random_unit(rng);
    if (trial % 4 == 0) r0[trial % 3] = 0.0;
    const double lambda = (trial % 2 ? 1.0 : -1.0) * uniform(rng, 0.5, 3.0);
    const QuadraticModel model{stability_test::random_body(rng, r0),
                               QuadraticField::coulomb(1.0, lambda)};
    const EquilibriumSet set = find_equilibria(model);
    const std::vector<Vec3> brute = multistart(model, rng, 300);
    ASSERT_EQ(set.equilibria.size(), brute.size()) << "trial " << trial;
    counts.insert(brute.size());
    for (const auto& e : set.equilibria) {
      ASSERT_TRUE(e.gamma.allFinite());
      EXPECT_LE(residual(model, e.gamma), residual_bound(model, e.gamma)) << "trial " << trial;
      EXPECT_NEAR(e.gamma.norm(), 1.0, kResidual);
      EXPECT_LE(std::abs(e.staude_residual),
                kResidual * model.body.inertia().maxCoeff() * r0.norm());
      EXPECT_EQ(e.type, type_by_sampling(model, e.gamma)) << "trial " << trial;
      bool matched = false;
      for (const auto& g : brute) matched = matched || (g - e.gamma).norm() <= kSamePoint;
      EXPECT_TRUE(matched) << "trial " << trial << " gamma " << e.gamma.transpose();
    }
    EXPECT_TRUE(set.count_rule_holds())
        << "trial " << trial << ": " << set.minima << " - " << set.saddles << " + " << set.maxima;
  }
  EXPECT_EQ(counts, (std::set<std::size_t>{2, 4, 6}));
}

TEST(Equilibria, SecularPolynomialVanishesAtEveryMultiplier) {
  // P(κ) = Π (κ − d_g)² (Σ β_g/(κ − d_g)² − 1): at each κ the secular equation holds, so P's
  // value is round-off relative to the size of its terms, scale^6.
  const QuadraticModel model{
      Body::from_principal(Vec3(1.0, 1.4, 1.9), 2.0, Vec3(0.05, -0.03, 0.02)),
      QuadraticField::coulomb(1.0, 1.2)};
  const Eigen::VectorXd p = secular_polynomial(model);
  ASSERT_EQ(p.size(), 7);
  EXPECT_EQ(p[6], -1.0);
  const EquilibriumSet set = find_equilibria(model);
  ASSERT_EQ(set.equilibria.size(), 6u);
  const double scale = 1.2 * 1.9 + 2.0 * Vec3(0.05, -0.03, 0.02).norm();
  for (const auto& e : set.equilibria) {
    double value = 0.0, power = 1.0;
    for (Eigen::Index i = 0; i < p.size(); ++i, power *= e.kappa) value += p[i] * power;
    EXPECT_LE(std::abs(value), 1e3 * kEps * std::pow(scale, 6));
  }
}

TEST(Equilibria, CompanionRootsOfKnownPolynomial) {
  // (x − 1)(x − 2)(x + 3)(x² + 1), built from its factors: real roots −3, 1, 2 and the pair ±i.
  auto mul = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(a.size() + b.size() - 1);
    for (Eigen::Index i = 0; i < a.size(); ++i) r.segment(i, b.size()) += a[i] * b;
    return r;
  };
  const Eigen::VectorXd p =
      mul(mul(mul(Eigen::Vector2d(-1, 1), Eigen::Vector2d(-2, 1)), Eigen::Vector2d(3, 1)),
          Eigen::Vector3d(1, 0, 1));
  const std::vector<double> r = real_polynomial_roots(p, 1e-9);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], -3.0, 64 * kEps * 3);
  EXPECT_NEAR(r[1], 1.0, 64 * kEps * 3);
  EXPECT_NEAR(r[2], 2.0, 64 * kEps * 3);
}

TEST(Equilibria, UniformGravityWithoutOffsetIsEveryOrientation) {
  const Body body = Body::from_principal(Vec3(1.0, 1.5, 2.0), 1.0, Vec3::Zero());
  EXPECT_TRUE(
      find_equilibria(QuadraticModel{body, QuadraticField::uniform(9.81)}).every_orientation);
  // With an offset: the heavy top hangs (minimum, γ = −r0/|r0|) or stands (maximum).
  const Vec3 r0(0.1, 0.2, -0.3);
  const EquilibriumSet set = find_equilibria(QuadraticModel{
      Body::from_principal(Vec3(1.0, 1.5, 2.0), 1.0, r0), QuadraticField::uniform(9.81)});
  ASSERT_EQ(set.equilibria.size(), 2u);
  EXPECT_EQ(set.equilibria[0].type, EquilibriumType::minimum);
  EXPECT_LE((set.equilibria[0].gamma + r0.normalized()).norm(), kResidual);
  EXPECT_EQ(set.equilibria[1].type, EquilibriumType::maximum);
  EXPECT_TRUE(set.count_rule_holds());
}

TEST(Equilibria, SymmetricBodyWithAxialOffsetHasACircle) {
  // A = B, r0 on the axis: ±e_z and, where |M g z0 / (λ(A − C))| < 1, a circle with
  // γ_z = M g z0 / (λ(A − C)) (κ = λA, docs/model.md §7 degenerate case with two free components).
  const double A = 2.0, C = 1.0, z0 = 0.3, lambda = 1.0;
  const QuadraticModel model{Body::from_principal(Vec3(A, A, C), 1.0, Vec3(0, 0, z0)),
                             QuadraticField::coulomb(1.0, lambda)};
  const EquilibriumSet set = find_equilibria(model);
  ASSERT_EQ(set.equilibria.size(), 2u);
  ASSERT_EQ(set.circles.size(), 1u);
  EXPECT_EQ(set.circles[0].axis, 2);
  EXPECT_NEAR(set.circles[0].gamma_axis, z0 / (lambda * (A - C)), kResidual);
  EXPECT_FALSE(set.count_rule_holds());
  // Every point of the circle is an equilibrium.
  const double gz = set.circles[0].gamma_axis, rho = std::sqrt(1 - gz * gz);
  for (double phi : {0.0, 1.0, 2.5}) {
    const Vec3 g(rho * std::cos(phi), rho * std::sin(phi), gz);
    EXPECT_LE(residual(model, g), kResidual);
  }
}

}  // namespace
}  // namespace test_equilibria_test
}  // namespace newtop
