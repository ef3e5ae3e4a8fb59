// The ensemble stepper against the scalar splitting stepper (its guarantee: bit-identical results
// for every point, every table and ordering, every instruction set), against itself under other
// groupings of the points into lanes, and against the Casimirs |γ| = 1 and m·γ over a long run.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "newtop/integrate/ensemble.hpp"
#include "support/ensemble.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_ensemble {
namespace {

using test::kEps;

using test::available_paths;
using test::kScalarMayContract;

// Random states of the generic body: ω in a box of half-width w_max, γ uniform on the sphere.
// With h w_max ≥ 0.1 some rotation angles leave both Taylor series (θ² > 1e-2) and use the
// library's sin; with h w_max ≪ 0.01 all stay in the short series.
std::vector<State> random_states(const QuadraticModel& model, std::size_t n, double w_max,
                                 unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<State> x;
  for (std::size_t i = 0; i < n; ++i) x.push_back(test::random_start(model.body, w_max, rng));
  return x;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Index of the first component whose bits differ, or -1.
int first_difference(const State& a, const State& b) {
  for (int i = 0; i < 3; ++i) {
    if (!same_bits(a.m[i], b.m[i])) return i;
    if (!same_bits(a.gamma[i], b.gamma[i])) return 3 + i;
  }
  return -1;
}

struct Case {
  std::string table;
  SplitOrdering ordering;
  std::string what;
};

// Every table, with the free body split into axes and into the spin (both kick placements) for
// the compositions, and the exact flow (its default) for the near-integrable ones (which needs
// k = 0).
std::vector<Case> every_method(bool gyrostat) {
  std::vector<Case> c;
  for (const CompositionTable& t : composition_tables()) {
    for (FreeBodySplit split : {FreeBodySplit::axes, FreeBodySplit::spin}) {
      for (bool outside : {false, true}) {
        SplitOrdering o = default_ordering(t);
        o.free_body = split;
        o.kick_outside = outside;
        o.axes = outside ? std::array<int, 3>{1, 0, 2} : std::array<int, 3>{2, 0, 1};  // odd, even
        c.push_back({std::string(t.name), o,
                     std::string(t.name) + (split == FreeBodySplit::axes ? " axes" : " spin") +
                         (outside ? " kick outside" : " kick inside")});
      }
    }
    c.push_back({std::string(t.name), default_ordering(t), std::string(t.name) + " default"});
  }
  for (const CompositionTable& t : near_integrable_tables()) {
    if (gyrostat) break;
    c.push_back({std::string(t.name), default_ordering(t), std::string(t.name) + " exact"});
  }
  return c;
}

constexpr int kAgreementSteps = 40;

void expect_scalar_agreement(const QuadraticModel& model, double h, double w_max) {
  if (kScalarMayContract) GTEST_SKIP() << "the scalar stepper may use fused multiply-adds here";
  const std::vector<State> x0 = random_states(model, 37, w_max, 12345);  // 37: a partial block
  for (const Case& c : every_method(model.body.gyrostat() != Vec3::Zero())) {
    const CompositionTable& table = composition_table(c.table);
    std::vector<State> ref = x0;
    for (State& x : ref) {
      SplittingStepper s(table, c.ordering);
      for (int i = 0; i < kAgreementSteps; ++i) s.step(model, x, h);
    }
    for (SimdPath path : available_paths()) {
      EnsembleStepper e(table, c.ordering, path);
      EnsembleState xs(x0);
      e.advance(model, xs, h, kAgreementSteps);
      for (std::size_t i = 0; i < x0.size(); ++i) {
        const int d = first_difference(xs[i], ref[i]);
        ASSERT_EQ(d, -1) << c.what << ", " << simd_path_name(path) << ", point " << i
                         << ", component " << d << ": ensemble " << xs[i].m.transpose() << " "
                         << xs[i].gamma.transpose() << " scalar " << ref[i].m.transpose() << " "
                         << ref[i].gamma.transpose();
      }
    }
  }
}

// Gyrostat with k on every axis, r0 off every axis, λ > 0: every term of the kick and rotations.
QuadraticModel gyrostat_model() { return test::generic_model(Vec3(0.1, -0.2, 0.05)); }

TEST(Ensemble, BitIdenticalToScalarStepperShortSeries) {
  expect_scalar_agreement(gyrostat_model(), 1e-3, 2.0);  // θ ≤ 4e-3: the vector series only
}

TEST(Ensemble, BitIdenticalToScalarStepperWhereLanesLeaveTheSeries) {
  // θ up to ~0.6: lanes in the short series, the long series and the library's sin side by side.
  expect_scalar_agreement(gyrostat_model(), 0.1, 3.0);
}

TEST(Ensemble, BitIdenticalToScalarStepperWithoutGyrostat) {
  expect_scalar_agreement(test::generic_model(), 0.01, 2.0);
}

// A point's result depends neither on its lane nor on the ensemble's size nor on the path: the
// same points reversed, shifted by one, alone, and in ensembles of sizes around the blocks.
TEST(Ensemble, IndependentOfLanesAndGrouping) {
  const QuadraticModel model = gyrostat_model();
  const double h = 0.05, w_max = 2.5;  // some lanes leave the series, most do not
  const std::vector<State> x0 = random_states(model, 150, w_max, 777);  // > 2 blocks of any path
  const CompositionTable& table = composition_table("splitting6");
  EnsembleStepper base(table, SimdPath::portable);
  EnsembleState ref(x0);
  base.advance(model, ref, h, 25);
  for (SimdPath path : available_paths()) {
    EnsembleStepper e(table, path);
    const std::string p(simd_path_name(path));
    EnsembleState rev;
    for (std::size_t i = x0.size(); i-- > 0;) rev.push_back(x0[i]);
    e.advance(model, rev, h, 25);
    for (std::size_t i = 0; i < x0.size(); ++i) {
      ASSERT_EQ(first_difference(rev[x0.size() - 1 - i], ref[i]), -1) << p << " reversed " << i;
    }
    for (std::size_t n : {std::size_t(1), std::size_t(2), std::size_t(7), simd_block(path) - 1,
                          simd_block(path), simd_block(path) + 1}) {
      for (std::size_t first : {std::size_t(0), std::size_t(5)}) {
        ASSERT_LE(first + n, x0.size());
        EnsembleState part(std::span<const State>(x0).subspan(first, n));
        e.advance(model, part, h, 25);
        for (std::size_t i = 0; i < n; ++i) {
          ASSERT_EQ(first_difference(part[i], ref[first + i]), -1)
              << p << " size " << n << " from " << first << " point " << i;
        }
      }
    }
  }
}

// Steps taken in several calls equal the steps taken in one.
TEST(Ensemble, StepsInSeveralCallsEqualOneCall) {
  const QuadraticModel model = gyrostat_model();
  const std::vector<State> x0 = random_states(model, 19, 2.0, 99);
  EnsembleStepper e(composition_table("splitting4"));
  EnsembleState one(x0), three(x0);
  e.advance(model, one, 0.01, 30);
  for (int k = 0; k < 3; ++k) e.advance(model, three, 0.01, 10);
  for (std::size_t i = 0; i < x0.size(); ++i) EXPECT_EQ(first_difference(one[i], three[i]), -1);
}

// Every sub-flow keeps γ·γ and m·γ exactly; each rounds each changed component once, so over N
// steps of S sub-flows the Casimirs random-walk with RMS ≤ ε √(S N/3) (test_round_off.cpp derives
// it), relative to |γ|² and |m||γ|. Checked over 64 points for 2¹⁶ steps of splitting6 (axes
// split), the RMS against that bound and every point against 5 times it (a Gaussian walk passes 5σ
// with probability 6e-7 per point).
TEST(Ensemble, CasimirsToRoundOffOverALongRun) {
  const QuadraticModel model = gyrostat_model();
  const std::vector<State> x0 = random_states(model, 64, 1.5, 4242);
  const CompositionTable& table = composition_table("splitting6");
  const int steps = 1 << 16;
  EnsembleStepper e(table);
  EnsembleState x(x0);
  e.advance(model, x, 0.02, steps);
  const double stages = double(SplittingStepper(table).stages());
  const double bound = kEps * std::sqrt(stages * steps / 3.0);
  double sg = 0, sa = 0, worst_g = 0, worst_a = 0;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    const State xi = x[i];
    ASSERT_TRUE(xi.m.allFinite() && xi.gamma.allFinite()) << "point " << i;
    const double dg = geometric(xi) - geometric(x0[i]);
    const double da = (area(xi) - area(x0[i])) / x0[i].m.norm();
    sg += dg * dg, sa += da * da;
    worst_g = std::max(worst_g, std::abs(dg)), worst_a = std::max(worst_a, std::abs(da));
    // The points did move: the check is not on frozen states.
    ASSERT_GT((xi.gamma - x0[i].gamma).norm(), 1e-3) << "point " << i;
  }
  const double n = double(x0.size());
  EXPECT_LT(std::sqrt(sg / n), bound);
  EXPECT_LT(std::sqrt(sa / n), bound);
  EXPECT_LT(worst_g, 5 * bound);
  EXPECT_LT(worst_a, 5 * bound);
}

TEST(Ensemble, RefusesAPathThisCpuLacks) {
  for (SimdPath path : {SimdPath::avx2, SimdPath::avx512}) {
    if (simd_path_available(path)) continue;
    EXPECT_THROW(EnsembleStepper(composition_table("splitting2"), path), InputError);
  }
  EXPECT_TRUE(simd_path_available(SimdPath::portable));
  EXPECT_TRUE(simd_path_available(best_simd_path()));
}

}  // namespace
}  // namespace test_ensemble
}  // namespace newtop
