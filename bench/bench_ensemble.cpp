// Trajectory-steps per second per core in the quadratic field: the ensemble stepper (every SIMD
// path this CPU has) against the scalar splitting stepper and Boost.Odeint's runge_kutta4 (on a
// plain array with a hand-written right-hand side), one trajectory at a time, in the same run.
// One benchmark iteration is one trajectory-step; rates are per CPU second of the one thread.
// tangent_*: the same with one tangent vector per trajectory (the ensemble tangent stepper against
// TangentSplittingStepper); ensemble_lanes/*: a model per point (EnsembleModels), against the
// one-model ensemble of the same table and path in the last column.
// After the runs, each rate is printed as a ratio to the scalar stepper of the same table.
// Run: build/bench/bench_ensemble --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//      --benchmark_enable_random_interleaving=true

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "newtop/integrate/ensemble.hpp"
#include "newtop/integrate/methods.hpp"
#include "newtop/newtop.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "newtop/phase/ensemble_tangent.hpp"
#include "newtop/phase/section_run.hpp"
#include "wp_support.hpp"

namespace {

using namespace newtop;

// The model and step of bench_steppers.cpp; the ensemble's points spread around its state.
QuadraticModel bench_model() {
  return QuadraticModel{
      Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1), Vec3(0.1, -0.2, 0.05)),
      QuadraticField::coulomb(1.0, 0.5)};
}

State bench_state(const QuadraticModel& m, int i = 0) {
  const double d = 1e-3 * i;
  return state_from_omega(m.body, Vec3(0.5 + d, 1.1 - d, -0.4 + d),
                          Vec3(0.48, -0.6 + d, 0.64).normalized());
}

constexpr double kStep = 1e-3;
constexpr int kPoints = 1024;               // 6 arrays of 8 KiB: the ensemble stays in L1/L2
constexpr std::int64_t kStepsPerCall = 64;  // steps per advance() call

void ensemble(benchmark::State& st, const char* table, SimdPath path) {
  const QuadraticModel m = bench_model();
  EnsembleState x;
  for (int i = 0; i < kPoints; ++i) x.push_back(bench_state(m, i));
  EnsembleStepper e(composition_table(table), path);
  while (st.KeepRunningBatch(kPoints * kStepsPerCall)) {
    e.advance(m, x, kStep, kStepsPerCall);
    benchmark::DoNotOptimize(x.m[0].data());
  }
  st.SetItemsProcessed(st.iterations());
}

// A model per point (EnsembleModels): the bench model's moments, λ and centre of mass varied
// point by point, in one working frame (A < B < C throughout: one group).
void ensemble_lanes(benchmark::State& st, const char* table, SimdPath path) {
  const QuadraticModel m = bench_model();
  EnsembleState x;
  std::vector<QuadraticModel> models;
  for (int i = 0; i < kPoints; ++i) {
    const double d = 1e-4 * i;
    models.push_back(
        QuadraticModel{Body::from_principal(Vec3(1.0 + d, 1.5, 2.2 - d), 1.0,
                                            Vec3(0.3, 0.2, 0.1 + d), m.body.gyrostat()),
                       QuadraticField::coulomb(1.0, 0.5 + d)});
    x.push_back(bench_state(models.back(), i));
  }
  EnsembleStepper e(composition_table(table), path);
  const EnsembleModels lanes(models, e.ordering());
  while (st.KeepRunningBatch(kPoints * kStepsPerCall)) {
    e.advance(lanes, x, kStep, kStepsPerCall);
    benchmark::DoNotOptimize(x.m[0].data());
  }
  st.SetItemsProcessed(st.iterations());
}

void scalar(benchmark::State& st, const char* table) {
  const QuadraticModel m = bench_model();
  State x = bench_state(m);
  SplittingStepper s(composition_table(table));
  while (st.KeepRunningBatch(100)) {
    for (int i = 0; i < 100; ++i) {
      s.step(m, x, kStep);
      benchmark::DoNotOptimize(x);
    }
  }
  st.SetItemsProcessed(st.iterations());
}

// With one tangent vector per trajectory (as MEGNO and the largest Lyapunov exponent use).
void tangent_ensemble(benchmark::State& st, const char* table, SimdPath path) {
  const QuadraticModel m = bench_model();
  EnsembleState x;
  for (int i = 0; i < kPoints; ++i) x.push_back(bench_state(m, i));
  std::vector<phase::Tangent> V(kPoints, phase::Tangent::Ones(6, 1));
  const CompositionTable& t = composition_table(table);
  phase::EnsembleTangentStepper e(t, default_ordering(t), path);
  while (st.KeepRunningBatch(kPoints * kStepsPerCall)) {
    e.advance(m, x, V, kStep, kStepsPerCall);
    benchmark::DoNotOptimize(x.m[0].data());
  }
  st.SetItemsProcessed(st.iterations());
}

