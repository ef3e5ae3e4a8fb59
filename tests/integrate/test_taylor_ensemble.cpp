// The Taylor ensemble against the scalar Taylor run of each point (its guarantee: the same
// Outcome, the same observed steps and samples, bit for bit, whatever the batch size, the lane or
// the instruction set), forward and backward in time, with a model per point or one for all, and
// through the driver's other ends (step limit, step-size underflow).

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/sampled.hpp"
#include "newtop/integrate/taylor.hpp"
#include "newtop/integrate/taylor_ensemble.hpp"
#include "support/ensemble.hpp"

namespace newtop {
namespace test_taylor_ensemble {
namespace {

using test::available_paths;

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same_state(const State& a, const State& b) {
  for (int i = 0; i < 3; ++i) {
    if (!same_bits(a.m[i], b.m[i]) || !same_bits(a.gamma[i], b.gamma[i])) return false;
  }
  return true;
}

// What a run reports: its outcome, every accepted step and every sample, in order.
struct Record {
  Outcome out;
  std::vector<std::pair<double, State>> steps, samples;
};

void expect_same(const Record& a, const Record& b, const std::string& what) {
  EXPECT_EQ(a.out.status, b.out.status) << what;
  EXPECT_TRUE(same_bits(a.out.t, b.out.t)) << what;
  EXPECT_TRUE(same_state(a.out.state, b.out.state))
      << what << ": ensemble " << a.out.state.m.transpose() << " " << a.out.state.gamma.transpose()
      << ", scalar " << b.out.state.m.transpose() << " " << b.out.state.gamma.transpose();
  EXPECT_EQ(a.out.steps, b.out.steps) << what;
  EXPECT_EQ(a.out.rejected, b.out.rejected) << what;
  EXPECT_TRUE(same_bits(a.out.last_step, b.out.last_step)) << what;
  ASSERT_EQ(a.steps.size(), b.steps.size()) << what;
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    ASSERT_TRUE(same_bits(a.steps[i].first, b.steps[i].first) &&
                same_state(a.steps[i].second, b.steps[i].second))
        << what << ", step " << i;
  }
  ASSERT_EQ(a.samples.size(), b.samples.size()) << what;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    ASSERT_TRUE(same_bits(a.samples[i].first, b.samples[i].first) &&
                same_state(a.samples[i].second, b.samples[i].second))
        << what << ", sample " << i;
  }
}

struct Runs {
  std::vector<QuadraticModel> models;  // one, or one per state
  std::vector<State> states;
  double tol = 1e-10, t0 = 0.0, t1 = 6.0;
  int order = 0;  // the tolerance's
  IntegrateOptions options;
};

const QuadraticModel& model_of(const Runs& r, std::size_t i) {
  return r.models.size() == 1 ? r.models[0] : r.models[i];
}

std::vector<Record> scalar_runs(const Runs& r, const OutputTimes& times) {
  std::vector<Record> rec(r.states.size());
  for (std::size_t i = 0; i < r.states.size(); ++i) {
    TaylorStepper s(r.tol, r.tol, r.order);
    Record& x = rec[i];
    x.out = integrate_sampled(
        s, model_of(r, i), r.states[i], r.t0, r.t1, times, r.options,
        [&](std::int64_t, double t, const State& y) { x.samples.emplace_back(t, y); },
        [&](double t, const State& y) { x.steps.emplace_back(t, y); });
  }
  return rec;
}

std::vector<Record> ensemble_runs(const Runs& r, const OutputTimes& times, SimdPath path) {
  std::vector<Record> rec(r.states.size());
  TaylorEnsembleObserver obs;
  obs.step = [&](std::size_t p, double t, const State& y) { rec[p].steps.emplace_back(t, y); };
  obs.times = &times;
  obs.sample = [&](std::size_t p, std::int64_t, double t, const State& y) {
    rec[p].samples.emplace_back(t, y);
  };
  TaylorEnsemble e(r.tol, r.tol, path, r.order);
  const std::vector<Outcome> out = e.integrate(r.models, r.states, r.t0, r.t1, r.options, obs);
  for (std::size_t i = 0; i < out.size(); ++i) rec[i].out = out[i];
  return rec;
}

Runs random_runs(std::size_t n, bool model_per_point, double tol, unsigned seed) {
  Runs r;
  r.tol = tol;
  r.models = test::random_models(model_per_point ? n : 1, true, seed);
  std::mt19937_64 rng(seed + 1);
  for (std::size_t i = 0; i < n; ++i) {
    r.states.push_back(test::random_start(model_of(r, i).body, 2.0, rng));
  }
  return r;
}

void expect_scalar_agreement(const Runs& r, const std::string& what) {
  if (test::kScalarMayContract)
    GTEST_SKIP() << "the scalar recurrences may use fused multiply-adds";
  const OutputTimes times = OutputTimes::every(0.7, r.t0, r.t1);
  const std::vector<Record> ref = scalar_runs(r, times);
  for (SimdPath path : available_paths()) {
    const std::vector<Record> got = ensemble_runs(r, times, path);
    ASSERT_EQ(got.size(), ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i) {
      expect_same(got[i], ref[i],
                  what + ", " + std::string(simd_path_name(path)) + ", point " + std::to_string(i));
    }
  }
}

TEST(TaylorEnsemble, BitIdenticalToScalarRunsForEveryBatchSize) {
  for (std::size_t n : {1, 3, 8, 17}) {
    for (double tol : {1e-9, 1e-12}) {
      const Runs r = random_runs(n, true, tol, static_cast<unsigned>(100 + n));
      expect_scalar_agreement(r, "n " + std::to_string(n) + ", tol " + std::to_string(tol));
    }
  }
}

TEST(TaylorEnsemble, BitIdenticalWithOneModelForAll) {
  expect_scalar_agreement(random_runs(11, false, 1e-11, 7), "one model");
}

TEST(TaylorEnsemble, BitIdenticalBackwardInTime) {
  Runs r = random_runs(9, true, 1e-10, 21);
  r.t0 = 2.0;
  r.t1 = -3.5;
  expect_scalar_agreement(r, "backward");
}

TEST(TaylorEnsemble, BitIdenticalWhereRunsStopEarly) {
  Runs limit = random_runs(10, true, 1e-12, 33);
  limit.options.max_steps = 7;  // every run ends at the step limit
  expect_scalar_agreement(limit, "step limit");
  Runs underflow = random_runs(10, true, 1e-12, 34);
  underflow.options.min_step_factor = 0.05;  // steps of ~0.1 against 0.05 · 6: some underflow
  expect_scalar_agreement(underflow, "underflow");
}

// An order given (as TaylorStepper takes one): the scalar run of that order, bit for bit.
TEST(TaylorEnsemble, BitIdenticalAtAGivenOrder) {
  for (int order : {6, 12, 25}) {
    Runs r = random_runs(9, true, 1e-10, 31);
    r.order = order;
    expect_scalar_agreement(r, "order " + std::to_string(order));
    EXPECT_EQ(TaylorEnsemble(1e-10, 1e-10, best_simd_path(), order).order(), order);
  }
}

TEST(TaylorEnsemble, BitIdenticalWhereSeriesAreNotFinite) {
  // m of 1e160 among ordinary points: the products of the recurrences overflow, the series is not
  // finite, every trial from the given first step on is rejected and retried 5× shorter until the
  // step underflows; the other lanes carry on. The rejections and the outcome are the scalar
  // driver's.
  Runs r = random_runs(7, true, 1e-10, 77);
  r.states[2].m *= 1e160;
  r.states[5].m *= 1e160;
  r.options.initial_step = 0.5;  // a finite first trial (the step of such a series is NaN)
  expect_scalar_agreement(r, "not finite");
  const std::vector<Record> ref = scalar_runs(r, OutputTimes::every(1.0, r.t0, r.t1));
  EXPECT_EQ(ref[2].out.status, Status::step_size_underflow);
  EXPECT_GT(ref[2].out.rejected, 0);
  EXPECT_EQ(ref[3].out.status, Status::finished);
}

TEST(TaylorEnsemble, ReachesTheEndAndIsIndependentOfTheLane) {
  // The same point first and last in a batch of 13 (two refills of the widest block).
  Runs r = random_runs(13, true, 1e-10, 55);
  r.models.back() = r.models.front();
  r.states.back() = r.states.front();
  for (SimdPath path : available_paths()) {
    TaylorEnsemble e(r.tol, r.tol, path);
    const std::vector<Outcome> out = e.integrate(r.models, r.states, r.t0, r.t1);
    for (const Outcome& o : out) {
      EXPECT_EQ(o.status, Status::finished);
      EXPECT_EQ(o.t, r.t1);
    }
    EXPECT_TRUE(same_state(out.front().state, out.back().state)) << simd_path_name(path);
  }
}

TEST(TaylorEnsemble, RefusesBadInputBeforeAnyWork) {
  const Runs r = random_runs(3, true, 1e-10, 1);
  TaylorEnsemble e(1e-10, 1e-10);
  EXPECT_THROW(e.integrate(std::span(r.models).first(2), r.states, 0.0, 1.0), InputError);
  std::vector<State> bad = r.states;
  bad[1].m[0] = std::nan("");
  EXPECT_THROW(e.integrate(r.models, bad, 0.0, 1.0), InputError);
  EXPECT_THROW(e.integrate(r.models, r.states, 0.0, INFINITY), InputError);
  EXPECT_THROW(TaylorEnsemble(0.0, 1e-10), InputError);
  EXPECT_THROW(TaylorEnsemble(1e-10, 1e-10, best_simd_path(), 41), InputError);
  EXPECT_THROW(TaylorEnsemble(1e-10, 1e-10, best_simd_path(), 1), InputError);
}

}  // namespace
}  // namespace test_taylor_ensemble
}  // namespace newtop
