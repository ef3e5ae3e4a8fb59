// newtop chaos SCENARIO.toml: Lyapunov exponents, MEGNO and FLI from the tangent map of the
// integrator (docs/chaos.md).

#include "newtop/phase/chaos.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "integration_options.hpp"
#include "interrupt.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "orbit_commands.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct ChaosArgs {
  std::string scenario;
  IntegrationArgs integration;
  bool spectrum = false;
  std::optional<std::string> out;
  bool json = false;
};

/// The history keeps at most this many rows of a fixed-step run (every step of a shorter run; an
/// adaptive run's every accepted step).
constexpr std::int64_t kHistoryRows = 10000;

void write_row(std::ostream& os, const phase::ChaosSample& s) {
  os << format_number(s.t) << ',' << format_number(s.lyapunov_max) << ','
     << format_number(s.megno_y) << ',' << format_number(s.megno) << ',' << format_number(s.fli);
  if (s.spectrum) {
    for (double v : *s.spectrum) os << ',' << format_number(v);
  }
  os << '\n';
}

int run(const ChaosArgs& a) {
  if (io::is_orbit_scenario(a.scenario)) {
    const IntegrationArgs& i = a.integration;
    return orbit_chaos_command(
        {a.scenario, i.t_end, i.step, i.tol, i.method, i.split, a.out, a.spectrum, a.json});
  }
  const io::Scenario sc = load_body_scenario(a.scenario);
  const RunSettings run = resolve_run(sc, a.integration);
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) {
    file = std::make_unique<io::AtomicFile>(*a.out, sc.input_files);
    file->stream() << "t,lyapunov_max,megno_y,megno,fli";
    if (a.spectrum) file->stream() << ",lambda1,lambda2,lambda3,lambda4,lambda5,lambda6";
    file->stream() << '\n';
  }
  phase::ChaosRequest request{.method = run.method,
                              .t0 = run.t0,
                              .t_end = run.t_end,
                              .spectrum = a.spectrum,
                              .options = run.options};
  if (file) {
    request.history = [&](const phase::ChaosSample& s) { write_row(file->stream(), s); };
    request.history_rows = kHistoryRows;
  }
  request.on_step = throw_if_interrupted;

  const InterruptGuard guard;
  phase::ChaosResult r;
  try {
    r = phase::chaos(sc.model, sc.initial, request);
  } catch (const Interrupted& e) {
    std::cerr << "newtop: interrupted by " << signal_name(e.signal)
              << " at t = " << format_number(e.t)
              << (a.out ? "; the output file was not written" : "") << '\n';
    return 128 + e.signal;
  }
  if (file) file->commit();
  const phase::ChaosSample& c = r.indicators;
  const bool adaptive = method_info(run.method.name).kind == MethodKind::adaptive;
  const std::optional<std::string> split = split_of(run.method);
  if (a.json) {
    io::Json j;
    j["lyapunov_max"] = c.lyapunov_max;
    j["spectrum"] = c.spectrum ? io::Json(*c.spectrum) : io::Json(nullptr);
    j["megno"] = c.megno;
    j["fli"] = c.fli;
    j["t_end"] = r.outcome.t;
    j["method"] = run.method.name;
    j["step"] = adaptive ? io::Json(nullptr) : io::Json(run.method.step);
    if (adaptive) j["tol"] = run.method.abs_tol;
    if (split) j["split"] = *split;
    j["outcome"] = to_string(r.outcome.status);
    j["flow"] = run.t_end > run.t0 ? "forward" : "backward";
    print_json(std::cout, j);
  } else {
    std::cout << "lambda_max = " << format_number(c.lyapunov_max)
              << "   MEGNO <Y> = " << format_number(c.megno) << "   FLI = " << format_number(c.fli)
              << "\n";
    if (c.spectrum) {
      std::cout << "spectrum:";
      for (double v : *c.spectrum) std::cout << ' ' << format_number(v);
      std::cout << '\n';
    }
    std::cout << "t = " << format_number(r.outcome.t)
              << (run.t_end < run.t0
                      ? " (the backward flow from t0 = " + format_number(run.t0) + ")"
                      : std::string())
              << ", method " << run.method.name << (adaptive ? ", tol " : ", step ")
              << format_number(adaptive ? run.method.abs_tol : run.method.step)
              << (split ? " (" + *split + " split)" : std::string()) << ", outcome "
              << to_string(r.outcome.status) << '\n';
    if (a.out) std::cout << "history written to " << *a.out << '\n';
  }
  return r.outcome.status == Status::finished ? kExitOk : kExitIncomplete;
}

const RegisterCommand reg{Command{
    "chaos",
    "Chaos indicators: Lyapunov exponents, MEGNO and FLI from the integrator's tangent map",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<ChaosArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      add_integration_options(sub, a->integration);
      sub.add_flag("--spectrum", a->spectrum, "the full spectrum (Benettin's QR on 6 vectors)");
      sub.add_option("--out", a->out, "write the history of the indicators to this CSV file");
      sub.add_flag("--json", a->json, "print one JSON object instead of the summary");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
