// Exact field of docs/model.md §2: moment, force and their identities; motion in the exact field.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "newtop/exact/exact_field.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop {
namespace test_exact_field {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

static_assert(Field<ExactField>);

std::shared_ptr<const MassModel> offset_box() {
  return std::make_shared<const MassModel>(
      make_box(Vec3(1.0, 1.6, 2.2), 1.3, Vec3(0.2, -0.1, 0.6)));
}

std::shared_ptr<const MassModel> points() {
  return std::make_shared<const MassModel>(
      PointMasses({1.0, 2.0, 0.5, 1.5},
                  {Vec3(1, 0, 0.3), Vec3(-0.4, 0.8, 0), Vec3(0, -0.5, 1), Vec3(0.2, 0.1, -0.7)}));
}

const Vec3 kGamma = Vec3(0.3, -0.5, 0.8).normalized();

TEST(ExactField, MomentIsGammaCrossFiniteDifferenceGradient) {
  const auto model = exact_model(offset_box(), 2.0, 6.0);
  const FieldValues v = field_values(model.field, kGamma);
  // Central differences of V in the free vector γ: truncation h² |V'''|/6 ~ h² |∂V/∂γ|,
  // round-off ε |V| / h; h = 1e-4 balances them near 1e-9 relative.
  const double h = 1e-4, tol = 1e-8;
  Vec3 fd;
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = h * Vec3::Unit(i);
    fd[i] = (potential(model.body, model.field, kGamma + e) -
             potential(model.body, model.field, kGamma - e)) /
            (2 * h);
  }
  EXPECT_LE((kGamma.cross(fd) - v.moment).norm(), tol * v.grad_gamma.norm());
  // ∂V/∂R by a central difference in R.
  ExactField up = model.field, down = model.field;
  up.R += h;
  down.R -= h;
  const double dR =
      (potential(model.body, up, kGamma) - potential(model.body, down, kGamma)) / (2 * h);
  EXPECT_NEAR(v.dV_dR, dR, tol * std::abs(v.dV_dR));
}

TEST(ExactField, ForceIdentitiesAgainstDirectIntegral) {
  // Point masses: F = −μ Σ m (Rγ + ρ)/|Rγ + ρ|³ and L = μR γ × Σ m ρ/|Rγ + ρ|³ (docs/model.md §2,
  // corrected sign) computed directly; the formulas from ∂V/∂γ and ∂V/∂R must reproduce them.
  const double mu = 3.0, R = 5.0;
  const auto pm = points();
  const ExactField f = ExactField::make(pm, mu, R);
  const auto& P = std::get<PointMasses>(*pm);
  Vec3 F = Vec3::Zero(), S = Vec3::Zero();
  for (std::size_t i = 0; i < P.masses().size(); ++i) {
    const Vec3 d = R * kGamma + P.positions()[i];
    F -= mu * P.masses()[i] * d / std::pow(d.norm(), 3);
    S += P.masses()[i] * P.positions()[i] / std::pow(d.norm(), 3);
  }
  const Vec3 L = mu * R * kGamma.cross(S);
  const FieldValues v = field_values(f, kGamma);
  // Sums of 4 terms, each a few roundings: 64 ε of the largest term.
  const double tol = 64 * kEps;
  EXPECT_LE((v.force - F).norm(), tol * F.norm());
  EXPECT_LE((v.moment - L).norm(), tol * F.norm() * R);
  EXPECT_NEAR(v.force.dot(kGamma), -v.dV_dR, tol * F.norm());
  EXPECT_NEAR(v.force.norm(),
              std::sqrt(v.dV_dR * v.dV_dR + kGamma.cross(v.grad_gamma).squaredNorm() / (R * R)),
              tol * F.norm());
  // F·L = 0: the attraction is one force through O′.
  EXPECT_LE(std::abs(v.force.dot(v.moment)), tol * v.force.norm() * v.moment.norm() * 4);
}

TEST(ExactField, PolyhedronForceIsMinusMuGradientAndNormalToMoment) {
  // F = −μ ∇Φ(−Rγ) directly from the closed form, against the docs/model.md §2 formula.
  const auto model = exact_model(offset_box(), 2.0, 4.0);
  const Vec3 gm = model.field.axes * kGamma;
  const Attraction a = attraction(*model.field.mass_model, -4.0 * gm);
  const Vec3 F = model.field.axes.transpose() * (-2.0 * a.gradient);
  const FieldValues v = field_values(model.field, kGamma);
  const double tol = 64 * kEps;  // a few roundings in the projection
  EXPECT_LE((v.force - F).norm(), tol * F.norm());
  EXPECT_LE(std::abs(v.force.dot(v.moment)), tol * v.force.norm() * v.moment.norm());
}

