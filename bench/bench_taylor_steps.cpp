// The cost of one Taylor step, per trajectory, of the scalar run and of the ensemble (each SIMD
// path this CPU has), in one regime of work_precision at one tolerance: CPU time / steps, with the
// order and the number of steps. A short run to follow the kernels' cost (and to profile them).
//
// Run: build/bench/bench_taylor_steps [regime] [tol] [N] [seconds] [paths]
//   regime: a, b (b3) or c (default c); tol (default 1e-9); N: trajectories of the ensemble
//   (default 64); seconds: the least CPU time spent on each measurement (default 0.3); paths: the
//   ensembles' SIMD paths to time, names joined by commas (default all available; the scalar run
//   is always timed, once).
// Run: build/bench/bench_taylor_steps [regime] [tol] [N] [seconds] [paths] tangent
//   the ensembles' runs with one tangent vector each (TaylorEnsemble::integrate_tangent, no
//   observer), per step of those runs.

#include <cstdio>
#include <cstdlib>
#include <string>

#include "taylor_ensemble_wp.hpp"

namespace {

using namespace wp;

// Repeats fn() until `seconds` of CPU time are spent; the CPU time of one call.
template <class Fn>
double cpu_per_call(double seconds, Fn&& fn) {
  const double c0 = cpu_seconds();
  int calls = 0;
  do {
    fn();
    ++calls;
  } while (cpu_seconds() - c0 < seconds);
  return (cpu_seconds() - c0) / calls;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "c";
  const double tol = argc > 2 ? std::atof(argv[2]) : 1e-9;
  const std::size_t n = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 64;
  const double seconds = argc > 4 ? std::atof(argv[4]) : 0.3;
  const std::string paths = argc > 5 ? argv[5] : "portable,avx2,avx512";
  const bool tangent = argc > 6 && std::string(argv[6]) == "tangent";
  const Regime r = which == "a" ? generic() : which == "b" ? fast_spin(1e-3, "b3") : libration();
  Outcome scalar;
  const double cpu = cpu_per_call(paths == "none" ? seconds : 0.05, [&] {
    TaylorStepper s(tol, tol);
    scalar = integrate(s, r.model, r.x0, 0.0, r.T, IntegrateOptions{});
  });
  const auto steps = static_cast<double>(scalar.steps);
  std::printf("regime %s, tol %.1e, order %d, %lld steps\n", r.name.c_str(), tol,
              TaylorStepper(tol, tol).order(), static_cast<long long>(scalar.steps));
  std::printf("%-10s %10.1f ns per step, %9.4f ms per trajectory\n", "scalar", 1e9 * cpu / steps,
              1e3 * cpu);
  const std::vector<State> x(n, r.x0);
  const std::vector<QuadraticModel> models{r.model};
  for (SimdPath path : {SimdPath::portable, SimdPath::avx2, SimdPath::avx512}) {
    if (!simd_path_available(path) || paths.find(simd_path_name(path)) == std::string::npos) {
      continue;
    }
    TaylorEnsemble e(tol, tol, path);
    std::vector<Outcome> out;
    if (tangent) {
      const std::vector<TangentVector> v0{phase::initial_tangent(1).col(0)};
      const double c =
          cpu_per_call(seconds,
                       [&] { out = e.integrate_tangent(models, x, v0, 0.0, r.T, {}, {}); }) /
          static_cast<double>(n);
      std::printf(
          "%-10s %10.1f ns per step with one tangent vector (%lld steps), %9.4f ms per "
          "trajectory\n",
          std::string(simd_path_name(path)).c_str(), 1e9 * c / static_cast<double>(out[0].steps),
          static_cast<long long>(out[0].steps), 1e3 * c);
      continue;
    }
    const double c = cpu_per_call(seconds, [&] { out = e.integrate(models, x, 0.0, r.T); }) /
                     static_cast<double>(n);
    const bool same = out[0].state.m == scalar.state.m && out[0].state.gamma == scalar.state.gamma;
    std::printf("%-10s %10.1f ns per step, %9.4f ms per trajectory (%.2fx scalar)%s\n",
                std::string(simd_path_name(path)).c_str(), 1e9 * c / steps, 1e3 * c, c / cpu,
                same ? "" : "  NOT the scalar run's bits");
  }
}
