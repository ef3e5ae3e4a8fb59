// The Taylor ensemble against newtop's scalar Taylor run, in the regimes (a), (b3), (c) of
// work_precision: CPU time per trajectory to a final state error of 1e-9 and 1e-12 (|Δm| + |Δγ|
// at T against Fehlberg 7(8) in long double at 1e-19), each interpolated in log–log on a ladder of
// tolerances; the ensemble runs N copies of the start (one per lane) and every lane is checked to
// be the scalar run's bits.
//
// The same with one tangent vector (the chaos indicators observed after every step, as newtop chaos
// runs them) in a second table.
//
// Run: build/bench/bench_taylor_ensemble [regimes] [rounds] [N]
//   regimes: letters among a, b, c (default abc); rounds: timing rounds, the best kept (default 3);
//   N: trajectories of the ensemble (default 64).

#include <cstdio>
#include <cstdlib>
#include <string>

#include "taylor_ensemble_wp.hpp"

namespace {

using namespace wp;

void report(const std::vector<WpPoint>& scalar, const std::vector<WpPoint>& lanes, bool same) {
  std::printf("every lane the scalar run's bits: %s\n", same ? "yes" : "NO");
  for (double target : {1e-9, 1e-12}) {
    const auto a = time_at(scalar, target), b = time_at(lanes, target);
    if (a && b) {
      std::printf("error %.0e: scalar %.5f ms, ensemble %.5f ms per trajectory (%.2fx)\n", target,
                  1e3 * *a, 1e3 * *b, *b / *a);
    } else {
      std::printf("error %.0e: not bracketed by the ladder\n", target);
    }
  }
}

void run_tangent(const Regime& r, const LState& ref, int rounds, std::size_t n) {
  std::vector<WpPoint> scalar, lanes;
  bool same = true;
  std::printf("with one tangent vector\n%-8s %12s %14s %14s\n", "tol", "state error", "scalar ms",
              "ensemble ms");
  for (double tol : tolerance_ladder()) {
    State xs;
    scalar.push_back(scalar_taylor_tangent(r, ref, tol, rounds, xs));
    lanes.push_back(ensemble_taylor_tangent(r, ref, tol, n, rounds, xs, same));
    std::printf("%-8.1e %12.3e %14.5f %14.5f\n", tol, scalar.back().error, 1e3 * scalar.back().cpu,
                1e3 * lanes.back().cpu);
  }
  report(scalar, lanes, same);
}

void run_regime(const Regime& r, int rounds, std::size_t n) {
  const LState ref = reference(r, 1e-19L);
  std::vector<WpPoint> scalar, lanes;
  bool same = true;
  std::printf("\n## %s\n%-8s %12s %14s %14s\n", r.description.c_str(), "tol", "state error",
              "scalar ms", "ensemble ms");
  for (double tol : tolerance_ladder()) {
    scalar.push_back(scalar_taylor(r, ref, tol, rounds));
    TaylorStepper s(tol, tol);
    const State xs = integrate(s, r.model, r.x0, 0.0, r.T, IntegrateOptions{}).state;
    lanes.push_back(ensemble_taylor(r, ref, tol, n, rounds, xs, same));
    std::printf("%-8.1e %12.3e %14.5f %14.5f\n", tol, scalar.back().error, 1e3 * scalar.back().cpu,
                1e3 * lanes.back().cpu);
  }
  report(scalar, lanes, same);
  run_tangent(r, ref, rounds, n);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "abc";
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::size_t n = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 64;
  std::printf("Taylor ensemble (%s, %zu lanes), %zu trajectories\n",
              std::string(newtop::simd_path_name(newtop::best_simd_path())).c_str(),
              newtop::TaylorEnsemble(1e-9, 1e-9).lanes(), n);
  if (which.find('a') != std::string::npos) run_regime(generic(), rounds, n);
  if (which.find('b') != std::string::npos) run_regime(fast_spin(1e-3, "b3"), rounds, n);
  if (which.find('c') != std::string::npos) run_regime(libration(), rounds, n);
}
