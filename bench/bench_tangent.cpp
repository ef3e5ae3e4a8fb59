// Cost of a step with the tangent map (one vector, and six) relative to a plain step of the same
// method, on the generic heavy body, in the quadratic field and the exact field of point masses.
// Run: build/bench/bench_tangent --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// (docs/chaos.md gives the measured ratios).

#include <benchmark/benchmark.h>

#include <memory>

#include "newtop/integrate/methods.hpp"
#include "newtop/newtop.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "newtop/phase/section_run.hpp"

namespace {

using namespace newtop;

constexpr double kStep = 1e-3;

QuadraticModel quadratic_model() {
  return QuadraticModel{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1)),
                        QuadraticField::coulomb(1.0, 0.5)};
}

BasicModel<ExactField> exact_model() {
  const auto points = std::make_shared<const MassModel>(PointMasses(
      {1.0, 0.7, 0.5, 0.9},
      {Vec3(0.3, 0.1, -0.2), Vec3(-0.4, 0.2, 0.1), Vec3(0.1, -0.5, 0.3), Vec3(0.0, 0.2, -0.4)}));
  return newtop::exact_model(Model::exact(points, 2.0, 3.0 * max_radius(*points)));
}

template <class M>
State start(const M& m) {
  return state_from_omega(m.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
}

MethodSettings method(const char* name) {
  MethodSettings s;
  s.name = name;
  s.step = kStep;
  return s;
}

template <class M>
void plain(benchmark::State& st, const M& model, const char* name) {
  with_stepper(method(name), [&](auto& s) {
    if constexpr (FixedStepper<std::decay_t<decltype(s)>, M>) {
      State x = start(model);
      for (auto _ : st) {
        s.step(model, x, kStep);
        benchmark::DoNotOptimize(x);
      }
    }
  });
}

template <class M>
void tangent(benchmark::State& st, const M& model, const char* name, int vectors) {
  phase::with_tangent_stepper(method(name), [&](auto& s) {
    if constexpr (phase::TangentFixedStepper<std::decay_t<decltype(s)>, M>) {
      State x = start(model);
      phase::Tangent V = phase::initial_tangent(vectors);
      for (auto _ : st) {
        s.step(model, x, V, kStep);
        benchmark::DoNotOptimize(x);
        benchmark::DoNotOptimize(V);
      }
    }
  });
}

void register_all() {
  static const QuadraticModel q = quadratic_model();
  static const BasicModel<ExactField> e = exact_model();
  for (const char* name : {"splitting6", "splitting4", "rk4"}) {
    const std::string n(name);
    benchmark::RegisterBenchmark(("quadratic/" + n + "/plain").c_str(),
                                 [name](benchmark::State& st) { plain(st, q, name); });
    benchmark::RegisterBenchmark(("quadratic/" + n + "/tangent1").c_str(),
                                 [name](benchmark::State& st) { tangent(st, q, name, 1); });
    benchmark::RegisterBenchmark(("quadratic/" + n + "/tangent6").c_str(),
                                 [name](benchmark::State& st) { tangent(st, q, name, 6); });
  }
  benchmark::RegisterBenchmark("exact/splitting6/plain",
                               [](benchmark::State& st) { plain(st, e, "splitting6"); });
  benchmark::RegisterBenchmark("exact/splitting6/tangent1",
                               [](benchmark::State& st) { tangent(st, e, "splitting6", 1); });
  benchmark::RegisterBenchmark("exact/splitting6/tangent6",
                               [](benchmark::State& st) { tangent(st, e, "splitting6", 6); });
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
