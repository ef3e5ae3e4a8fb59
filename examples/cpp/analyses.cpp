// The analyses of the library on one model and state, each a function with a plain result
// (docs/cpp.md, "Analyses"): equilibria, stability of an equilibrium, a Poincaré section, chaos
// indicators and the closed form of a heavy top against a numerical run.
#include <cstdio>
#include <newtop/newtop.hpp>
#include <vector>

#include "newtop/analysis/analytic_comparison.hpp"
#include "newtop/analysis/stability_report.hpp"

int main() {
  using namespace newtop;
  const Model model(Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.1, 0.05, 0.2)),
                    QuadraticField::coulomb(1.0, 0.7));
  const State x0 = state_from_omega(model.body(), Vec3(0.3, -0.2, 0.9), Vec3(0.0, 0.6, 0.8));

  const EquilibriumSet eq = find_equilibria(model);
  std::printf("%zu equilibria, count rule %s\n", eq.equilibria.size(),
              eq.count_rule_holds() ? "holds" : "does not apply");

  const StabilityReport st = stability_of_equilibrium(model, 1);
  std::printf("equilibrium 1: max real part %.3g, %s\n", st.spectrum.max_real_part,
              st.spectrum.linearly_stable ? "linearly stable" : "unstable");

  const MethodSettings method{"splitting6", 0.01};
  const phase::SectionResult sec = phase::section(model, x0,
                                                  {.method = method,
                                                   .surface = phase::parse_surface("gamma1 = 0"),
                                                   .max_crossings = 50,
                                                   .t_end = 1e4});
  std::printf("section: %zu crossings (%s)\n", sec.crossings.size(), phase::to_string(sec.status));

  const phase::ChaosResult ch = phase::chaos(model, x0, {.method = method, .t_end = 100.0});
  std::printf("MEGNO %.4f, lambda_max %.4g\n", ch.indicators.megno, ch.indicators.lyapunov_max);

  // A heavy symmetric top: Lagrange's case, its closed form against rkf78 at 5 times.
  const QuadraticModel top{Body::from_principal(Vec3(2, 2, 1), 1.0, Vec3(0, 0, 0.5)),
                           QuadraticField::uniform(9.81)};
  const State y0 = state_from_omega(top.body, Vec3(0.3, 0, 20), Vec3(0.6, 0, 0.8));
  const AnalyticDetection det = detect_analytic_case(top, y0);
  const AnalyticComparison cmp =
      compare_analytic(top, y0, analytic_solution(top, y0, det.kind), {0.5, 1.0, 1.5, 2.0, 2.5});
  std::printf("%s: max |analytic - numeric| = %.3g\n", to_string(det.kind).c_str(),
              cmp.max_abs_error.value_or(-1.0));

  // The closed form agrees with rkf78 at tol 1e-13 to ~1e-11 here; 1e-8 leaves a wide margin.
  const bool ok = !eq.equilibria.empty() && sec.crossings.size() == 50 &&
                  sec.status == phase::SectionStatus::crossings &&
                  ch.outcome.status == Status::finished && det.kind == AnalyticKind::lagrange &&
                  cmp.max_abs_error && *cmp.max_abs_error < 1e-8;
  return ok ? 0 : 1;
}
