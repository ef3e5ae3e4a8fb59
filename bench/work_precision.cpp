// Work–precision: max relative energy error over T against CPU time, for the splitting methods of
// order 2–8 and Boost.Odeint's runge_kutta_dopri5 and runge_kutta_fehlberg78 (adaptive), on one
// generic (non-integrable) model. Also measures the orderings of the free-body split.
// Run: build/work_precision [T]   (default T = 1e4; prints markdown tables)

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "newtop/newtop.hpp"

namespace {

using namespace newtop;
using Clock = std::chrono::steady_clock;

Model wp_model() {
  return Model{
      Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1), Vec3(0.1, -0.2, 0.05)),
      QuadraticField::coulomb(1.0, 0.5)};
}

struct Point {
  double seconds, max_rel_energy_error;
  std::int64_t steps;
};

template <class Run>
Point measure(const Model& m, Run&& run) {
  const State x0 = state_from_omega(m.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
  const double e0 = energy(m, x0);
  double err = 0;
  auto obs = [&](double, const State& x) { err = std::max(err, std::abs(energy(m, x) - e0)); };
  const auto t0 = Clock::now();
  const Outcome o = run(x0, obs);
  const double secs = std::chrono::duration<double>(Clock::now() - t0).count();
  return {secs, err / std::abs(e0), o.steps};
}

void orderings(const Model& m) {
  std::printf("\n### Ordering of the free-body split (splitting2, h = 0.01, T = 10)\n\n");
  std::printf(
      "| kick | axes (i, j, k) | max rel. energy error | state error at T vs rkf78 "
      "|\n|---|---|---|---|\n");
  const State x0 = state_from_omega(m.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
  Fehlberg78Stepper ref_s(1e-14, 1e-14);
  const State ref = integrate(ref_s, m, x0, 0.0, 10.0, IntegrateOptions{}).state;
  const std::array<std::array<int, 3>, 6> perms{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (bool outside : {true, false}) {
    for (const auto& p : perms) {
      SplitOrdering o{p, outside, false};
      const Point pt = measure(m, [&](const State& x, auto& obs) {
        SplittingStepper s(composition_table("splitting2"), o);
        return integrate(s, m, x, 0.0, 10.0, IntegrateOptions{.step = 0.01}, obs);
      });
      SplittingStepper s(composition_table("splitting2"), o);
      const State xe = integrate(s, m, x0, 0.0, 10.0, IntegrateOptions{.step = 0.01}).state;
      const double dist = std::max((xe.m - ref.m).norm(), (xe.gamma - ref.gamma).norm());
      std::printf("| %s | (%c, %c, %c) | %.3e | %.3e |\n", outside ? "outside" : "inside",
                  "xyz"[p[0]], "xyz"[p[1]], "xyz"[p[2]], pt.max_rel_energy_error, dist);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const double T = argc > 1 ? std::atof(argv[1]) : 1e4;
  const Model m = wp_model();
  std::printf(
      "### Work–precision, T = %g (A, B, C = 1, 1.5, 2.2; r0 = (0.3, 0.2, 0.1); k = (0.1, -0.2, "
      "0.05); g = 1, lambda = 0.5)\n\n",
      T);
  std::printf(
      "| method | step or tol | steps | CPU s | max rel. energy error |\n|---|---|---|---|---|\n");
  const std::vector<std::pair<const char*, std::vector<double>>> split{
      {"splitting2", {0.02, 0.01, 0.005, 0.0025}},
      {"splitting4", {0.1, 0.05, 0.025, 0.0125}},
      {"splitting6", {0.2, 0.1, 0.05, 0.025}},
      {"splitting8", {0.4, 0.2, 0.1, 0.05}}};
  for (const auto& [name, steps] : split) {
    for (double h : steps) {
      const Point p = measure(m, [&](const State& x, auto& obs) {
        SplittingStepper s(composition_table(name));
        return integrate(s, m, x, 0.0, T, IntegrateOptions{.step = h}, obs);
      });
      std::printf("| %s | h = %g | %lld | %.3f | %.2e |\n", name, h, (long long)p.steps, p.seconds,
                  p.max_rel_energy_error);
    }
  }
  for (double tol : {1e-8, 1e-10, 1e-12, 1e-13}) {
    const Point p = measure(m, [&](const State& x, auto& obs) {
      Dopri5Stepper s(tol, tol);
      return integrate(s, m, x, 0.0, T, IntegrateOptions{}, obs);
    });
    std::printf("| odeint dopri5 | tol = %g | %lld | %.3f | %.2e |\n", tol, (long long)p.steps,
                p.seconds, p.max_rel_energy_error);
  }
  for (double tol : {1e-8, 1e-10, 1e-12, 1e-13, 1e-14}) {
    const Point p = measure(m, [&](const State& x, auto& obs) {
      Fehlberg78Stepper s(tol, tol);
      return integrate(s, m, x, 0.0, T, IntegrateOptions{}, obs);
    });
    std::printf("| odeint fehlberg78 | tol = %g | %lld | %.3f | %.2e |\n", tol, (long long)p.steps,
                p.seconds, p.max_rel_energy_error);
  }
  orderings(m);
  return 0;
}
