// The quadratic field (docs/model.md §3–§4): moment against a finite difference of the potential,
// variants.

#include <gtest/gtest.h>

#include <cmath>

#include "support/problems.hpp"

namespace newtop {
namespace test_field {
namespace {

using test::kEps;

// Central differences of V along γ (V regarded on R³): the truncation error of a central difference
// is h²/6 |V'''| = 0 for a quadratic V, so only round-off remains: ~ ε |V| / h per component.
constexpr double kFdStep = 1e-4;
double fd_tolerance(double v_scale) { return 16 * kEps * v_scale / kFdStep; }

Vec3 fd_gradient(const QuadraticModel& m, const Vec3& gamma) {
  Vec3 g;
  for (int i = 0; i < 3; ++i) {
    Vec3 e = Vec3::Zero();
    e[i] = kFdStep;
    g[i] = (potential(m, gamma + e) - potential(m, gamma - e)) / (2 * kFdStep);
  }
  return g;
}

TEST(QuadraticField, MomentIsGammaCrossFiniteDifferenceGradient) {
  const QuadraticModel m = test::generic_model();
  for (const Vec3& gamma : {Vec3(0.48, -0.6, 0.64), Vec3(1, 0, 0), Vec3(0.0, 0.6, -0.8)}) {
    const Vec3 L = moment(m, gamma);
    const Vec3 L_fd = gamma.cross(fd_gradient(m, gamma));
    const double scale = 1.0 + std::abs(potential(m, gamma));
    EXPECT_LT((L - L_fd).cwiseAbs().maxCoeff(), fd_tolerance(scale));
  }
}

TEST(QuadraticField, MomentMatchesExpandedEulerPoisson) {
  // Spec §4 expanded: L = ((C−B) λ γ2γ3 + Mg(z0γ2 − y0γ3), (A−C) λ γ1γ3 + …, …).
  const QuadraticModel m = test::generic_model();
  const Vec3 gm(0.48, -0.6, 0.64);
  const double A = m.body.A(), B = m.body.B(), C = m.body.C(), lam = m.field.lambda_;
  const double Mg = m.body.mass() * m.field.g;
  const Vec3 r0 = m.body.center_of_mass();
  const Vec3 expected((C - B) * lam * gm[1] * gm[2] + Mg * (r0[2] * gm[1] - r0[1] * gm[2]),
                      (A - C) * lam * gm[0] * gm[2] + Mg * (r0[0] * gm[2] - r0[2] * gm[0]),
                      (B - A) * lam * gm[0] * gm[1] + Mg * (r0[1] * gm[0] - r0[0] * gm[1]));
  EXPECT_LT((moment(m, gm) - expected).cwiseAbs().maxCoeff(), 16 * kEps);
}

TEST(QuadraticField, NamedConstructors) {
  const QuadraticField f = QuadraticField::from_mu_R(398600.4418, 7000.0);
  EXPECT_DOUBLE_EQ(f.g, 398600.4418 / (7000.0 * 7000.0));
  EXPECT_DOUBLE_EQ(f.lambda_, 3 * 398600.4418 / (7000.0 * 7000.0 * 7000.0));
  EXPECT_DOUBLE_EQ(QuadraticField::from_g_R(2.0, 4.0).lambda_, 1.5);
  EXPECT_EQ(QuadraticField::uniform(9.81).lambda_, 0.0);
  EXPECT_EQ(QuadraticField::brun(0.8).lambda_, -0.8);
  EXPECT_THROW(QuadraticField::from_mu_R(1.0, 0.0), InputError);
  EXPECT_THROW(QuadraticField::from_mu_R(-1.0, 1.0), InputError);
  EXPECT_THROW(QuadraticField::coulomb(NAN, 1.0), InputError);
}

TEST(QuadraticField, BrunPlaneNotThroughOriginIsLinearPlusQuadratic) {
  // V = ½N Σ m_i (ρ_i·γ − d)² for point masses, against the general form −½Nγ·Iγ − N d M r0·γ
  // + const: differences of V between two directions must agree (the constant cancels).
  const double N = 0.7, d = 0.4;
  const std::vector<std::pair<double, Vec3>> pts{
      {1.0, Vec3(0.3, 0.1, -0.2)}, {2.0, Vec3(-0.1, 0.4, 0.2)}, {0.5, Vec3(0.2, -0.3, 0.5)}};
  Mat3 J = Mat3::Zero();
  Vec3 first = Vec3::Zero();
  double M = 0;
  for (const auto& [mi, r] : pts) {
    M += mi;
    first += mi * r;
    J += mi * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  const Body body = Body::from_tensor(J, M, first / M);
  const QuadraticModel model{body, QuadraticField::brun(N, d)};
  const Mat3& P = body.principal_axes();
  auto direct = [&](const Vec3& gamma_body) {
    const Vec3 gu = P * gamma_body;
    double v = 0;
    for (const auto& [mi, r] : pts) v += 0.5 * N * mi * std::pow(r.dot(gu) - d, 2);
    return v;
  };
  const Vec3 g1 = Vec3(0.48, -0.6, 0.64), g2 = Vec3(0, 0.6, 0.8);
  EXPECT_NEAR(direct(g1) - direct(g2), potential(model, g1) - potential(model, g2), 64 * kEps);
}

}  // namespace
}  // namespace test_field
}  // namespace newtop
