// Spin–orbit resonances (docs/orbit.md §9): the shooting's periodic solutions against the small-e
// series of the synchronous solution, the Goldreich–Peale strengths against their published
// series, the libration frequency (the averaged half-width) against Goldreich & Peale's averaged
// pendulum, and the periapsis map's fixed points.

#include <gtest/gtest.h>

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "newtop/orbit/spin_orbit.hpp"

namespace newtop {
namespace test_spin_orbit {
namespace {

constexpr double kPi = std::numbers::pi;

/// The periodic solution on the line θ(0) = θ0 nearest θ′(0) = guess.
PeriodicSolution solution_on(const PitchProblem& p, const SpinOrbitResonance& r, double theta0) {
  const auto all = periodic_solutions(p, r);
  const PeriodicSolution* best = nullptr;
  for (const auto& s : all) {
    if (s.theta0 == theta0 && (!best || s.max_deviation < best->max_deviation)) best = &s;
  }
  if (!best) throw std::runtime_error("no periodic solution on the line");
  return *best;
}

TEST(SpinOrbit, ResonancesReduceToPeriodAndHalfTurns) {
  // θ(ν + 2πN) = θ(ν) + Mπ with M/(2N) = (p − q)/q.
  auto check = [](int p, int q, int n, int m) {
    const SpinOrbitResonance r = resonance(p, q);
    EXPECT_EQ(r.periods, n) << p << ':' << q;
    EXPECT_EQ(r.half_turns, m) << p << ':' << q;
  };
  check(1, 1, 1, 0);
  check(3, 2, 1, 1);
  check(2, 1, 1, 2);
  check(1, 2, 1, -1);
  check(5, 2, 1, 3);
  check(4, 3, 3, 2);
  check(2, 2, 1, 0);
  EXPECT_THROW(resonance(1, 0), InputError);
  EXPECT_THROW(resonance(-1, 2), InputError);
}

TEST(SpinOrbit, SynchronousSolutionFollowsItsSeriesInE) {
  // To first order in e, θ″ + 3kθ = 2e sin ν: θ = 2e sin ν/(3k − 1), θ′(0) = 2e/(3k − 1). The
  // deviation from the e = 0 solution θ ≡ 0 then halves with e: the ratio is 2(1 + O(e)); at
  // e = 0.02 the O(e²) term is ~c e with c ≲ 2 here, so 2 ± 0.08. The first-order series' error is
  // O(e²): halving e divides it by ~4 (3 to 5 allows the O(e³) term).
  const double k = 0.1;
  const PitchProblem p1 = pitch_problem(0.02, k), p2 = pitch_problem(0.01, k);
  const PeriodicSolution s1 = solution_on(p1, resonance(1, 1), 0.0);
  const PeriodicSolution s2 = solution_on(p2, resonance(1, 1), 0.0);
  EXPECT_EQ(s1.stability, FloquetStability::stable);
  EXPECT_LT(s1.residual, 1e-10);
  EXPECT_NEAR(s1.max_deviation / s2.max_deviation, 2.0, 0.08);
  const double series1 = 2 * 0.02 / (3 * k - 1), series2 = 2 * 0.01 / (3 * k - 1);
  EXPECT_NEAR(s1.max_deviation, std::abs(series1), 0.05 * std::abs(series1));
  const double ratio = std::abs(s1.dtheta0 - series1) / std::abs(s2.dtheta0 - series2);
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.0);
}

TEST(SpinOrbit, StrengthsMatchGoldreichPealesSeries) {
  // Goldreich & Peale (1966), AJ 71, 425, Table I (Cayley's expansions of (a/R)³ e^{2i(ν − pM)}):
  // H(1/2) = −e/2 + e³/16, H(1) = 1 − 5e²/2 + 13e⁴/16, H(3/2) = 7e/2 − 123e³/16,
  // H(2) = 17e²/2 − 115e⁴/6, H(5/2) = 845e³/48. At e = 0.01 the omitted terms are below
  // 3e² ≈ 3e-4 of the leading one (the largest, H(5/2)'s −32525e⁵/768, is 2.4e² of it): 1e-3.
  constexpr double kSeries = 1e-3;
  const double e = 0.01, e2 = e * e, e3 = e2 * e, e4 = e2 * e2;
  const double published[][2] = {{0.5, -e / 2 + e3 / 16},
                                 {1.0, 1 - 2.5 * e2 + 13 * e4 / 16},
                                 {1.5, 3.5 * e - 123 * e3 / 16},
                                 {2.0, 8.5 * e2 - 115 * e4 / 6},
                                 {2.5, 845 * e3 / 48}};
  for (const auto& [ratio, h] : published) {
    EXPECT_NEAR(resonance_strength(ratio, e), h, kSeries * std::abs(h)) << ratio;
  }
  EXPECT_NEAR(resonance_strength(1.0, 0.0), 1.0, 1e-14);
  EXPECT_NEAR(resonance_strength(1.5, 0.0), 0.0, 1e-14);
}

TEST(SpinOrbit, LibrationFrequencyIsTheAveragedHalfWidth) {
  // Averaged over the orbit (Goldreich & Peale 1966; Murray & Dermott 1999, §5.4), γ = θ_inertial
  // − pM obeys γ̈ + (3k/2) n² H(p, e) sin 2γ = 0: the centre is γ = 0 (θ(0) = 0 at periapsis) when
  // H > 0 and γ = π/2 when H < 0, the separatrix's half-width in θ̇/n is √(3k|H|), and so is the
  // small-libration frequency. The Floquet multipliers exp(±iα) of the stable periodic solution
  // give α = 2πN · frequency. The averaging's error is O(k) relative: with k = 1e-3, 3k.
  const double k = 1e-3, e = 0.1;
  const PitchProblem p = pitch_problem(e, k);
  for (const auto& [pp, qq] : {std::pair{1, 1}, {3, 2}, {2, 1}, {1, 2}, {5, 2}}) {
    const SpinOrbitResonance r = resonance(pp, qq);
    const double ratio = double(pp) / qq;
    const double h = resonance_strength(ratio, e);
    const PeriodicSolution centre = solution_on(p, r, h > 0 ? 0.0 : kPi / 2);
    const PeriodicSolution saddle = solution_on(p, r, h > 0 ? kPi / 2 : 0.0);
    EXPECT_EQ(centre.stability, FloquetStability::stable) << ratio;
    EXPECT_EQ(saddle.stability, FloquetStability::unstable) << ratio;
    const double alpha = std::acos(centre.monodromy.trace() / 2);
    const double frequency = alpha / (2 * kPi * r.periods);
    EXPECT_NEAR(frequency, averaged_half_width(p, ratio), 3 * k * averaged_half_width(p, ratio))
        << ratio;
  }
}

TEST(SpinOrbit, ResonanceWidthIsGoldreichPealesAveragedWidth) {
  // The separatrix measured on the periapsis map (the last start that still librates about the
  // centre over 400 orbits, above and below it) against Goldreich & Peale's averaged half-width
  // √(3k|H|) in θ̇/n. The averaging's error is O(k) relative: measured 3.2e-3, 1.3e-2 and 8e-4
  // at k = 1e-3, 4e-3, 2.5e-4 for 3:2 (≈ 3.3k); bound 10k = 1 %.
  const double k = 1e-3, e = 0.1;
  const PitchProblem p = pitch_problem(e, k);
  for (const auto& [pp, qq] : {std::pair{1, 1}, {3, 2}, {2, 1}, {1, 2}}) {
    const double ratio = double(pp) / qq;
    const PeriodicSolution centre =
        solution_on(p, resonance(pp, qq), resonance_strength(ratio, e) > 0 ? 0.0 : kPi / 2);
    const double width = averaged_half_width(p, ratio);
    EXPECT_NEAR(measured_half_width(p, centre, 400), width, 10 * k * width) << ratio;
  }
}

TEST(SpinOrbit, SynchronousSolutionLosesStabilityInTheFirstMathieuTongue) {
  // About the synchronous solution (θ = O(e), cos 2θ = 1 + O(e²)) the variational equation is
  // (1 + e cos ν) δ″ − 2e sin ν δ′ + ω²δ = 0, ω² = 3k. At ω = 1/2 the trial 4π-periodic
  // δ = a cos(ν/2) + b sin(ν/2) leaves a(ω² − 1/4 + 3e/8) cos(ν/2) + b(ω² − 1/4 − 3e/8) sin(ν/2)
  // (plus 3ν/2 harmonics): the first tongue, where the multipliers are real and negative
  // (trace < −2), is 3k ∈ (1/4 − 3e/8, 1/4 + 3e/8) + O(e²), i.e. k = 1/12 ∓ e/8. Its edges are
  // found where trace + 2 changes sign; their O(e²) error quarters as e halves (measured 2.4e-4 and
  // 2.7e-4 at e = 0.02, 6e-5 at e = 0.01): bound 2e² at e = 0.02, ratio in (3, 5).
  auto trace_plus_2 = [](double e, double k) {
    for (const auto& s : periodic_solutions(pitch_problem(e, k), resonance(1, 1))) {
      if (s.theta0 == 0.0 && std::abs(s.dtheta0) < 0.5) return s.monodromy.trace() + 2;
    }
    throw std::runtime_error("no synchronous solution");
  };
  auto edges = [&](double e) {
    const double centre = 1.0 / 12, reach = e / 4;
    EXPECT_LT(trace_plus_2(e, centre), 0.0);  // inside: unstable by period doubling
    std::uintmax_t n = 100;
    const auto f = [&](double k) { return trace_plus_2(e, k); };
    const auto lo = boost::math::tools::toms748_solve(
        f, centre - reach, centre, boost::math::tools::eps_tolerance<double>(40), n);
    n = 100;
    const auto hi = boost::math::tools::toms748_solve(
        f, centre, centre + reach, boost::math::tools::eps_tolerance<double>(40), n);
    return std::pair{0.5 * (lo.first + lo.second) - (centre - e / 8),
                     0.5 * (hi.first + hi.second) - (centre + e / 8)};
  };
  const auto err1 = edges(0.02), err2 = edges(0.01);
  EXPECT_LT(std::abs(err1.first), 2 * 0.02 * 0.02);
  EXPECT_LT(std::abs(err1.second), 2 * 0.02 * 0.02);
  for (const double ratio : {err1.first / err2.first, err1.second / err2.second}) {
    EXPECT_GT(ratio, 3.0);
    EXPECT_LT(ratio, 5.0);
  }
}

TEST(SpinOrbit, PeriodicSolutionIsAFixedPointOfThePeriapsisMap) {
  // N = 1: the section of the periodic start returns to (θ0 + Mπ mod π, θ′0) every orbit;
  // 20 orbits of the stable (elliptic) solution at ~1e-12 per orbit: 1e-9.
  const PitchProblem p = pitch_problem(0.1, 0.05);
  const PeriodicSolution s = solution_on(p, resonance(3, 2), 0.0);
  ASSERT_EQ(s.stability, FloquetStability::stable);
  const SectionOrbit o = periapsis_section(p, s.theta0, s.dtheta0, 20);
  for (const Vec2& x : o.points) {
    EXPECT_NEAR(x[0], 0.0, 1e-9);
    EXPECT_NEAR(x[1], s.dtheta0, 1e-9);
  }
  EXPECT_FALSE(o.chaotic);
}

}  // namespace
}  // namespace test_spin_orbit
}  // namespace newtop
