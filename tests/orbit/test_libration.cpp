// Beletsky's equation with its variational equation (docs/orbit.md §9): Liouville's formula for
// the determinant of the fundamental matrix, the variational matrix against finite differences
// of the flow, and the Floquet multipliers of the circular orbit's equilibria in closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "newtop/orbit/libration.hpp"
#include "newtop/orbit/spin_orbit.hpp"

namespace newtop {
namespace test_libration {
namespace {

constexpr double kPi = std::numbers::pi;

// Fehlberg 7(8) at 1e-13 per step over a few orbits of ~100 steps: the global error of Φ is
// ~1e-11 relative; 1e-10 leaves room, while a wrong trace of A (the 2e sin ν/(1 + e cos ν) term)
// changes det Φ at O(e) ≥ 1e-2.
constexpr double kLiouville = 1e-10;

TEST(Libration, DeterminantOfTheFundamentalMatrixIsLiouvillesRatio) {
  // d det Φ/dν = tr A det Φ, tr A = 2e sin ν/(1 + e cos ν) = −2 d/dν ln(1 + e cos ν), hence
  // det Φ(ν1, ν0) = ((1 + e cos ν0)/(1 + e cos ν1))², and 1 over whole orbits.
  for (const double e : {0.0, 0.1, 0.5}) {
    const PitchProblem p = pitch_problem(e, 0.26);
    for (const double nu1 : {1.3, 2 * kPi, 4 * kPi + 2.0}) {
      const double nu0 = 0.4;
      const PitchFlow f = pitch_flow(p, Vec2(0.3, 0.7), nu0, nu1);
      const double expected = liouville_determinant(e, nu0, nu1);
      EXPECT_NEAR(f.phi.determinant(), expected, kLiouville * expected) << e << ' ' << nu1;
    }
    const PitchFlow whole = pitch_flow(p, Vec2(-1.0, 0.2), 0.0, 4 * kPi);
    EXPECT_NEAR(whole.phi.determinant(), 1.0, kLiouville) << e;
  }
  EXPECT_NEAR(liouville_determinant(0.3, kPi, 0.0), std::pow(0.7 / 1.3, 2), 1e-15);
}

TEST(Libration, VariationalMatrixIsTheDerivativeOfTheFlow) {
  // Central differences with h = 1e-5: truncation h²|x‴|/6 ~ 1e-10 and the integrator's
  // tolerance-level noise 1e-13/h ~ 1e-8 (per unit |Φ|); 1e-6 |Φ| bounds both, while a wrong
  // entry of A (cos θ for cos 2θ, a lost factor) is wrong at O(1).
  constexpr double h = 1e-5, kFiniteDifference = 1e-6;
  const PitchProblem p = pitch_problem(0.2, 0.4);
  const Vec2 x0(0.5, -0.3);
  const double nu0 = 0.3, nu1 = 0.3 + 2 * kPi;
  const PitchFlow f = pitch_flow(p, x0, nu0, nu1);
  EXPECT_LT((f.x - pitch_advance(p, x0, nu0, nu1)).norm(), 1e-11);  // same trajectory
  for (int j = 0; j < 2; ++j) {
    const Vec2 dx = h * Vec2::Unit(j);
    const Vec2 column =
        (pitch_advance(p, x0 + dx, nu0, nu1) - pitch_advance(p, x0 - dx, nu0, nu1)) / (2 * h);
    EXPECT_LT((column - f.phi.col(j)).norm(), kFiniteDifference * std::max(1.0, f.phi.norm()))
        << "column " << j;
  }
}

TEST(Libration, CircularOrbitEquilibriaHaveClosedFormMultipliers) {
  // e = 0: θ″ + 3k sin θ cos θ = 0; about θ = 0, δθ″ = −3k δθ: multipliers exp(±2πi√(3k));
  // about θ = π/2, δθ″ = 3k δθ: exp(±2π√(3k)). Both found by the 1:1 shooting.
  constexpr double kMultiplier = 1e-9;  // relative; the integration is good to ~1e-11
  for (const double k : {0.01, 0.2, 0.6}) {
    const PitchProblem p = pitch_problem(0.0, k);
    const double w = 2 * kPi * std::sqrt(3 * k);
    int stable = 0, unstable = 0;
    for (const PeriodicSolution& s : periodic_solutions(p, resonance(1, 1))) {
      if (std::abs(s.dtheta0) > 1e-12) continue;  // the equilibria only
      const double big = std::max(std::abs(s.multipliers[0]), std::abs(s.multipliers[1]));
      if (s.theta0 == 0.0) {
        ++stable;
        EXPECT_EQ(s.stability, FloquetStability::stable);
        EXPECT_NEAR(s.multipliers[0].real(), std::cos(w), kMultiplier);
        EXPECT_NEAR(std::abs(s.multipliers[0].imag()), std::abs(std::sin(w)), kMultiplier);
        EXPECT_NEAR(std::abs(s.multipliers[0]), 1.0, kMultiplier);
      } else {
        ++unstable;
        EXPECT_EQ(s.stability, FloquetStability::unstable);
        EXPECT_NEAR(big, std::exp(w), kMultiplier * std::exp(w));
        EXPECT_NEAR(std::abs(s.multipliers[0] * s.multipliers[1]), 1.0, kMultiplier);
      }
    }
    EXPECT_EQ(stable, 1) << k;
    EXPECT_EQ(unstable, 1) << k;
  }
}

TEST(Libration, SectionOfTheCircularOrbitKeepsTheEnergy) {
  // e = 0 is a pendulum: E = ½θ′² + (3k/2) sin²θ is constant (π-periodic in θ, so the reduction
  // mod π keeps it), every start is regular. 500 orbits at ~1e-12 per orbit: 1e-9.
  constexpr double kEnergy = 1e-9;
  const double k = 0.26;
  const PitchProblem p = pitch_problem(0.0, k);
  auto energy = [k](const Vec2& x) {
    return 0.5 * x[1] * x[1] + 1.5 * k * std::sin(x[0]) * std::sin(x[0]);
  };
  for (const double spin : {0.3, 0.9, 1.7, 2.6}) {
    const Vec2 x0(0.2, dtheta_from_spin(0.0, spin));
    const SectionOrbit o = periapsis_section(p, x0[0], x0[1], 500);
    ASSERT_EQ(o.points.size(), 500u);
    for (const Vec2& x : o.points) {
      EXPECT_NEAR(energy(x), energy(x0), kEnergy);
      EXPECT_GE(x[0], -kPi / 2);
      EXPECT_LT(x[0], kPi / 2);
    }
    EXPECT_FALSE(o.chaotic) << spin << " exponent " << o.lyapunov;
  }
}

TEST(Libration, LyapunovExponentAtTheSaddleIsItsRate) {
  // From the e = 0 saddle θ = π/2 the tangent vector grows by exp(2π√(3k)) per orbit once it lies
  // along the unstable direction; over 5 orbits the initial misalignment costs
  // |ln cos(angle)|/5 < 0.1/5 of the ~5.5 per orbit: 1 % relative.
  const double k = 0.26;
  const SectionOrbit o = periapsis_section(pitch_problem(0.0, k), kPi / 2, 0.0, 5);
  EXPECT_NEAR(o.lyapunov, 2 * kPi * std::sqrt(3 * k), 0.01 * 2 * kPi * std::sqrt(3 * k));
  EXPECT_TRUE(o.chaotic);
}

TEST(Libration, HyperionLikeRotationIsChaoticBetweenTheResonances) {
  // Wisdom, Peale & Mignard (1984): Hyperion (e ≈ 0.1, ω0² = 3(B − A)/C ≈ 0.89) has a wide
  // chaotic zone between spin rates ~0.5 and ~2.5; the synchronous island and the fast rotation
  // above it are regular. Exponents there are ~0.3–0.9 per orbit against a threshold of 0.022.
  const PitchProblem p = pitch_problem(0.1, 0.89 / 3);
  EXPECT_TRUE(periapsis_section(p, 0.0, dtheta_from_spin(0.1, 1.75), 500).chaotic);
  EXPECT_TRUE(periapsis_section(p, kPi / 2, dtheta_from_spin(0.1, 1.25), 500).chaotic);
  EXPECT_FALSE(periapsis_section(p, 0.0, dtheta_from_spin(0.1, 3.5), 500).chaotic);
  EXPECT_NEAR(spin_from_dtheta(0.1, dtheta_from_spin(0.1, 1.75)), 1.75, 1e-15);
}

}  // namespace
}  // namespace test_libration
}  // namespace newtop
