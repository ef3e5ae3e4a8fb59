// Branch switching (docs/continuation.md §2): from a flip of the odd 1:1 family onto the
// period-doubled family, and from the pitchfork of the 1:2 family onto the asymmetric pair, each
// branch's solutions checked by an integration independent of the shooting (Dormand–Prince 5(4),
// Boost.Odeint, written out here from Beletsky's equation).

#include <gtest/gtest.h>

#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>

#include "newtop/orbit/orbit_families.hpp"

namespace newtop {
namespace test_branch {
namespace {

constexpr double kPi = std::numbers::pi;

/// x(ν1) of (1 + e cos ν) θ″ − 2e sin ν (θ′ + 1) + 3k sin θ cos θ = 0 from x(0), by Dormand–Prince
/// 5(4) at absolute and relative tolerance 1e-12 (the library's shooting uses Fehlberg 7(8)).
Vec2 integrate(double e, double k, const Vec2& x0, double nu1) {
  namespace ode = boost::numeric::odeint;
  using S = std::array<double, 2>;
  S s{x0[0], x0[1]};
  auto rhs = [e, k](const S& x, S& dx, double nu) {
    dx[0] = x[1];
    dx[1] = (2 * e * std::sin(nu) * (x[1] + 1) - 3 * k * std::sin(x[0]) * std::cos(x[0])) /
            (1 + e * std::cos(nu));
  };
  ode::integrate_adaptive(ode::make_controlled<ode::runge_kutta_dopri5<S>>(1e-12, 1e-12), rhs, s,
                          0.0, nu1, 1e-3);
  return {s[0], s[1]};
}

std::vector<BifurcationEvent> of_type(const Family& f, BifurcationType t) {
  std::vector<BifurcationEvent> out;
  for (const BifurcationEvent& e : f.events)
    if (e.type == t) out.push_back(e);
  return out;
}

// The independent integration's error on these periods (4π, Dormand–Prince at 1e-12 per step,
// ~10³ steps): ~1e-10, grown along an unstable solution by its multiplier (measured ≤ 30 here);
// the shooting's own residual is ≤ 1e-11.
constexpr double kClosed = 1e-8;
// A solution of twice the period is not one of the period: |x(2π) − x(0)| of order the distance
// from the flip's solution; beyond the first steps off the flip it is above this.
constexpr double kNotClosed = 1e-3;

double max_multiplier(const FamilyPoint& p) {
  double m = 0.0;
  for (const auto& z : p.multipliers) m = std::max(m, std::abs(z));
  return m;
}

TEST(ContinuationBranch, PeriodDoubledFamilyStartsAtTheFlipAndHasTwiceThePeriod) {
  // The odd 1:1 family at k = 0.2 (θ(0) = 0), its first flip at e ≈ 0.1908; the period-doubled
  // family (N = 2, M = 0) continued in e within [0.05, 0.6]: it folds at e ≈ 0.1925 and comes
  // back towards e = 0 (where the equation is autonomous and its solutions a circle of phases).
  const double k = 0.2;
  const Family f = resonance_family(eccentricity_path(k), 0.0, 0.6, resonance(1, 1), 0.0, 0.0);
  const auto flips = of_type(f, BifurcationType::flip);
  ASSERT_FALSE(flips.empty());
  const BifurcationEvent& flip = flips[0];
  const Family b = resonance_branch(eccentricity_path(k), flip, 0.05, 0.6, resonance(1, 1), 0.0);
  ASSERT_GE(b.points.size(), 10u);
  EXPECT_EQ(b.end, "range");
  EXPECT_EQ(b.points.back().parameter, 0.05);
  // It meets the parent at the flip: its first point is the flip's solution, and the parent's
  // solution there is 2π-periodic (the doubled family's degenerate member).
  EXPECT_EQ(b.points[0].parameter, flip.value);
  EXPECT_EQ(b.points[0].values[1], flip.point.values[1]);
  const Vec2 star(0.0, flip.point.values[1]);
  EXPECT_LE((integrate(flip.value, k, star, 2 * kPi) - star).norm(), kClosed);
  // The second point, the switching step away, has e within O(step²) of the flip's (a pitchfork).
  const double step = ContinuationSettings{}.switch_step;
  EXPECT_LE(std::abs(b.points[1].parameter - flip.value), step * step * 10);
  double worst = 0.0, growth = 0.0;
  int doubled = 0;
  for (const FamilyPoint& p : b.points) {
    ASSERT_EQ(p.period, 4 * kPi);
    const Vec2 x0(p.values[0], p.values[1]);
    const double closed = (integrate(p.parameter, k, x0, 4 * kPi) - x0).norm();
    EXPECT_LE(closed, kClosed) << "e = " << p.parameter;
    worst = std::max(worst, closed);
    growth = std::max(growth, max_multiplier(p));
    if ((integrate(p.parameter, k, x0, 2 * kPi) - x0).norm() > kNotClosed) ++doubled;
  }
  EXPECT_GE(doubled, static_cast<int>(b.points.size()) - 3);  // all but the first steps
  std::printf("period-doubled: %zu points, max |x(4π) − x(0)| = %.2e (max |multiplier| %.1f)\n",
              b.points.size(), worst, growth);
  // Its own events: it folds back at e ≈ 0.1925, where its multipliers are +1 (trace 2).
  const auto folds = of_type(b, BifurcationType::fold);
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_GT(folds[0].value, flip.value);
  const auto& m = folds[0].point.multipliers;
  EXPECT_NEAR((m[0] + m[1]).real(), 2.0, 1e-6);
}

TEST(ContinuationBranch, AsymmetricBranchLeavesThePitchforkWithoutTheSymmetry) {
  // e = 0.1, 1:2 on θ(0) = π/2: the pitchfork at k ≈ 0.88024 (docs/orbit.md §9); one of the
  // asymmetric pair (θ(0) < π/2; the other is its mirror image θ → π − θ) continued within
  // [0.86, 0.89].
  const double e = 0.1;
  const PitchPath path = [e](double kk) { return pitch_problem(e, kk); };
  const Family g = resonance_family(path, 0.86, 0.89, resonance(1, 2), kPi / 2, -0.5);
  const auto bp = of_type(g, BifurcationType::branch_point);
  ASSERT_EQ(bp.size(), 1u);
  const Family a = resonance_branch(path, bp[0], 0.86, 0.89, resonance(1, 2), kPi / 2);
  ASSERT_GE(a.points.size(), 10u);
  EXPECT_EQ(a.end, "range");
  EXPECT_EQ(a.points[0].parameter, bp[0].value);  // meets the symmetric family at its pitchfork
  EXPECT_EQ(a.points[0].values[0], kPi / 2);
  const double step = ContinuationSettings{}.switch_step;
  EXPECT_LE(std::abs(a.points[1].values[0] - kPi / 2), 2 * step);
  EXPECT_LE(std::abs(a.points[1].parameter - bp[0].value), step * step * 10);
  double worst = 0.0;
  int asymmetric = 0;
  for (const FamilyPoint& p : a.points) {
    const Vec2 x0(p.values[0], p.values[1]);
    // 1:2: θ(2π) = θ(0) − π.
    const double closed = (integrate(e, p.parameter, x0, 2 * kPi) - x0 - Vec2(-kPi, 0)).norm();
    EXPECT_LE(closed, kClosed) << "k = " << p.parameter;
    worst = std::max(worst, closed);
    // Not symmetric: neither θ(0) nor θ(π) on a reversibility line (a multiple of π/2).
    const double th_pi = integrate(e, p.parameter, x0, kPi)[0];
    auto off_line = [](double th) { return std::abs(th - kPi / 2 * std::round(th / (kPi / 2))); };
    if (std::min(off_line(x0[0]), off_line(th_pi)) > kNotClosed) ++asymmetric;
  }
  EXPECT_GE(asymmetric, static_cast<int>(a.points.size()) - 3);
  EXPECT_EQ(a.points.back().parameter, 0.86);  // ends exactly at the range's end
  std::printf("asymmetric: %zu points, max |x(2π) − x(0) − (−π, 0)| = %.2e\n", a.points.size(),
              worst);
}

}  // namespace
}  // namespace test_branch
}  // namespace newtop
