// Round-off of the splitting methods. Every sub-flow keeps γ·γ and m·γ exactly, so their errors are
// round-off alone. Each rotation adds a rounded increment to the state (sub_flows.hpp); the
// rounding errors are unbiased, so the Casimirs perform a random walk whose size grows like √N
// (Brouwer's law). A biased rotation (c² + s² ≠ 1 by an ulp, e.g. cos θ rounded before it is used)
// drifts like N instead. Checked on an ensemble of runs: the RMS error over the ensemble must grow
// with an exponent near ½, not 1, and stay below the bound derived for unbiased rounding.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/problems.hpp"

namespace newtop {
namespace test_round_off {
namespace {

using test::kEps;

constexpr int kRuns = 16;
constexpr int kCheckpoints = 4;  // N/64, N/16, N/4, N
constexpr int kSteps = 1 << 17;  // N
// The RMS over 16 runs estimates the spread to ~18%; over a factor 64 in N the fitted exponent
// is then within ~0.06 of the truth. A random walk gives ½, a drift 1.
constexpr double kExponentLow = 0.3, kExponentHigh = 0.7;

struct Profile {
  std::vector<double> geometric, area;  // RMS errors at the checkpoints
};

Profile ensemble(const SplittingStepper& prototype, const QuadraticModel& m) {
  std::vector<double> sg(kCheckpoints, 0.0), sa(kCheckpoints, 0.0);
  for (int run = 0; run < kRuns; ++run) {
    const double d = 0.01 * run;
    State x = state_from_omega(m.body, Vec3(0.5 + d, 1.1 - d, -0.4 + 0.5 * d),
                               Vec3(0.48, -0.6 + d, 0.64).normalized());
    const double g0 = geometric(x), a0 = area(x), scale = x.m.norm();
    SplittingStepper s = prototype;
    int next = 0;
    for (int i = 1; i <= kSteps; ++i) {
      s.step(m, x, 0.02);
      if (i == kSteps >> (2 * (kCheckpoints - 1 - next))) {
        sg[next] += std::pow(geometric(x) - g0, 2);
        sa[next] += std::pow((area(x) - a0) / scale, 2);
        ++next;
      }
    }
  }
  Profile p;
  for (int k = 0; k < kCheckpoints; ++k) {
    p.geometric.push_back(std::sqrt(sg[k] / kRuns));
    p.area.push_back(std::sqrt(sa[k] / kRuns));
  }
  return p;
}

// Least-squares slope of log(rms) against log(n) over the checkpoints (n ∝ 4^k).
double exponent(const std::vector<double>& rms) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int n = static_cast<int>(rms.size());
  for (int k = 0; k < n; ++k) {
    const double x = k * std::log(4.0), y = std::log(rms[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Each sub-flow rounds each component of γ it changes once, by at most ½ ulp ≤ ε/2 relative, so
// |δ(γ·γ)| ≤ ε|γ|² per sub-flow; a uniformly distributed rounding has σ ≤ ε/√3, and S sub-flows
// per step for N steps give RMS ≤ ε √(S N/3). The same holds for m·γ relative to |m||γ|.
double unbiased_bound(const SplittingStepper& s) {
  return kEps * std::sqrt(double(s.stages()) * kSteps / 3.0);
}

void expect_brouwer(const SplittingStepper& s, const char* what) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const Profile p = ensemble(s, m);
  for (const auto& [rms, name] : {std::pair{&p.geometric, "gamma.gamma"}, {&p.area, "m.gamma"}}) {
    ASSERT_GT(rms->front(), 0.0) << what << " " << name;
    const double e = exponent(*rms);
    EXPECT_GT(e, kExponentLow) << what << " " << name;
    EXPECT_LT(e, kExponentHigh) << what << " " << name;
    EXPECT_LT(rms->back(), unbiased_bound(s)) << what << " " << name;
  }
}

TEST(RoundOff, CasimirsFollowBrouwersLawAxesSplit) {
  const CompositionTable& t = composition_table("splitting2");
  SplitOrdering o = default_ordering(t);
  o.free_body = FreeBodySplit::axes;
  expect_brouwer(SplittingStepper(t, o), "axes");
}

TEST(RoundOff, CasimirsFollowBrouwersLawSpinSplit) {
  const CompositionTable& t = composition_table("splitting2");
  SplitOrdering o = default_ordering(t);
  o.free_body = FreeBodySplit::spin;
  expect_brouwer(SplittingStepper(t, o), "spin");
}

}  // namespace
}  // namespace test_round_off
}  // namespace newtop
