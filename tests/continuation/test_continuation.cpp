// Pseudo-arclength continuation (docs/continuation.md): a family with a known fold, the 1:1 odd
// family of Beletsky's equation against independent computations of its flips and folds,
// Beletsky's threshold as a Krein collision, and the DeBra–Delp boundaries crossed by a family
// of relative equilibria.

#include <gtest/gtest.h>

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "newtop/analysis/rotation_family.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/orbit/orbit_families.hpp"

namespace newtop {
namespace test_continuation {
namespace {

constexpr double kPi = std::numbers::pi;
// The demand on every located event: 1e-10 in the parameter. The events are zeros of
// smooth test functions located by TOMS 748 to a few ulps of the chord; the test functions carry
// the corrector's residual (≤ 1e-11) and the integration's error (1e-13 per step), which move a
// simple zero by ~1e-12 / |slope| with slopes of order one here.
constexpr double kLocated = 1e-10;

std::vector<BifurcationEvent> of_type(const Family& f, BifurcationType t) {
  std::vector<BifurcationEvent> out;
  for (const BifurcationEvent& e : f.events)
    if (e.type == t) out.push_back(e);
  return out;
}

TEST(Continuation, FollowsACircleThroughItsFoldAndLocatesIt) {
  // u² + p² = 1 from (u, p) = (−√0.75, −0.5) towards p = 2: the family turns at p = 1 (u = 0) and
  // comes back to p = −0.5 on the other half.
  ContinuationProblem pr;
  pr.unknowns = 1;
  pr.residual = [](const Eigen::VectorXd& u, double p) {
    return Eigen::VectorXd::Constant(1, u[0] * u[0] + p * p - 1);
  };
  pr.evaluate = [](const Eigen::VectorXd&, double) { return FamilyPoint{}; };
  const Family f = continue_family(pr, Eigen::VectorXd::Constant(1, -0.8), -0.5, 2.0);
  EXPECT_EQ(f.end, "left_range");
  const auto folds = of_type(f, BifurcationType::fold);
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_NEAR(folds[0].value, 1.0, kLocated);
  EXPECT_NEAR(folds[0].point.values[0], 0.0, 1e-5);  // √(1 − p) magnifies p's error near the fold
  EXPECT_GT(f.points.back().values[0], 0.5);         // followed onto the other half
}

// --- the 1:1 odd family, independently -------------------------------------------------------

/// θ′(0) of the odd 1:1 solution (θ(0) = 0, θ(π) = 0) by Newton's method from `guess`.
double odd_solution(double k, double e, double guess) {
  const PitchProblem p = pitch_problem(e, k);
  double s = guess;
  for (int i = 0; i < 30; ++i) {
    const PitchFlow f = pitch_flow(p, Vec2(0.0, s), 0.0, kPi);
    const double step = f.x[0] / f.phi(0, 1);
    s -= step;
    if (std::abs(step) < 1e-14) break;
  }
  return s;
}

/// The monodromy's trace over one orbit, integrated in one piece.
double trace(double k, double e, double s) {
  return pitch_flow(pitch_problem(e, k), Vec2(0.0, s), 0.0, 2 * kPi).phi.trace();
}

TEST(ContinuationResonance, OddFamilyFlipsAgreeWithBisectionOnTheTrace) {
  int flips = 0;
  for (const double k : {0.2, 0.3, 0.9}) {
    const Family f = resonance_family(eccentricity_path(k), 0.0, 0.6, resonance(1, 1), 0.0, 0.0);
    for (const BifurcationEvent& ev : of_type(f, BifurcationType::flip)) {
      ++flips;
      // Bisection on |T| − 2 in e along shooting solutions, within ±1e-3 of the event.
      double lo = ev.value - 1e-3, hi = ev.value + 1e-3, s = ev.point.values[1];
      auto g = [&](double e) {
        s = odd_solution(k, e, s);
        return std::abs(trace(k, e, s)) - 2;
      };
      const bool lo_sign = g(lo) < 0;
      ASSERT_NE(lo_sign, g(hi) < 0) << "k = " << k << ": no sign change about " << ev.value;
      while (hi - lo > 1e-14) {
        const double mid = 0.5 * (lo + hi);
        ((g(mid) < 0) == lo_sign ? lo : hi) = mid;
      }
      EXPECT_NEAR(ev.value, 0.5 * (lo + hi), kLocated) << "k = " << k;
      EXPECT_NEAR(ev.point.tests[0], 0.0, 1e-9);  // T + 2 at the event
    }
  }
  EXPECT_GE(flips, 5);  // k = 0.2, 0.3: two each; k = 0.9: two before the fold
}

TEST(ContinuationResonance, OddFamilyFoldsAgreeWithNewtonOnTheFoldSystem) {
  int folds = 0;
  for (const double k : {0.6, 0.9}) {
    const Family f = resonance_family(eccentricity_path(k), 0.0, 0.6, resonance(1, 1), 0.0, 0.0);
    for (const BifurcationEvent& ev : of_type(f, BifurcationType::fold)) {
      ++folds;
      // θ(π) = 0 and ∂θ(π)/∂θ′(0) = 0 by Newton's method in (θ′(0), e), the Jacobian by central
      // differences, from a start 1e-3 away.
      auto G = [k](const Vec2& x) {
        const PitchFlow fl = pitch_flow(pitch_problem(x[1], k), Vec2(0.0, x[0]), 0.0, kPi);
        return Vec2(fl.x[0], fl.phi(0, 1));
      };
      Vec2 x(ev.point.values[1] + 1e-3, ev.value - 1e-3);
      for (int it = 0; it < 20; ++it) {
        Mat2 J;
        for (int i = 0; i < 2; ++i) {
          Vec2 a = x, b = x;
          a[i] += 1e-6;
          b[i] -= 1e-6;
          J.col(i) = (G(a) - G(b)) / 2e-6;
        }
        const Vec2 step = J.inverse() * G(x);
        x -= step;
        if (step.norm() < 1e-14) break;
      }
      EXPECT_NEAR(ev.value, x[1], kLocated) << "k = " << k;
      EXPECT_NEAR(ev.point.values[1], x[0], 1e-5);  // θ′(0) varies like √ near a fold
      for (const FamilyPoint& p : f.points) EXPECT_LE(p.parameter, ev.value + 1e-12);
    }
  }
  EXPECT_EQ(folds, 2);
}

TEST(ContinuationResonance, AsymmetricPitchforkOfTheHalfSynchronousResonance) {
  // e = 0.1, 1:2 (N = 1, M = −1), the symmetric solution on θ(0) = π/2 (docs/orbit.md §9):
  // continued in k, its branch point (c = Φ₁₀(π, 0) = 0, where T = 2 without a fold) against
  // bisection on T − 2 along the 1-D shooting solutions θ(π) = π/2 − π/2 = 0.
  const double e = 0.1;
  const Family f = resonance_family([e](double k) { return pitch_problem(e, k); }, 0.86, 0.89,
                                    resonance(1, 2), kPi / 2, -0.5);
  const auto bp = of_type(f, BifurcationType::branch_point);
  ASSERT_EQ(bp.size(), 1u);
  EXPECT_TRUE(of_type(f, BifurcationType::fold).empty());
  double s = bp[0].point.values[1];
  auto g = [&](double k) {
    const PitchProblem p = pitch_problem(e, k);
    for (int i = 0; i < 30; ++i) {
      const PitchFlow fl = pitch_flow(p, Vec2(kPi / 2, s), 0.0, kPi);
      const double step = fl.x[0] / fl.phi(0, 1);
      s -= step;
      if (std::abs(step) < 1e-14) break;
    }
    return pitch_flow(p, Vec2(kPi / 2, s), 0.0, 2 * kPi).phi.trace() - 2;
  };
  double lo = bp[0].value - 1e-3, hi = bp[0].value + 1e-3;
  const bool lo_sign = g(lo) < 0;
  ASSERT_NE(lo_sign, g(hi) < 0);
  while (hi - lo > 1e-14) {
    const double mid = 0.5 * (lo + hi);
    ((g(mid) < 0) == lo_sign ? lo : hi) = mid;
  }
  EXPECT_NEAR(bp[0].value, 0.5 * (lo + hi), kLocated);
  EXPECT_NEAR(bp[0].value, 0.8803, 1e-4);  // docs/orbit.md §9: k ≈ 0.8803
}

TEST(ContinuationResonance, FoldAndFlipCurvesMeetTheOneParameterFamilies) {
  // The plane (e, A) with B = C = 1, k = 1 − A. The odd family at k = 0.9 (A = 0.1): its first flip
  // and its fold continued in A to A = 0.05 (k = 0.95) and the fold also to A = 0.5 (k = 0.5); the
  // curves' last points (exactly at the range's end) against the one-parameter family at that k.
  const PitchPlanePath plane = pitch_plane_path(Vec3(0.1, 1.0, 1.0), 0.0, kEccentricityKey, 0);
  const Family f = resonance_family(eccentricity_path(0.9), 0.0, 0.6, resonance(1, 1), 0.0, 0.0);
  const auto flips = of_type(f, BifurcationType::flip);
  const auto folds = of_type(f, BifurcationType::fold);
  ASSERT_FALSE(flips.empty());
  ASSERT_EQ(folds.size(), 1u);
  struct Case {
    BifurcationEvent event;
    double a_end;
  };
  for (const Case& c : {Case{flips[0], 0.05}, Case{folds[0], 0.05}, Case{folds[0], 0.5}}) {
    const Family curve = resonance_boundary(plane, c.event, 0.1, c.a_end, resonance(1, 1), 0.0);
    ASSERT_EQ(curve.end, "range");
    const double k = 1 - c.a_end;
    const Family there =
        resonance_family(eccentricity_path(k), 0.0, 0.6, resonance(1, 1), 0.0, 0.0);
    const auto expected = of_type(there, c.event.type);
    ASSERT_FALSE(expected.empty()) << k;
    EXPECT_NEAR(curve.points.back().values[2], expected[0].value, kLocated)
        << to_string(c.event.type) << " at k = " << k;
  }
}

// --- rotations: Beletsky's threshold as a Krein collision ------------------------------------

TEST(ContinuationRotation, KreinCollisionIsBeletskysThreshold) {
  for (const Vec3& I : {Vec3(1.0, 1.5, 2.2), Vec3(2.0, 1.2, 2.6), Vec3(1.3, 2.9, 1.7)}) {
    for (const double lambda : {1.0, 3.0}) {
      const QuadraticModel m{Body::from_principal(I, 1.0, Vec3::Zero()), {0.0, lambda}};
      const int axis = largest_axis(m.body);
      const double omega_star = *beletsky_threshold(m.body, lambda, axis);
      const Family f = rotation_family(m, axis, 0.05, 4 * std::sqrt(lambda));
      const auto krein = of_type(f, BifurcationType::krein);
      ASSERT_EQ(krein.size(), 1u) << I.transpose() << " " << lambda;
      EXPECT_NEAR(krein[0].value, omega_star, kLocated);
      EXPECT_EQ(f.points.back().stability, "stable");
      for (const FamilyPoint& p : f.points) {
        if (std::abs(p.parameter - omega_star) > 1e-6) {
          EXPECT_EQ(p.stability, p.parameter > omega_star ? "stable" : "unstable") << p.parameter;
        }
      }
    }
  }
}

// --- relative equilibria: the DeBra–Delp boundaries ------------------------------------------

TEST(ContinuationEquilibrium, CrossesTheDebraDelpBoundariesWhereTheFormulasSay) {
  // Roll A = 1.5 (body x, along the velocity), pitch B = 1 (y, the orbit normal), yaw C (z, the
  // radius) from 0.9 to 1.6: k_R = (1 − C)/1.5, k_Y = −0.5/C. k_R = 0 at C = 1; the roll–yaw
  // boundary 1 + 3k_R + k_R k_Y = 4√(k_R k_Y) between; k_R = k_Y at C = 1.5.
  const Family f = equilibrium_family(Vec3(1.5, 1.0, 1.0), 2, 1, 2, 0.9, 1.6);
  EXPECT_EQ(f.end, "range");
  auto roll_yaw = [](double C) {
    const double kr = (1 - C) / 1.5, ky = -0.5 / C;
    return 1 + 3 * kr + kr * ky - 4 * std::sqrt(kr * ky);
  };
  std::uintmax_t iterations = 200;
  const auto r = boost::math::tools::toms748_solve(
      roll_yaw, 1.05, 1.3, boost::math::tools::eps_tolerance<double>(52), iterations);
  const double krein_at = 0.5 * (r.first + r.second);
  const auto branch = of_type(f, BifurcationType::branch_point);
  const auto krein = of_type(f, BifurcationType::krein);
  ASSERT_EQ(branch.size(), 2u);
  ASSERT_EQ(krein.size(), 1u);
  EXPECT_NEAR(branch[0].value, 1.0, kLocated);  // k_R = 0
  EXPECT_NEAR(krein[0].value, krein_at, kLocated);
  EXPECT_NEAR(branch[1].value, 1.5, kLocated);  // k_R = k_Y
  // Stable by gyroscopic coupling between k_R = 0 and the roll–yaw boundary (DeBra–Delp region).
  for (const FamilyPoint& p : f.points) {
    if (p.parameter > 1.0 + 1e-6 && p.parameter < krein_at - 1e-6) {
      EXPECT_EQ(p.stability, "gyroscopic") << p.parameter;
    }
    if (p.parameter > krein_at + 1e-6) {
      EXPECT_EQ(p.stability, "unstable") << p.parameter;
    }
  }
}

}  // namespace
}  // namespace test_continuation
}  // namespace newtop