TEST(ExactField, FarFromAPolyhedronExactToRoundOff) {
  // A cube centred at O has no quadrupole: Φ = M/R (1 + O((r/R)⁴)). At R = 1e4 r the closed form
  // alone would lose ~ε (R/r)² ≈ 1e-8 to cancellation; the far-field series keeps a few ε.
  const auto cube = std::make_shared<const MassModel>(make_box(Vec3(2, 2, 2), 1.0));
  const double R = 1e4 * max_radius(*cube), M = 8.0;
  const ExactField f = ExactField::make(cube, 1.0, R);
  ASSERT_TRUE(f.far_moments);
  const double V = field_values(f, kGamma).potential;
  EXPECT_NEAR(V, -M / R, 16 * kEps * M / R);
  // Near the switch both evaluations agree to the closed form's accuracy, C ε (R/r)² with C
  // measured at 100–300 on Eros and boxes (the sums have hundreds of terms); bound with C = 400.
  const auto box = offset_box();
  const double r = max_radius(*box), Rs = 1.01 * ExactField::kFarField * r;
  const ExactField near = ExactField::make(box, 1.0, Rs);
  ASSERT_TRUE(near.far_moments);
  const Attraction closed = attraction(*box, -Rs * kGamma);
  const FieldValues series = field_values(near, kGamma);
  const double tol = 400 * kEps * std::pow(ExactField::kFarField, 2);
  EXPECT_NEAR(series.potential, -closed.potential, tol * closed.potential);
  EXPECT_LE((series.grad_gamma - Rs * closed.gradient).norm(), tol * Rs * closed.gradient.norm());
}

TEST(ExactField, RejectsCentreInsideTheBody) {
  EXPECT_THROW(ExactField::make(offset_box(), 1.0, 0.5), InputError);
  EXPECT_THROW(ExactField::make(offset_box(), -1.0, 10.0), InputError);
}

TEST(ExactField, SplittingConservesCasimirsAndAgreesWithRkf78) {
  // Motion in the exact field: splitting4 (exact ∂V/∂γ in the kick) against a tight rkf78 run.
  const auto model = exact_model(offset_box(), 40.0, 5.0);
  const State x0 = state_from_omega(model.body, Vec3(0.4, -0.3, 1.1), kGamma);
  const double T = 4.0;
  SplittingStepper split(composition_table("splitting4"));
  const Outcome a = integrate(split, model, x0, 0.0, T, IntegrateOptions{.step = 0.005});
  Fehlberg78Stepper rk(1e-13, 1e-13);
  const Outcome b = integrate(rk, model, x0, 0.0, T, IntegrateOptions{});
  ASSERT_EQ(a.status, Status::finished);
  ASSERT_EQ(b.status, Status::finished);
  // Casimirs exact to round-off over 800 steps: 64 ε √n.
  const double cas = 64 * kEps * std::sqrt(800.0);
  EXPECT_NEAR(geometric(a.state), 1.0, cas);
  EXPECT_NEAR(area(a.state), area(x0), cas * x0.m.norm());
  // Fourth order, h = 0.005, |ω| ~ 1: global error ~ C h⁴ T with C ≲ 1e3 → 2.5e-6.
  const double tol = 2.5e-6;
  EXPECT_LE((a.state.gamma - b.state.gamma).norm(), tol);
  EXPECT_LE((a.state.m - b.state.m).norm(), tol * x0.m.norm());
  const double e0 = energy(model, x0);
  EXPECT_NEAR(energy(model, a.state), e0, tol * std::abs(e0));
  // The motion differs from the quadratic model's: the exact field matters here.
  const QuadraticModel quad{model.body, QuadraticField::from_mu_R(40.0, 5.0)};
  Fehlberg78Stepper rq(1e-13, 1e-13);
  const Outcome c = integrate(rq, quad, x0, 0.0, T, IntegrateOptions{});
  EXPECT_GT((c.state.gamma - b.state.gamma).norm(), 100 * tol);
}

}  // namespace
}  // namespace test_exact_field
}  // namespace newtop
