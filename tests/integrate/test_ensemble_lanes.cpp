// The ensemble stepper with a model per point (EnsembleModels): every point against the scalar
// splitting stepper on its own model, bit for bit, for random bodies and fields whose split frames
// differ (axes sorted by moment in every order, ties, a gyrostat on the reference axis or not);
// against itself under other groupings; and against the one-model stepper when the models agree.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "newtop/integrate/ensemble.hpp"
#include "support/ensemble.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_ensemble_lanes {
namespace {

using test::available_paths;
using test::kScalarMayContract;

bool same_state(const State& a, const State& b) {
  for (int i = 0; i < 3; ++i) {
    if (std::bit_cast<std::uint64_t>(a.m[i]) != std::bit_cast<std::uint64_t>(b.m[i]) ||
        std::bit_cast<std::uint64_t>(a.gamma[i]) != std::bit_cast<std::uint64_t>(b.gamma[i])) {
      return false;
    }
  }
  return true;
}

std::vector<State> random_states(const std::vector<QuadraticModel>& models, double w_max,
                                 unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<State> x;
  for (const QuadraticModel& m : models) x.push_back(test::random_start(m.body, w_max, rng));
  return x;
}

struct Case {
  std::string table;
  SplitOrdering ordering;
};

// Every composition table with the axes and the spin split, both kick placements, by moment and
// in body order; every near-integrable table with the exact flow (k = 0 only).
std::vector<Case> every_method(bool gyrostat) {
  std::vector<Case> c;
  for (const CompositionTable& t : composition_tables()) {
    for (FreeBodySplit split : {FreeBodySplit::axes, FreeBodySplit::spin}) {
      for (bool outside : {false, true}) {
        SplitOrdering o = default_ordering(t);
        o.free_body = split;
        o.kick_outside = outside;
        o.by_moment = !outside;
        o.axes = outside ? std::array<int, 3>{1, 0, 2} : std::array<int, 3>{2, 0, 1};
        c.push_back({std::string(t.name), o});
      }
    }
  }
  if (!gyrostat) {
    for (const CompositionTable& t : near_integrable_tables()) {
      c.push_back({std::string(t.name), default_ordering(t)});
    }
  }
  return c;
}

std::string describe(const Case& c) {
  const char* split = c.ordering.free_body == FreeBodySplit::axes   ? "axes"
                      : c.ordering.free_body == FreeBodySplit::spin ? "spin"
                                                                    : "exact";
  return c.table + " " + split + (c.ordering.by_moment ? " by moment" : " body order");
}

constexpr int kSteps = 30;

// Each point of the ensemble equals the scalar stepper's run on its own model.
void expect_scalar_agreement(bool gyrostat, double h, double w_max) {
  if (kScalarMayContract) GTEST_SKIP() << "the scalar stepper may use fused multiply-adds here";
  const std::vector<QuadraticModel> models = test::random_models(53, gyrostat, 2024);
  const std::vector<State> x0 = random_states(models, w_max, 31);
  for (const Case& c : every_method(gyrostat)) {
    const CompositionTable& table = composition_table(c.table);
    std::vector<State> ref = x0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      SplittingStepper s(table, c.ordering);
      for (int k = 0; k < kSteps; ++k) s.step(models[i], ref[i], h);
    }
    const EnsembleModels lanes(models, c.ordering);
    // By moment the working axes follow the inertia; the spin split's form follows k_r.
    if (c.ordering.by_moment && c.ordering.free_body != FreeBodySplit::exact) {
      ASSERT_GT(lanes.groups(), 1u) << describe(c) << ": expected several working frames";
    }
    for (SimdPath path : available_paths()) {
      EnsembleStepper e(table, c.ordering, path);
      EnsembleState xs(x0);
      e.advance(lanes, xs, h, kSteps);
      for (std::size_t i = 0; i < x0.size(); ++i) {
        ASSERT_TRUE(same_state(xs[i], ref[i]))
            << describe(c) << ", " << simd_path_name(path) << ", point " << i << ": ensemble "
            << xs[i].m.transpose() << " " << xs[i].gamma.transpose() << " scalar "
            << ref[i].m.transpose() << " " << ref[i].gamma.transpose();
      }
    }
  }
}

