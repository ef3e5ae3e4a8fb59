// Cost of one step of each stepper on the same model, beside Boost.Odeint's runge_kutta4 driven
// directly on a plain array (the peer). Run: build/bench_steppers --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include "newtop/newtop.hpp"

namespace {

using namespace newtop;

Model bench_model() {
  return Model{
      Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1), Vec3(0.1, -0.2, 0.05)),
      QuadraticField::coulomb(1.0, 0.5)};
}

State bench_state(const Model& m) {
  return state_from_omega(m.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
}

constexpr double kStep = 1e-3;

void BM_Splitting(benchmark::State& st, const char* name) {
  const Model m = bench_model();
  State x = bench_state(m);
  SplittingStepper s(composition_table(name));
  for (auto _ : st) {
    s.step(m, x, kStep);
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK_CAPTURE(BM_Splitting, splitting2, "splitting2");
BENCHMARK_CAPTURE(BM_Splitting, splitting4, "splitting4");
BENCHMARK_CAPTURE(BM_Splitting, splitting6, "splitting6");
BENCHMARK_CAPTURE(BM_Splitting, splitting8, "splitting8");

template <class S>
void BM_Fixed(benchmark::State& st) {
  const Model m = bench_model();
  State x = bench_state(m);
  S s;
  for (auto _ : st) {
    s.step(m, x, kStep);
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK_TEMPLATE(BM_Fixed, Rk4Stepper)->Name("newtop_rk4");
BENCHMARK_TEMPLATE(BM_Fixed,
                   OdeintFixedStepper<boost::numeric::odeint::runge_kutta_dopri5<OdeState>, 5>)
    ->Name("dopri5_fixed_step");
BENCHMARK_TEMPLATE(BM_Fixed,
                   OdeintFixedStepper<boost::numeric::odeint::runge_kutta_fehlberg78<OdeState>, 8>)
    ->Name("rkf78_fixed_step");

// The peer: odeint's runge_kutta4 on std::array with the right-hand side written out by hand.
void BM_OdeintRk4(benchmark::State& st) {
  const Model m = bench_model();
  const Vec3 I = m.body.inertia(), k = m.body.gyrostat();
  const Vec3 b = m.body.mass() * m.field.g * m.body.center_of_mass();
  const double lam = m.field.lambda_;
  auto sys = [&](const OdeState& y, OdeState& d, double) {
    const double w0 = (y[0] - k[0]) / I[0], w1 = (y[1] - k[1]) / I[1], w2 = (y[2] - k[2]) / I[2];
    const double g0 = b[0] + lam * I[0] * y[3], g1 = b[1] + lam * I[1] * y[4],
                 g2 = b[2] + lam * I[2] * y[5];
    d[0] = y[1] * w2 - y[2] * w1 + y[4] * g2 - y[5] * g1;
    d[1] = y[2] * w0 - y[0] * w2 + y[5] * g0 - y[3] * g2;
    d[2] = y[0] * w1 - y[1] * w0 + y[3] * g1 - y[4] * g0;
    d[3] = y[4] * w2 - y[5] * w1;
    d[4] = y[5] * w0 - y[3] * w2;
    d[5] = y[3] * w1 - y[4] * w0;
  };
  OdeState y = to_ode(bench_state(m));
  boost::numeric::odeint::runge_kutta4<OdeState> rk4;
  double t = 0;
  for (auto _ : st) {
    rk4.do_step(sys, y, t, kStep);
    t += kStep;
    benchmark::DoNotOptimize(y);
  }
}
BENCHMARK(BM_OdeintRk4)->Name("odeint_runge_kutta4_peer");

}  // namespace

BENCHMARK_MAIN();
