// Cost and accuracy of the exact free-body flow as a splitting sub-flow, against the rotation
// splitting (free body split into three axis rotations), on a body in Brun's field.
// Accuracy: max |m − m_ref| + |γ − γ_ref| at t = 10 against rkf78 at tol 1e-14, reported as the
// counter "error"; cost: time per step.

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <benchmark/benchmark.h>

#include "newtop/integrate/free_body_flow.hpp"
#include "newtop/integrate/methods.hpp"

namespace {

using namespace newtop;

const QuadraticModel kModel{Body::from_principal({1.0, 1.6, 2.1}, 1.0, Vec3::Zero()),
                            QuadraticField::coulomb(0.0, 0.5)};
const State kStart =
    state_from_omega(kModel.body, {0.4, -0.7, 1.2}, Vec3(0.3, 0.5, 0.8).normalized());
constexpr double kT = 10.0;

State reference() {
  Fehlberg78Stepper s(1e-14, 1e-14);
  return integrate(s, kModel, kStart, 0.0, kT, {}).state;
}

template <class Stepper>
void run(benchmark::State& st, Stepper make) {
  const double h = kT / static_cast<double>(st.range(0));
  const State ref = reference();
  State x;
  for (auto _ : st) {
    auto s = make();
    x = integrate(s, kModel, kStart, 0.0, kT, {.step = h}).state;
    benchmark::DoNotOptimize(x);
  }
  st.counters["error"] = (x.m - ref.m).norm() + (x.gamma - ref.gamma).norm();
  st.counters["ns_per_step"] =
      benchmark::Counter(static_cast<double>(st.iterations() * st.range(0)),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void ExactFreeBody2(benchmark::State& st) {
  run(st, [] { return FreeBodySplittingStepper(composition_table("splitting2")); });
}
void RotationSplit2(benchmark::State& st) {
  run(st, [] { return SplittingStepper(composition_table("splitting2")); });
}
void ExactFreeBody4(benchmark::State& st) {
  run(st, [] { return FreeBodySplittingStepper(composition_table("splitting4")); });
}
void RotationSplit4(benchmark::State& st) {
  run(st, [] { return SplittingStepper(composition_table("splitting4")); });
}

// One call of the exact free-body flow from a fresh state (what a splitting sub-flow costs): the
// elliptic parameters, sn cn dn, two R_J (three when a half period is crossed) and the rotation.
void FreeBodyFlowCall(benchmark::State& st) {
  const Body body = Body::from_principal({1.0, 1.6, 2.1}, 1.0, Vec3::Zero());
  State x = kStart;
  const double h = 0.01 * static_cast<double>(st.range(0));
  for (auto _ : st) {
    benchmark::DoNotOptimize(x = free_body_flow(body, x, h));
  }
}

BENCHMARK(FreeBodyFlowCall)->Arg(1)->Arg(100);
BENCHMARK(ExactFreeBody2)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(RotationSplit2)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(ExactFreeBody4)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(RotationSplit4)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
