// Brun's case, level f = 0: the sphero-conic change of variables (m, γ) → (u, w) → (φ, signs) →
// (m, γ) is the identity to round-off on random points of random levels, the separated points lie
// on the curve w² = R(u), and the generating identity for N(u) holds.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "newtop/analysis/brun_separation.hpp"
#include "newtop/model/integrals.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_brun_separation {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// The round trip takes ~50 operations on O(1) numbers and square roots of differences of
// the e_i (condition ~ (e3 − e1)/(e_(i+1) − e_i) ≤ 10 for the bodies drawn): 64·10 ε.
constexpr double kRoundTrip = 640 * kEps;
// Near a branch point the return trip amplifies the error of u_s: γ_i² ∝ Π_s (u_s − e_i) gives
// δγ_i = (γ_i / 2) Σ_s δu_s / (u_s − e_i), with δu_s ≈ 64 ε (e3 − e1) from the root finding.
double round_trip_bound(const BrunCurve& k, const State& x) {
  const BrunPoint p = brun_point(k, x);
  double amplification = 10;
  for (int i = 0; i < 3; ++i) {
    double sum = 0;
    for (int s = 0; s < 2; ++s) sum += 1 / std::abs(p.u[s] - k.e[i]);
    amplification =
        std::max(amplification, (k.e[2] - k.e[0]) * std::abs(x.gamma[k.axis[i]]) * sum / 2);
  }
  return 64 * kEps * amplification;
}
// w² and R(u) are sums of terms of size |m|² (e3 − e1)³ ≲ 100 for the levels drawn; ~40 flops.
constexpr double kCurveRelation = 64 * kEps;

using test::random_brun_level;
using RandomLevel = test::RandomBrunLevel;

RandomLevel random_level(std::mt19937_64& rng) { return random_brun_level(rng, true); }

TEST(BrunSeparation, ChangeOfVariablesIsTheIdentity) {
  std::mt19937_64 rng(20240611);
  for (int trial = 0; trial < 200; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_curve(L.model, L.x0);
    const BrunAngles a = brun_angles(k, L.x0);
    const State back = brun_state_at(k, a);
    ASSERT_TRUE(back.m.allFinite() && back.gamma.allFinite());
    const double scale = std::max(1.0, L.x0.m.norm());
    const double bound = round_trip_bound(k, L.x0);
    EXPECT_LT((back.m - L.x0.m).cwiseAbs().maxCoeff(), bound * scale) << trial;
    EXPECT_LT((back.gamma - L.x0.gamma).cwiseAbs().maxCoeff(), bound) << trial << " " << bound;
    // The other way: any angles and signs give a state of the same level whose angles and signs
    // are the same (φ taken mod 2π; a turn of φ_s with flips is the reflected state).
    std::uniform_real_distribution<double> phi(0.0, 2 * std::acos(-1.0));
    const BrunAngles b{{phi(rng), phi(rng)}, {1.0, -1.0, 1.0}};
    const State y = brun_state_at(k, b);
    EXPECT_NEAR(y.gamma.norm(), 1.0, kRoundTrip);
    EXPECT_NEAR(area(y), 0.0, kRoundTrip * scale);
    EXPECT_NEAR(energy(L.model, y), k.h, kRoundTrip * scale * scale);
    EXPECT_NEAR(brun(L.model, y), k.c, 10 * kRoundTrip * scale * scale);
    const BrunAngles c = brun_angles(k, y);
    for (int s = 0; s < 2; ++s) EXPECT_NEAR(c.phi[s], b.phi[s], 1e3 * kRoundTrip) << trial;
  }
}

TEST(BrunSeparation, PointsLieOnTheCurveAndNMatchesItsDefinition) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_curve(L.model, L.x0);
    const BrunPoint p = brun_point(k, L.x0);
    const double scale = std::max(1.0, L.x0.m.squaredNorm()) * std::pow(k.e[2] - k.e[0], 3);
    for (int s = 0; s < 2; ++s) {
      EXPECT_GE(p.u[s], k.root[k.lower[s]]);
      EXPECT_LE(p.u[s], k.root[k.upper[s]]);
      EXPECT_NEAR(p.w[s] * p.w[s], brun_R(k, p.u[s]), kCurveRelation * scale) << trial;
    }
    // N(u) = λ P(u) Σ γ_i²/(u − e_i) + Σ m_i² (u − e_i) at an arbitrary u (working frame).
    const State w = to_working_frame(k, L.x0);
    const double u = 0.3;
    double rhs = 0;
    for (int i = 0; i < 3; ++i) {
      const double others = (u - k.e[(i + 1) % 3]) * (u - k.e[(i + 2) % 3]);
      rhs += k.lambda_ * w.gamma[i] * w.gamma[i] * others + w.m[i] * w.m[i] * (u - k.e[i]);
    }
    EXPECT_NEAR(brun_N(k, u), rhs, kCurveRelation * 100 * std::max(1.0, std::abs(rhs)));
  }
}

TEST(BrunSeparation, RejectsNonzeroAreaEqualMomentsAndOtherCases) {
  const QuadraticModel model{Body::from_principal(Vec3(1, 1.5, 2.2), 1.0, Vec3::Zero()),
                             QuadraticField::brun(0.8)};
  const State off_level{Vec3(0.5, 1.65, -0.88), Vec3(0.48, -0.6, 0.64)};
  EXPECT_THROW(brun_curve(model, off_level), InputError);
  const QuadraticModel equal{Body::from_principal(Vec3(1, 2, 2), 1.0, Vec3::Zero()),
                             QuadraticField::brun(0.8)};
  EXPECT_THROW(brun_curve(equal, State{Vec3(0, 0.8, -0.6), Vec3(0, 0.6, 0.8)}), InputError);
  const QuadraticModel heavy{Body::from_principal(Vec3(1, 1.5, 2.2), 1.0, Vec3(0, 0, 0.1)),
                             QuadraticField::coulomb(1.0, 0.8)};
  EXPECT_THROW(brun_curve(heavy, State{Vec3(0, 0.8, -0.6), Vec3(0, 0.6, 0.8)}), InputError);
}

}  // namespace
}  // namespace test_brun_separation
}  // namespace newtop
