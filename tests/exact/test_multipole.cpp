// Multipole expansion (docs/model.md §3): the quadratic model, the R⁻⁴ error law, convergence and
// the truncation bound; Brun's field from a plane not through O.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "newtop/exact/multipole.hpp"

namespace newtop {
namespace test_multipole {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

static_assert(Field<MultipoleField>);

const MassModel kTet = Polyhedron::make(
    {Vec3(0.1, 0.2, -0.1), Vec3(1.3, 0, 0), Vec3(0, 0.9, 0.2), Vec3(0.3, 0.1, 1.6)},
    {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, 2.0);
const Vec3 kGamma = Vec3(-0.2, 0.6, 0.7).normalized();

TEST(Multipole, MomentsOfTheSameBoxAgreeAcrossModels) {
  // A box as a polyhedron and as 2³ point masses... differ; but a box and an ellipsoid share
  // nothing. Instead: a cube's moments against closed forms ∫ x^i = (b^{i+1} − a^{i+1})/(i+1).
  const MassMoments m(make_box(Vec3(2, 2, 2), 1.0, Vec3(1, 1, 1)), 6);  // [0, 2]³
  auto one = [](int i) { return std::pow(2.0, i + 1) / (i + 1); };
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; i + j <= 6; ++j)
      for (int k = 0; i + j + k <= 6; ++k) {
        const double want = one(i) * one(j) * one(k);
        EXPECT_NEAR(m(i, j, k), want, 1024 * kEps * want) << i << j << k;
      }
  // Ellipsoid moments against the ball: ∫ z² over a ball of radius a = 4π a⁵/15.
  const MassMoments e(Ellipsoid::make(Vec3(2, 2, 2), 1.0), 4);
  EXPECT_NEAR(e(0, 0, 2), 4 * M_PI * 32 / 15, 64 * kEps * 30);
  EXPECT_EQ(e(1, 0, 1), 0.0);
}

TEST(Multipole, OrderThreeIsTheQuadraticModelOfSpec3) {
  const double mu = 5.0, R = 7.0;
  const Body body = body_of(kTet);
  const MultipoleField f = MultipoleField::make(kTet, 3, mu, R, body.principal_axes());
  const FieldValues v = field_values(f, kGamma);
  const double M = body.mass(), trI = body.inertia().sum();
  const double V3 =
      -mu * (M / R - M / (R * R) * kGamma.dot(body.center_of_mass()) +
             (trI - 3 * kGamma.dot(body.inertia().cwiseProduct(kGamma))) / (2 * R * R * R));
  const double tol = 256 * kEps;  // a few dozen terms
  EXPECT_NEAR(v.potential, V3, tol * std::abs(V3));
  const QuadraticField q = QuadraticField::from_mu_R(mu, R);
  const Vec3 L = moment(body, q, kGamma);
  EXPECT_LE((v.moment - L).norm(), tol * v.grad_gamma.norm());
}

TEST(Multipole, ErrorOfQuadraticModelFallsAsRToMinusFour) {
  // At fixed μ the neglected octupole makes |V − V_3| and |L − L_3| ∝ R⁻⁴. The exact V of point
  // masses is a plain sum (relative error ε, no cancellation), so the difference is clean down
  // to 1e-9 relative. R = 20 … 160 body radii: the next term bends the fitted slope by about the
  // ratio r/R ≤ 5 % of one order only at the near end, i.e. by ~0.02.
  const MassModel pm = PointMasses(
      {1.0, 2.0, 3.0, 0.7},
      {Vec3(1, 0, 0.2), Vec3(0, 0.5, 0.1), Vec3(0.3, -0.2, 0.7), Vec3(-0.6, -0.4, -0.5)});
  const double mu = 1.0;
  const Body body = body_of(pm);
  const auto shared = std::make_shared<const MassModel>(pm);
  const double r = max_radius(pm);
  std::vector<double> lx, ly, lm;
  for (double R = 20.0 * r; R <= 160.0 * r; R *= 2) {
    const ExactField e = ExactField::make(shared, mu, R, body.principal_axes());
    const MultipoleField q = MultipoleField::make(pm, 3, mu, R, body.principal_axes());
    const FieldValues a = field_values(e, kGamma), b = field_values(q, kGamma);
    lx.push_back(std::log(R));
    ly.push_back(std::log(std::abs(a.potential - b.potential)));
    lm.push_back(std::log((a.moment - b.moment).norm()));
  }
  auto slope = [&](const std::vector<double>& y) {
    const double n = static_cast<double>(lx.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < lx.size(); ++i) {
      sx += lx[i], sy += y[i], sxx += lx[i] * lx[i], sxy += lx[i] * y[i];
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  };
  EXPECT_NEAR(slope(ly), -4.0, 0.05);
  EXPECT_NEAR(slope(lm), -4.0, 0.05);
}

TEST(Multipole, ConvergesToExactWithinTheTruncationBound) {
  const double mu = 2.0, R = 4.0;  // max radius ≈ 1.6: ratio 0.4
  // (The closed form is accurate to ~1e-14 relative at R = 2.5 radii; each term falls by ~0.4.)
  const auto shared = std::make_shared<const MassModel>(kTet);
  const FieldValues exact = field_values(ExactField::make(shared, mu, R), kGamma);
  double last = INFINITY;
  for (int p = 1; p <= 14; ++p) {
    const MultipoleField f = MultipoleField::make(kTet, p, mu, R);
    const double err = std::abs(field_values(f, kGamma).potential - exact.potential);
    const TruncationError t = truncation_error(f, kGamma);
    EXPECT_LE(err, t.bound * (1 + 1e-9)) << p;
    // The first omitted term dominates the error while the error is above round-off.
    if (err > 1e-12) {
      EXPECT_NEAR(t.next_term, err, 0.8 * err) << p;
    }
    last = err;
  }
  EXPECT_LT(last, 1e-6 * std::abs(exact.potential));
}

TEST(Multipole, BrunFieldFromPlaneNotThroughO) {
  // Brun: V = ½N Σ m (ρ·γ − d)², the force ∝ mass and distance to a plane with normal γ at offset
  // d. Up to a γ-independent constant it is the general form with λ = −N, g = −N d (docs/model.md
  // §3).
  const PointMasses pm({1.0, 2.0, 0.5}, {Vec3(1, 0.2, 0), Vec3(-0.3, 0.7, 0.4), Vec3(0, -1, 1.2)});
  const Body body = body_of(pm);
  const double N = 2.5, d = 0.8;
  auto brun_direct = [&](const Vec3& g_user) {
    double v = 0;
    for (std::size_t i = 0; i < pm.masses().size(); ++i) {
      v += 0.5 * N * pm.masses()[i] * std::pow(pm.positions()[i].dot(g_user) - d, 2);
    }
    return v;
  };
  const QuadraticField q = QuadraticField::brun(N, d);
  const Mat3& P = body.principal_axes();
  const Vec3 g1 = kGamma, g2 = Vec3(0.9, -0.1, 0.3).normalized();
  const double direct = brun_direct(P * g1) - brun_direct(P * g2);
  const double general = potential(body, q, g1) - potential(body, q, g2);
  EXPECT_NEAR(general, direct, 256 * kEps * N * 4);
}

}  // namespace
}  // namespace test_multipole
}  // namespace newtop