TEST(EnsembleLanes, BitIdenticalToScalarStepperOnEachModel) {
  expect_scalar_agreement(true, 1e-3, 2.0);  // the short series only
}

TEST(EnsembleLanes, BitIdenticalToScalarStepperWhereLanesLeaveTheSeries) {
  expect_scalar_agreement(true, 0.1, 3.0);
}

TEST(EnsembleLanes, BitIdenticalToScalarStepperWithoutGyrostat) {
  expect_scalar_agreement(false, 0.02, 2.0);
}

// A point's result depends only on its state and model: the same points reversed, each alone, and
// every third one, against the whole ensemble, on every path.
TEST(EnsembleLanes, IndependentOfGrouping) {
  const std::vector<QuadraticModel> models = test::random_models(61, true, 99);
  const std::vector<State> x0 = random_states(models, 2.5, 5);
  const CompositionTable& table = composition_table("splitting6");
  const SplitOrdering o = default_ordering(table);
  const double h = 0.05;
  EnsembleState ref(x0);
  EnsembleStepper(table, o, SimdPath::portable).advance(EnsembleModels(models, o), ref, h, 20);
  for (SimdPath path : available_paths()) {
    EnsembleStepper e(table, o, path);
    const std::string p(simd_path_name(path));
    std::vector<QuadraticModel> rm(models.rbegin(), models.rend());
    std::vector<State> rx(x0.rbegin(), x0.rend());
    EnsembleState rev(rx);
    e.advance(EnsembleModels(rm, o), rev, h, 20);
    for (std::size_t i = 0; i < x0.size(); ++i) {
      ASSERT_TRUE(same_state(rev[x0.size() - 1 - i], ref[i])) << p << " reversed " << i;
      EnsembleState one(std::span<const State>(x0).subspan(i, 1));
      e.advance(EnsembleModels(std::span<const QuadraticModel>(models).subspan(i, 1), o), one, h,
                20);
      ASSERT_TRUE(same_state(one[0], ref[i])) << p << " alone " << i;
    }
    std::vector<QuadraticModel> tm;
    std::vector<State> tx;
    for (std::size_t i = 0; i < x0.size(); i += 3) tm.push_back(models[i]), tx.push_back(x0[i]);
    EnsembleState third(tx);
    e.advance(EnsembleModels(tm, o), third, h, 20);
    for (std::size_t i = 0; i < tx.size(); ++i) {
      ASSERT_TRUE(same_state(third[i], ref[3 * i])) << p << " every third " << i;
    }
  }
}

// With every point on one model, the per-lane ensemble equals the one-model ensemble.
TEST(EnsembleLanes, OneModelPerLaneEqualsTheSharedModel) {
  const QuadraticModel model = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const std::vector<QuadraticModel> models(40, model);
  const std::vector<State> x0 = random_states(models, 2.5, 8);
  for (const char* name : {"splitting2", "splitting6"}) {
    const CompositionTable& table = composition_table(name);
    EnsembleStepper e(table);
    EnsembleState shared(x0), lanes(x0);
    e.advance(model, shared, 0.05, 25);
    e.advance(EnsembleModels(models, e.ordering()), lanes, 0.05, 25);
    for (std::size_t i = 0; i < x0.size(); ++i) {
      ASSERT_TRUE(same_state(lanes[i], shared[i])) << name << " point " << i;
    }
  }
}

TEST(EnsembleLanes, RefusesModelsThatDoNotFit) {
  const std::vector<QuadraticModel> models = test::random_models(5, true, 1);
  const CompositionTable& table = composition_table("splitting2");
  EnsembleStepper e(table);
  EnsembleState x(random_states(models, 1.0, 2));
  EXPECT_THROW(
      e.advance(EnsembleModels(std::span<const QuadraticModel>(models).subspan(0, 4), e.ordering()),
                x, 0.01, 1),
      InputError);
  SplitOrdering other = e.ordering();
  other.kick_outside = !other.kick_outside;
  EXPECT_THROW(e.advance(EnsembleModels(models, other), x, 0.01, 1), InputError);
}

}  // namespace
}  // namespace test_ensemble_lanes
}  // namespace newtop
