// The moment of the exact and multipole fields far from the body (docs/model.md §2, §3): relative
// error against 50/100-digit references and against the quadratic model, R/r = 1e1 … 1e8. Formed
// naively as γ × ∂V/∂γ it would lose ε (R/r)² of its digits (∂V/∂γ ≈ μM/R is radial; the moment is
// (R/r)² smaller); the fields form it without that cancellation.
//
// Run `test_exact --gtest_filter='MomentAccuracy.*'` to print the table.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "bodies.hpp"
#include "newtop/exact/multipole.hpp"

namespace newtop {
namespace test_moment_accuracy {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The moment is a sum of terms of its own size (the monopole's radial term excluded, no
// cancellation): each term a few roundings (≤ 8 ε), the sums of ≤ 6 points, 12 triangles or
// a series of some dozen terms adding up to κ·8 ε with κ = Σ|terms|/|sum| ≲ 4 for these bodies
// and directions: 32 ε. (Measured: ≤ 6 ε, table below.)
constexpr double kMomentTol = 32 * kEps;

const Vec3 kGamma = Vec3(-0.95855, -0.13584, -0.25046).normalized();

double rel(const Vec3& a, const Vec3& b) { return (a - b).norm() / b.norm(); }

/// The quadratic model's moment γ × (M g r0 + λ Iγ) in the body's principal axes, turned back
/// into the mass model's frame.
Vec3 quadratic_moment(const MassModel& m, double mu, double R, const Vec3& gamma) {
  const Body body = body_of(m);
  const Mat3& P = body.principal_axes();
  return P * moment(body, QuadraticField::from_mu_R(mu, R), P.transpose() * gamma);
}

TEST(MomentAccuracy, FewUlpsAgainstHighPrecisionAndTheQuadraticModel) {
  const double mu = 3.986004360e14;
  std::printf("%-22s %8s %12s %12s %12s %12s\n", "body", "R/r", "exact-ref", "order3-quad",
              "exact-quad", "|exact-ser|");
  for (const test::Case& c : test::cases()) {
    const double r = max_radius(*c.model);
    for (double q = 1e1; q <= 1e8 * 1.0001; q *= 10) {
      const double R = q * r;
      const Vec3 ref = c.reference(mu, R, kGamma).moment;
      const Vec3 exact = field_values(ExactField::make(c.model, mu, R), kGamma).moment;
      const Vec3 order3 = field_values(MultipoleField::make(*c.model, 3, mu, R), kGamma).moment;
      const Vec3 series = field_values(MultipoleField::make(*c.model, 20, mu, R), kGamma).moment;
      const Vec3 quad = quadratic_moment(*c.model, mu, R, kGamma);
      std::printf("%-22s %8.0e %12.2e %12.2e %12.2e %12.2e\n", c.name.c_str(), q, rel(exact, ref),
                  rel(order3, quad), rel(exact, quad), rel(series, ref));
      ASSERT_TRUE(ref.allFinite() && exact.allFinite());
      EXPECT_LE(rel(exact, ref), kMomentTol) << c.name << " R/r = " << q;
      // Order 20: truncation (r/R)^18 of the leading moment, below ε from R/r = 10 on.
      EXPECT_LE(rel(series, ref), kMomentTol) << c.name << " R/r = " << q;
      // Order 3 is the quadratic model (different formulas: mass moments and Taylor coefficients
      // against the diagonalised inertia tensor), at every distance.
      EXPECT_LE(rel(order3, quad), kMomentTol) << c.name << " R/r = " << q;
      // A symmetric body's next term is (r/R)² of the moment: below round-off at R/r = 1e8.
      if (c.symmetric && q >= 1e8) {
        EXPECT_LE(rel(exact, quad), kMomentTol) << c.name;
      }
    }
  }
}

}  // namespace
}  // namespace test_moment_accuracy
}  // namespace newtop
