// Periodic solutions of Beletsky's equation by 2-D shooting (docs/orbit.md §9): the symmetric
// solutions recovered from nearby starts, and an asymmetric pair born in a pitchfork bifurcation of
// a symmetric solution, checked for periodicity, asymmetry and the reversibility that maps one onto
// the other.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "newtop/orbit/spin_orbit.hpp"

namespace newtop {
namespace test_spin_orbit_shooting {
namespace {

constexpr double kPi = std::numbers::pi;
// Newton stops at max |F| ≤ 1e-11; with Φ − I of order one the start is then within ~1e-11 of the
// solution, and two solves from different starts agree to ~1e-10 (integrations at 1e-13).
constexpr double kSameStart = 1e-9;
// The periodicity over a full period, integrated again in other pieces: the brief's 1e-10.
constexpr double kPeriodic = 1e-10;

TEST(SpinOrbitShooting, RecoversTheSymmetricSolutionsFromNearbyStarts) {
  int checked = 0;
  for (const double e : {0.05, 0.2}) {
    for (const double k : {0.1, 0.3}) {
      const PitchProblem p = pitch_problem(e, k);
      for (const auto& [sp, sq] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{2, 1}}) {
        const SpinOrbitResonance r = resonance(sp, sq);
        for (const PeriodicSolution& s : periodic_solutions(p, r)) {
          if (s.stability == FloquetStability::parabolic) continue;  // Φ − I singular
          EXPECT_LT(s.symmetry_distance, kSymmetryTolerance);
          const auto shot = shoot_periodic(p, r, Vec2(s.theta0 + 0.01, s.dtheta0 - 0.01));
          ASSERT_TRUE(shot.has_value()) << e << " " << k << " " << sp << ":" << sq;
          EXPECT_NEAR(std::remainder(shot->theta0 - s.theta0, kPi), 0.0, kSameStart);
          EXPECT_NEAR(shot->dtheta0, s.dtheta0, kSameStart);
          EXPECT_LT(shot->residual, kPeriodic);
          EXPECT_LT(shot->symmetry_distance, kSymmetryTolerance);
          EXPECT_NEAR(shot->monodromy.trace(), s.monodromy.trace(),
                      1e-6 * std::max(1.0, std::abs(s.monodromy.trace())));
          ++checked;
        }
      }
    }
  }
  EXPECT_GE(checked, 16);
}

// e = 0.1, k = (B − A)/C = 0.87, the 1:2 resonance (N = 1, M = −1): the symmetric solution on
// θ(0) = π/2 has its trace rise through +2 between k = 0.87 (0.93) and 0.89 (3.12); below that
// point a pair of asymmetric, unstable solutions branches off it (a pitchfork of the reversible
// map). Found by 2-D shooting from (−1.459, −0.226): θ(0) = −1.459145, θ′(0) = −0.226071,
// trace 3.38, θ at ν = 0 and ν = π 0.112 rad from every multiple of π/2 (against ≤ 1e-9 for a
// symmetric one). Reversibility maps it onto θ̃(ν) = −θ(−ν), whose start is (−θ(0), θ′(0)): shooting
// from the mirrored guess must land there.
TEST(SpinOrbitShooting, FindsAnAsymmetricPairBesideAPitchfork) {
  const PitchProblem p = pitch_problem(0.1, 0.87);
  const SpinOrbitResonance r = resonance(1, 2);
  ASSERT_EQ(r.periods, 1);
  ASSERT_EQ(r.half_turns, -1);
  const auto a = shoot_periodic(p, r, Vec2(-1.459, -0.226));
  ASSERT_TRUE(a.has_value());
  EXPECT_NEAR(a->theta0, -1.459145, 1e-6);
  EXPECT_NEAR(a->dtheta0, -0.226071, 1e-6);
  EXPECT_LT(a->residual, kPeriodic);
  // Periodic again from a separate integration over the period in one piece.
  const Vec2 end = pitch_advance(p, Vec2(a->theta0, a->dtheta0), 0.0, 2 * kPi);
  EXPECT_LT((end - Vec2(a->theta0 - kPi, a->dtheta0)).norm(), kPeriodic);
  EXPECT_GT(a->symmetry_distance, 0.1);  // not symmetric: 1e8 times the symmetric tolerance
  EXPECT_EQ(a->stability, FloquetStability::unstable);
  const auto b = shoot_periodic(p, r, Vec2(1.459, -0.226));
  ASSERT_TRUE(b.has_value());
  EXPECT_NEAR(b->theta0, -a->theta0, kSameStart);
  EXPECT_NEAR(b->dtheta0, a->dtheta0, kSameStart);
  EXPECT_NEAR(b->monodromy.trace(), a->monodromy.trace(), 1e-6);
  // The pitchfork: the symmetric parent's trace crosses +2 between k = 0.87 and 0.89 (at
  // k ≈ 0.8803), and as k approaches it the pair, followed by continuation in k (each solve from
  // the previous solution), merges with the parent: its asymmetry shrinks (measured 0.112, 0.080,
  // 0.054, 0.032 at k = 0.87, 0.8725, 0.875, 0.8775) and its trace falls towards the parent's 2
  // (3.38, 3.20, 2.92, 2.54).
  auto parent_trace = [&](double k) {
    for (const PeriodicSolution& s : periodic_solutions(pitch_problem(0.1, k), r)) {
      if (std::abs(s.theta0 - kPi / 2) < 1e-12) return s.monodromy.trace();
    }
    return std::nan("");
  };
  EXPECT_LT(parent_trace(0.87), 2.0);
  EXPECT_GT(parent_trace(0.89), 2.0);
  PeriodicSolution last = *a;
  for (const double k : {0.8725, 0.875, 0.8775}) {
    const auto next = shoot_periodic(pitch_problem(0.1, k), r, Vec2(last.theta0, last.dtheta0));
    ASSERT_TRUE(next.has_value()) << k;
    EXPECT_LT(next->residual, kPeriodic) << k;
    EXPECT_LT(next->symmetry_distance, last.symmetry_distance) << k;
    EXPECT_GT(next->symmetry_distance, kSymmetryTolerance) << k;
    EXPECT_LT(next->monodromy.trace(), last.monodromy.trace()) << k;
    EXPECT_GT(next->monodromy.trace(), 2.0) << k;
    last = *next;
  }
  EXPECT_LT(last.symmetry_distance, 0.3 * a->symmetry_distance);
}

TEST(SpinOrbitShooting, GridFindsTheAsymmetricSolution) {
  const PitchProblem p = pitch_problem(0.1, 0.87);
  int asymmetric = 0;
  for (const PeriodicSolution& s : shoot_periodic_solutions(p, resonance(1, 2))) {
    EXPECT_LT(s.residual, kPeriodic);
    asymmetric += s.symmetry_distance > kSymmetryTolerance;
  }
  EXPECT_GE(asymmetric, 1);
}

}  // namespace
}  // namespace test_spin_orbit_shooting
}  // namespace newtop