void tangent_scalar(benchmark::State& st, const char* table) {
  const QuadraticModel m = bench_model();
  State x = bench_state(m);
  phase::Tangent V = phase::Tangent::Ones(6, 1);
  const CompositionTable& t = composition_table(table);
  phase::TangentSplittingStepper s(t, default_ordering(t));
  while (st.KeepRunningBatch(100)) {
    for (int i = 0; i < 100; ++i) {
      s.step(m, x, V, kStep);
      benchmark::DoNotOptimize(V);
    }
  }
  st.SetItemsProcessed(st.iterations());
}

void odeint_rk4(benchmark::State& st) {
  const QuadraticModel m = bench_model();
  const wp::QuadraticRhs<double> rhs(m);
  OdeState y = to_ode(bench_state(m));
  boost::numeric::odeint::runge_kutta4<OdeState> rk4;
  double t = 0.0;
  while (st.KeepRunningBatch(100)) {
    for (int i = 0; i < 100; ++i) {
      rk4.do_step(rhs, y, t, kStep);
      t += kStep;
      benchmark::DoNotOptimize(y);
    }
  }
  st.SetItemsProcessed(st.iterations());
}

// The console report, then each benchmark's rate (median over repetitions where there are any)
// against the scalar stepper of its table (odeint's against splitting2's).
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred || (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median"))
        continue;
      const auto it = r.counters.find("items_per_second");
      if (it != r.counters.end()) rate_[r.run_name.function_name] = it->second.value;
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\n%-38s %14s %10s %10s\n", "benchmark", "steps/s/core", "/ scalar", "/ shared");
    for (const auto& [name, rate] : rate_) {
      const std::string table =
          name.substr(name.find('/') + 1, name.find('/', name.find('/') + 1) - name.find('/') - 1);
      const std::string family = name.rfind("tangent_", 0) == 0 ? "tangent_scalar/" : "scalar/";
      auto scalar = rate_.find(family + table + "/");
      if (scalar == rate_.end()) scalar = rate_.find("scalar/splitting2/");  // odeint's rk4
      // A model per lane against one model for all, same table and path.
      const std::string lanes = "ensemble_lanes/";
      auto shared = rate_.end();
      if (name.rfind(lanes, 0) == 0) shared = rate_.find("ensemble/" + name.substr(lanes.size()));
      std::printf("%-38s %14.4g ", name.c_str(), rate);
      if (scalar != rate_.end()) {
        std::printf("%10.2f", rate / scalar->second);
      } else {
        std::printf("%10s", "");
      }
      if (shared != rate_.end()) std::printf(" %10.2f", rate / shared->second);
      std::printf("\n");
    }
  }

 private:
  std::map<std::string, double> rate_;
};

}  // namespace

int main(int argc, char** argv) {
  for (const char* table : {"splitting2", "splitting6"}) {
    for (SimdPath path : {SimdPath::portable, SimdPath::avx2, SimdPath::avx512}) {
      if (!simd_path_available(path)) continue;
      benchmark::RegisterBenchmark(
          ("ensemble/" + std::string(table) + "/" + std::string(simd_path_name(path))).c_str(),
          [table, path](benchmark::State& st) { ensemble(st, table, path); });
      benchmark::RegisterBenchmark(
          ("ensemble_lanes/" + std::string(table) + "/" + std::string(simd_path_name(path)))
              .c_str(),
          [table, path](benchmark::State& st) { ensemble_lanes(st, table, path); });
    }
    benchmark::RegisterBenchmark(("scalar/" + std::string(table) + "/").c_str(),
                                 [table](benchmark::State& st) { scalar(st, table); });
  }
  benchmark::RegisterBenchmark("odeint_runge_kutta4/rk4/", odeint_rk4);
  for (SimdPath path : {SimdPath::portable, SimdPath::avx2, SimdPath::avx512}) {
    if (!simd_path_available(path)) continue;
    benchmark::RegisterBenchmark(
        ("tangent_ensemble/splitting2/" + std::string(simd_path_name(path))).c_str(),
        [path](benchmark::State& st) { tangent_ensemble(st, "splitting2", path); });
  }
  benchmark::RegisterBenchmark("tangent_scalar/splitting2/",
                               [](benchmark::State& st) { tangent_scalar(st, "splitting2"); });
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
