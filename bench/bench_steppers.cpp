// Cost of one step of each stepper on the same model, beside Boost.Odeint's runge_kutta4 driven
// directly on a plain array with a hand-written right-hand side (the peer).
// Run: build/bench/bench_steppers --benchmark_repetitions=9 --benchmark_report_aggregates_only=true
//      --benchmark_enable_random_interleaving=true
// Instruction counts (repeatable on a busy machine):
//      valgrind --tool=callgrind build/bench/bench_steppers --steps NAME N
// runs N steps of NAME (a benchmark name below) and nothing else.

#include <benchmark/benchmark.h>

#include <cstring>
#include <functional>
#include <map>
#include <string>

#include "newtop/integrate/methods.hpp"
#include "newtop/newtop.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "newtop/phase/section_run.hpp"
#include "wp_support.hpp"

namespace {

using namespace newtop;

QuadraticModel bench_model() {
  return QuadraticModel{
      Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1), Vec3(0.1, -0.2, 0.05)),
      QuadraticField::coulomb(1.0, 0.5)};
}

State bench_state(const QuadraticModel& m) {
  return state_from_omega(m.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
}

constexpr double kStep = 1e-3;

SplittingStepper make_splitting(const char* name, FreeBodySplit split) {
  const CompositionTable& t = composition_table(name);
  SplitOrdering o = default_ordering(t);
  o.free_body = split;
  return SplittingStepper(t, o);
}

// Each benchmark as a function advancing its own state by n steps, so that the same code serves
// Google Benchmark and the instruction counts.
using Steps = std::function<void(std::int64_t)>;

// X = OrientedState: the same steps carrying the attitude (the cost of it).
template <class S, class X = State>
Steps newtop_steps(S stepper) {
  return
      [s = std::move(stepper), m = bench_model(), x = X{}, init = false](std::int64_t n) mutable {
        if (!init) {
          if constexpr (kOriented<X>) {
            x = with_attitude(bench_state(m), from_euler_321(Vec3(0.7, -0.4, 2.1)));
          } else {
            x = bench_state(m);
          }
          init = true;
        }
        for (std::int64_t i = 0; i < n; ++i) {
          s.step(m, x, kStep);
          benchmark::DoNotOptimize(x);
        }
      };
}

// The peer: odeint's runge_kutta4 on std::array with the right-hand side written out by hand.
Steps odeint_rk4_steps() {
  const QuadraticModel m = bench_model();
  return [rhs = wp::QuadraticRhs<double>(m), y = to_ode(bench_state(m)),
          rk4 = boost::numeric::odeint::runge_kutta4<OdeState>(), t = 0.0](std::int64_t n) mutable {
    for (std::int64_t i = 0; i < n; ++i) {
      rk4.do_step(rhs, y, t, kStep);
      t += kStep;
      benchmark::DoNotOptimize(y);
    }
  };
}

// The latency floor of splitting2's step (axes split, kick inside: T(h/2) K(h) T(h/2)): the same
// sub-flows on a phase point held in registers from step to step, without the State the stepper
// reads and writes; with the kick (the whole step) or its ten rotations alone. Each rotation's
// angle depends on the momentum the one before produced, so these run at the latency of that chain.
template <bool Kick>
Steps splitting2_floor_steps() {
  using P = detail::Axes<0, 1, 2>;  // the bench body's moments increase along x, y, z
  const QuadraticModel m = bench_model();
  SplitFrame f;
  for (int w = 0; w < 3; ++w) {
    f.rate[w] = 1.0 / m.body.inertia()[w];
    f.k_over_i[w] = m.body.gyrostat()[w] / m.body.inertia()[w];
  }
  return [m, f, z = detail::to_phase<P>(bench_state(m))](std::int64_t n) mutable {
    for (std::int64_t i = 0; i < n; ++i) {
      detail::AxesFlow::flow<P>(z, f, m.body, 0.5 * kStep);
      if constexpr (Kick) detail::kick<P>(z, m, kStep);
      detail::AxesFlow::flow<P>(z, f, m.body, 0.5 * kStep);
    }
    benchmark::DoNotOptimize(z);  // z stays in registers through the loop
  };
}

/// Dormand–Prince 8(5,3)'s trial step at a tolerance every step meets: the whole accepted step
/// (12 evaluations, the error estimate, the step's bookkeeping), as a fixed step.
struct Dop853EveryStepAccepted {
  Dop853Stepper s{1e3, 1e3};
  int order() const { return s.order(); }
  void step(const QuadraticModel& m, State& x, double h) {
    double t = 0.0, dt = h;
    s.try_step(m, x, t, dt);
  }
};

/// Taylor's step at tolerance 1e-12 (order 21) as a fixed step: the coefficients at the point and
/// the series summed at h (the step the method would take there is longer than kStep).
struct TaylorFixedStep {
  TaylorStepper s{1e-12, 1e-12};
  int order() const { return s.order(); }
  void step(const QuadraticModel& m, State& x, double h) {
    double t = 0.0, dt = h;
    s.try_step(m, x, t, dt);
  }
};

std::map<std::string, std::function<Steps()>> benchmarks() {
  std::map<std::string, std::function<Steps()>> b;
  for (const char* name : {"splitting2", "splitting4", "splitting6", "splitting8"}) {
    b[std::string(name) + "_axes"] = [name] {
      return newtop_steps(make_splitting(name, FreeBodySplit::axes));
    };
    b[std::string(name) + "_spin"] = [name] {
      return newtop_steps(make_splitting(name, FreeBodySplit::spin));
    };
  }
  for (const char* name : {"splitting2", "splitting6"}) {
    b[std::string(name) + "_axes_attitude"] = [name] {
      return newtop_steps<SplittingStepper, OrientedState>(
          make_splitting(name, FreeBodySplit::axes));
    };
    b[std::string(name) + "_spin_attitude"] = [name] {
      return newtop_steps<SplittingStepper, OrientedState>(
          make_splitting(name, FreeBodySplit::spin));
    };
  }
  b["splitting2_axes_floor_step"] = splitting2_floor_steps<true>;
  b["splitting2_axes_floor_rotations"] = splitting2_floor_steps<false>;
  b["newtop_rk4"] = [] { return newtop_steps(Rk4Stepper()); };
  b["newtop_rk4_attitude"] = [] { return newtop_steps<Rk4Stepper, OrientedState>(Rk4Stepper()); };
  b["dopri5_fixed_step"] = [] {
    return newtop_steps(
        OdeintFixedStepper<boost::numeric::odeint::runge_kutta_dopri5<OdeState>, 5>());
  };
  b["rkf78_fixed_step"] = [] {
    return newtop_steps(
        OdeintFixedStepper<boost::numeric::odeint::runge_kutta_fehlberg78<OdeState>, 8>());
  };
  b["dop853_accepted_step"] = [] { return newtop_steps(Dop853EveryStepAccepted()); };
  b["taylor21_step"] = [] { return newtop_steps(TaylorFixedStep()); };
  b["odeint_runge_kutta4_peer"] = odeint_rk4_steps;
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  const auto all = benchmarks();
  if (argc == 4 && std::strcmp(argv[1], "--steps") == 0) {
    const auto it = all.find(argv[2]);
    if (it == all.end()) return 2;
    it->second()(std::atoll(argv[3]));
    return 0;
  }
  for (const auto& [name, make] : all) {
    benchmark::RegisterBenchmark(name.c_str(), [make = make](benchmark::State& st) {
      Steps steps = make();
      while (st.KeepRunningBatch(100)) steps(100);  // one iteration = one step
    });
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
