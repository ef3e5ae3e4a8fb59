// Work–precision of the chaos indicators (docs/chaos.md): for each adaptive method with a tangent
// map and each tolerance, the CPU time of `phase::chaos` (one tangent vector, or six with
// --spectrum) and its errors against the same run of dop853 at tolerance 1e-15: the final state
// |Δm| + |Δγ|, λ_max and MEGNO. The regimes of bench/work_precision ((a) generic, T = 40; (b) fast
// spin, λ/Ω² = 1e-3, T = 1e4; (c) slow libration, T = 1e4).
//
// Run: build/bench/chaos_precision [rounds] [--spectrum]   (rounds: the best of, default 3)
//
// "newtop rkf78" is odeint's runge_kutta_fehlberg78 on the state and vectors together (newtop's
// tangent map of rkf78), the general solver the other two are measured against.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "newtop/phase/chaos_run.hpp"
#include "wp_support.hpp"

namespace {

using namespace wp;

struct Case {
  const char* name;
  QuadraticModel model;
  State x0;
  double T;
};

struct Run {
  double cpu;
  phase::ChaosResult r;
};

Run run(const char* method, double tol, const Case& c, bool spectrum, int rounds) {
  MethodSettings s;
  s.name = method;
  s.abs_tol = s.rel_tol = tol;
  Run best{1e300, {}};
  for (int k = 0; k < rounds; ++k) {
    const double t0 = cpu_seconds();
    phase::ChaosResult r =
        phase::chaos(c.model, c.x0, {.method = s, .t_end = c.T, .spectrum = spectrum});
    const double t = cpu_seconds() - t0;
    if (t < best.cpu) best = {t, std::move(r)};
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 && argv[1][0] != '-' ? std::atoi(argv[1]) : 3;
  bool spectrum = false;
  for (int i = 1; i < argc; ++i) spectrum |= std::strcmp(argv[i], "--spectrum") == 0;
  const QuadraticModel a{
      Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1), Vec3(0.1, -0.2, 0.05)),
      QuadraticField::coulomb(1.0, 0.5)};
  const QuadraticModel b{Body::from_principal(Vec3(1.0, 1.2, 1.5), 1.0, Vec3::Zero()),
                         QuadraticField::coulomb(0.0, 1e-3)};
  const QuadraticModel c{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                         QuadraticField::coulomb(0.0, 1.0)};
  const Case cases[] = {
      {"(a) generic, T = 40", a,
       state_from_omega(a.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64)), 40.0},
      {"(b) fast spin, lambda/Omega^2 = 1e-3, T = 1e4", b,
       state_from_omega(b.body, Vec3(0.08, -0.06, 1.0).normalized(),
                        Vec3(0.3, -0.5, 0.8).normalized()),
       1e4},
      {"(c) slow libration, T = 1e4", c,
       state_from_omega(c.body, Vec3(0.05, -0.1, 0.12), Vec3(1.0, 0.15, -0.1).normalized()), 1e4}};
  std::printf("Chaos indicators (%s), best CPU time of %d rounds\n",
              spectrum ? "6 vectors" : "1 vector", rounds);
  for (const Case& k : cases) {
    const Run ref = run("dop853", 1e-15, k, spectrum, 1);
    std::printf(
        "\n### %s\n\nReference: dop853 at tol 1e-15 (%lld steps): MEGNO %.10g, lambda_max %.8g\n\n",
        k.name, static_cast<long long>(ref.r.outcome.steps), ref.r.indicators.megno,
        ref.r.indicators.lyapunov_max);
    std::printf(
        "| method | tol | CPU ms | steps | state error | lambda_max error | MEGNO error |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const char* method : {"rkf78", "dop853", "taylor"}) {
      for (const double tol : {1e-6, 1e-8, 1e-10, 1e-12}) {
        const Run x = run(method, tol, k, spectrum, rounds);
        const State &s = x.r.outcome.state, &r = ref.r.outcome.state;
        std::printf("| %s | %.0e | %.3g | %lld | %.2e | %.2e | %.2e |\n", method, tol, x.cpu * 1e3,
                    static_cast<long long>(x.r.outcome.steps),
                    (s.m - r.m).norm() + (s.gamma - r.gamma).norm(),
                    std::abs(x.r.indicators.lyapunov_max - ref.r.indicators.lyapunov_max),
                    std::abs(x.r.indicators.megno - ref.r.indicators.megno));
      }
    }
  }
  return 0;
}
