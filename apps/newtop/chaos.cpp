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
#include "newtop/io/chaos_output.hpp"
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
    io::write_chaos_csv_header(file->stream(), a.spectrum);
  }
  phase::ChaosRequest request{.method = run.method,
                              .t0 = run.t0,
                              .t_end = run.t_end,
                              .spectrum = a.spectrum,
                              .options = run.options};
  if (file) {
    request.history = [&](const phase::ChaosSample& s) {
      io::write_chaos_csv_row(file->stream(), s);
    };
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
  if (a.json) {
    print_json(std::cout, io::to_json(r, request));
  } else {
    io::write_chaos_text(std::cout, r, request);
    if (a.out) std::cout << "history written to " << *a.out << '\n';
  }
  return r.outcome.status == Status::finished ? kExitOk : kExitIncomplete;
}

const RegisterCommand reg_chaos{Command{
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
