// Work–precision in the three regimes of docs/performance.md: for each method, the least CPU time
// to reach a final state error |Δm| + |Δγ| at T (against Fehlberg 7(8) in long double at tolerance
// 1e-19) of 1e-6, 1e-9 and 1e-12, and, separately, a maximum relative energy error of the same
// sizes. The step (fixed-step methods) or the tolerance (adaptive methods) is found by bisection;
// then every method's best setting is timed in interleaved rounds and the median CPU time kept.
//
// Run: build/bench/work_precision [regimes] [rounds] [data.csv] [max_steps]
//   regimes: letters among a, b (both λ/Ω²), c (default: abc); rounds: timing rounds (default 7);
//   data.csv: every run of the search (method, setting, steps, error, CPU s) for plotting;
//   max_steps: fixed-step runs longer than this are not tried (default 2e7; a target a method
//   reaches only beyond it is "not reached"); only: comma-separated parts of the names of the
//   methods to run, the odeint peers always (e.g. "taylor,dop853").

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "wp_support.hpp"

namespace {

using namespace wp;

struct Run {
  State x;
  std::int64_t steps = 0;
  double energy_error = 0.0;  // max |E − E0|/|E0| over the steps (when observed)
};

struct Method {
  std::string name;
  bool adaptive;
  std::function<Run(const Regime&, double, bool)> run;  // (regime, h or tol, observe energy)
};

// Tracks max |E − E0| / |E0| along a run.
struct EnergyWatch {
  const QuadraticModel* m;
  double e0, worst = 0.0;
  void operator()(const State& x) {
    worst = std::max(worst, std::abs(energy(*m, x) - e0) / std::abs(e0));
  }
};

Method splitting(std::string label, const CompositionTable& table, SplitOrdering o) {
  return {std::move(label), false, [&table, o](const Regime& r, double h, bool observe) {
            SplittingStepper s(table, o);
            EnergyWatch w{&r.model, energy(r.model, r.x0)};
            const IntegrateOptions opt{.step = h};
            const Outcome out = observe ? integrate(s, r.model, r.x0, 0.0, r.T, opt,
                                                    [&](double, const State& x) { w(x); })
                                        : integrate(s, r.model, r.x0, 0.0, r.T, opt);
            return Run{out.state, out.steps, w.worst};
          }};
}

template <class Stepper>
Method peer(std::string label) {
  return {std::move(label), true, [](const Regime& r, double tol, bool observe) {
            EnergyWatch w{&r.model, energy(r.model, r.x0)};
            Run run;
            run.x = observe ? odeint_run<Stepper, true>(r, tol, run.steps, w)
                            : odeint_run<Stepper, false>(r, tol, run.steps, w);
            run.energy_error = w.worst;
            return run;
          }};
}

template <class Stepper>
Method newtop_adaptive(std::string label) {
  return {std::move(label), true, [](const Regime& r, double tol, bool observe) {
            Stepper s(tol, tol);
            EnergyWatch w{&r.model, energy(r.model, r.x0)};
            const Outcome out = observe ? integrate(s, r.model, r.x0, 0.0, r.T, {},
                                                    [&](double, const State& x) { w(x); })
                                        : integrate(s, r.model, r.x0, 0.0, r.T, {});
            return Run{out.state, out.steps, w.worst};
          }};
}

std::string only;  // comma-separated parts of method names to run (empty: every method)

std::vector<Method> methods(bool exact_allowed) {
  std::vector<Method> m;
  for (const auto& t : composition_tables()) {
    const SplitOrdering o = default_ordering(t);
    m.push_back(splitting(std::string(t.name) + " (axes)", t, o));
    SplitOrdering spin = o;
    spin.free_body = FreeBodySplit::spin;
    m.push_back(splitting(std::string(t.name) + " (spin)", t, spin));
  }
  if (exact_allowed) {
    const SplitOrdering exact{{0, 1, 2}, true, true, FreeBodySplit::exact};
    m.push_back(splitting("splitting4 (exact free body)", composition_table("splitting4"), exact));
    for (const auto& t : near_integrable_tables()) {
      if (t.name == "saba2" || t.name == "sbab4" || t.name == "saba4") continue;
      m.push_back(splitting(std::string(t.name) + " (exact free body)", t, exact));
    }
  }
  m.push_back(newtop_adaptive<Dop853Stepper>("newtop dop853"));
  m.push_back(newtop_adaptive<TaylorStepper>("newtop taylor"));
  m.push_back(newtop_adaptive<Fehlberg78Stepper>("newtop rkf78 (odeint through newtop)"));
  m.push_back(peer<ode::runge_kutta_fehlberg78<OdeState>>("odeint rkf78 (peer)"));
  m.push_back(peer<ode::runge_kutta_dopri5<OdeState>>("odeint dopri5 (peer)"));
  if (!only.empty()) {  // keep the methods named in `only` and the peers (the last two)
    std::erase_if(m, [](const Method& x) {
      if (x.name.find("(peer)") != std::string::npos) return false;
      for (std::size_t a = 0; a < only.size();) {
        const std::size_t b = std::min(only.find(',', a), only.size());
        if (x.name.find(only.substr(a, b - a)) != std::string::npos) return false;
        a = b + 1;
      }
      return true;
    });
  }
  return m;
}

// --- search --------------------------------------------------------------------------------------

struct Eval {
  double param, error, cpu;
  std::int64_t steps;
  bool ok;
};

std::int64_t max_steps = 20'000'000;  // a fixed-step run above this many steps is not tried

struct Context {
  const Regime* regime;
  LState ref;
  FILE* data;
};

Eval evaluate(const Context& c, const Method& m, double param, bool energy_metric) {
  if (!m.adaptive && std::ceil(c.regime->T / param) > double(max_steps))
    return {param, 0, 0, 0, false};
  const double t0 = cpu_seconds();
  const Run r = m.run(*c.regime, param, energy_metric);
  const double cpu = cpu_seconds() - t0;
  double err = energy_metric ? r.energy_error : state_error(r.x, c.ref);
  if (!std::isfinite(err) || !is_finite(r.x)) err = INFINITY;
  if (c.data) {
    std::fprintf(c.data, "%s,%s,\"%s\",%.6g,%lld,%.6e,%.6e\n", c.regime->name.c_str(),
                 energy_metric ? "energy" : "state", m.name.c_str(), param, (long long)r.steps, err,
                 cpu);
    std::fflush(c.data);
  }
  return {param, err, cpu, r.steps, true};
}

// The cheapest setting meeting `target`: fixed step — the largest h (from h_start, halving, then
// bisecting in log h to 1%), accepted only if 0.9 h passes too; adaptive — the largest tolerance
// (from 1e-3 down by 10, then bisecting in log tol to 2%). Returns ok = false if none is found.
Eval search(const Context& c, const Method& m, double target, bool energy_metric, double start) {
  auto pass = [&](const Eval& e) { return e.ok && e.error <= target; };
  const double factor = m.adaptive ? 10.0 : 2.0, floor = m.adaptive ? 1e-16 : 0.0;
  double hi = start;  // hi fails (or is the start), lo passes
  Eval lo{};
  Eval e = evaluate(c, m, start, energy_metric);
  if (pass(e)) {
    lo = e;  // already passes at the start: the start is the coarsest setting we try
    return lo;
  }
  for (double p = start / factor;; p /= factor) {
    if (p < floor) return {p, INFINITY, 0, 0, false};
    e = evaluate(c, m, p, energy_metric);
    if (!e.ok) return e;
    if (pass(e)) {
      lo = e;
      hi = p * factor;
      break;
    }
  }
  const double resolution = m.adaptive ? 1.02 : 1.01;
  while (hi / lo.param > resolution) {
    const double mid = std::sqrt(hi * lo.param);
    e = evaluate(c, m, mid, energy_metric);
    if (pass(e)) {
      lo = e;
    } else {
      hi = mid;
    }
  }
  if (!m.adaptive) {  // guard against an accidental zero of a sign-changing error
    const Eval check = evaluate(c, m, 0.9 * lo.param, energy_metric);
    if (!pass(check)) return search(c, m, target, energy_metric, 0.9 * lo.param / 2);
  }
  return lo;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Times every method at its setting in `rounds` interleaved rounds (each timing repeats the run
// until it lasts 20 ms); returns the median CPU seconds per run.
std::vector<double> time_interleaved(const Context& c, const std::vector<Method>& ms,
                                     const std::vector<Eval>& settings, bool energy_metric,
                                     int rounds) {
  std::vector<std::vector<double>> t(ms.size());
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t k = 0; k < ms.size(); ++k) {
      const std::size_t i = (k + round) % ms.size();  // rotate the order each round
      if (!settings[i].ok) continue;
      const int reps = std::max(1, int(0.02 / std::max(settings[i].cpu, 1e-6)));
      const double t0 = cpu_seconds();
      for (int rep = 0; rep < reps; ++rep) ms[i].run(*c.regime, settings[i].param, energy_metric);
      t[i].push_back((cpu_seconds() - t0) / reps);
    }
  }
  std::vector<double> med(ms.size(), INFINITY);
  for (std::size_t i = 0; i < ms.size(); ++i)
    if (!t[i].empty()) med[i] = median(t[i]);
  return med;
}

void run_regime(const Regime& r, int rounds, FILE* data) {
  const double t0 = cpu_seconds();
  Context c{&r, reference(r, 1e-19L), data};
  const LState check = reference(r, 1e-18L);
  double ref_err = 0;
  for (int i = 0; i < 6; ++i) ref_err += std::abs(double(check[i] - c.ref[i]));
  std::printf(
      "\n### %s\n\nReference: rkf78 in long double at tol 1e-19 (%.1f s CPU); it differs "
      "from the same at tol 1e-18 by %.1e.\n",
      r.description.c_str(), cpu_seconds() - t0, ref_err);
  const bool exact_allowed = r.model.body.gyrostat().isZero(0.0);
  const std::vector<Method> ms = methods(exact_allowed);
  for (bool energy_metric : {false, true}) {
    std::printf("\n%s\n\n| method |", energy_metric ? "Max relative energy error over the run "
                                                      "(observed at every step):"
                                                    : "Final state error |dm| + |dgamma| at T:");
    const double targets[] = {1e-6, 1e-9, 1e-12};
    for (double tg : targets) std::printf(" %.0e: h or tol | steps | CPU ms | ratio |", tg);
    std::printf("\n|---|");
    for (int i = 0; i < 3; ++i) std::printf("---|---|---|---|");
    std::printf("\n");
    std::vector<std::vector<Eval>> found(3);
    std::vector<std::vector<double>> cpu(3);
    for (int ti = 0; ti < 3; ++ti) {
      for (std::size_t i = 0; i < ms.size(); ++i) {
        const double start =
            ms[i].adaptive ? 1e-3
                           : (ti > 0 && found[ti - 1][i].ok ? found[ti - 1][i].param : r.h_max);
        found[ti].push_back(search(c, ms[i], targets[ti], energy_metric, start));
      }
      cpu[ti] = time_interleaved(c, ms, found[ti], energy_metric, rounds);
    }
    for (std::size_t i = 0; i < ms.size(); ++i) {
      std::printf("| %s |", ms[i].name.c_str());
      for (int ti = 0; ti < 3; ++ti) {
        const Eval& e = found[ti][i];
        const double best_peer = std::min(cpu[ti][ms.size() - 1], cpu[ti][ms.size() - 2]);
        if (!e.ok || !std::isfinite(cpu[ti][i])) {
          std::printf(" not reached | | | |");
        } else {
          std::printf(" %.3g | %lld | %.3g |", e.param, (long long)e.steps, 1e3 * cpu[ti][i]);
          if (std::isfinite(best_peer)) {
            std::printf(" %.2f |", cpu[ti][i] / best_peer);
          } else {
            std::printf(" no peer |");  // no odeint method reached this target
          }
        }
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "abc";
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 7;
  FILE* data = argc > 3 ? std::fopen(argv[3], "w") : nullptr;
  if (argc > 4) max_steps = std::atoll(argv[4]);
  if (argc > 5) only = argv[5];
  if (data) std::fprintf(data, "regime,metric,method,setting,steps,error,cpu_s\n");
  std::printf(
      "Work–precision (ratio: CPU time over the best odeint peer's at the same target; "
      "%d timing rounds; fixed-step runs above %lld steps not tried)\n",
      rounds, (long long)max_steps);
  if (which.find('a') != std::string::npos) run_regime(generic(), rounds, data);
  if (which.find('b') != std::string::npos) {
    run_regime(fast_spin(1e-3, "b3"), rounds, data);
    run_regime(fast_spin(1e-5, "b5"), rounds, data);
  }
  if (which.find('c') != std::string::npos) run_regime(libration(), rounds, data);
  if (data) std::fclose(data);
  return 0;
}
