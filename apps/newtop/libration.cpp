// newtop libration SCENARIO.toml: planar pitch motion on an elliptic orbit (Beletsky's equation,
// docs/orbit.md §9): the p:q spin–orbit resonances as periodic solutions with their Floquet
// multipliers, and the periapsis section with a finite-time Lyapunov exponent per start.

#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "interrupt.hpp"
#include "newtop/io/libration_json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/libration_report.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct LibrationArgs {
  std::string scenario;
  std::string resonances = "1:2,1:1,3:2,2:1,5:2";
  std::optional<std::string> spin, out;
  int iterates = 200;
  bool asymmetric = false;
  bool json = false;
};

void print_solution(const PeriodicSolution& s, const char* label) {
  std::cout << "  " << label << "theta(0) = " << format_number(s.theta0)
            << "  theta'(0) = " << format_number(s.dtheta0)
            << "  trace = " << format_number(s.monodromy.trace()) << "  " << to_string(s.stability)
            << "\n";
}

void print_report(const io::OrbitScenario& sc, const LibrationReport& r,
                  const std::optional<std::string>& out) {
  std::cout << "newtop libration " << sc.source << "\n  e = " << format_number(r.eccentricity)
            << ", k = (B - A)/C = " << format_number(r.k) << "\n";
  for (const LibrationResonance& x : r.resonances) {
    std::cout << "resonance " << x.resonance.p << ":" << x.resonance.q
              << "  H = " << format_number(x.strength) << ", averaged half-width "
              << format_number(x.averaged_half_width) << "\n";
    for (const PeriodicSolution& s : x.solutions) print_solution(s, "");
    if (x.asymmetric_solutions) {
      for (const PeriodicSolution& s : *x.asymmetric_solutions) print_solution(s, "asymmetric: ");
    }
  }
  std::cout << r.starts.size() << " starts, " << r.iterates << " orbits each: " << r.chaotic_starts
            << " chaotic (Lyapunov exponent > " << format_number(r.chaos_threshold)
            << " per orbit)\n";
  if (out) std::cout << "section written to " << *out << "\n";
}

int run_guarded(const LibrationArgs& a) {
  const io::OrbitScenario sc = io::load_orbit_scenario(a.scenario);
  LibrationRequest request;
  request.resonances = io::parse_resonances(a.resonances);
  request.iterates = a.iterates;
  request.asymmetric = a.asymmetric;
  if (a.spin) {
    const io::SpinScan scan = io::parse_spin(*a.spin);
    request.spin = SpinStarts{scan.lo, scan.hi, scan.n};
  }
  request.on_step = throw_if_interrupted;
  pitch_orbit(sc.orbit, sc.source + ": ");  // bad input before the output file is opened
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) {
    const std::string inputs[] = {a.scenario};
    file = std::make_unique<io::AtomicFile>(*a.out, inputs);
  }
  const LibrationReport r =
      libration_report(sc.body, sc.orbit, sc.initial, request, sc.source + ": ");
  if (file) {
    io::write_csv(file->stream(), r);
    file->commit();
  }
  if (a.json) {
    print_json(std::cout, io::to_json(r, sc.source, a.out));
  } else {
    print_report(sc, r, a.out);
  }
  return kExitOk;
}

/// SIGINT/SIGTERM between resonances or starts: the CSV under construction is removed, exit
/// 128 + the signal.
int run(const LibrationArgs& a) {
  const InterruptGuard guard;
  try {
    return run_guarded(a);
  } catch (const Interrupted& e) {
    std::cerr << "newtop: interrupted by " << signal_name(e.signal)
              << (a.out ? "; the output file was not written" : "") << '\n';
    return 128 + e.signal;
  }
}

const RegisterCommand reg_libration{Command{
    "libration",
    "Planar pitch on an elliptic orbit: spin-orbit resonances, Floquet multipliers, periapsis "
    "section",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<LibrationArgs>();
      sub.add_option("scenario", a->scenario,
                     "orbit scenario file (TOML), elliptic (or circular, as e = 0)")
          ->required();
      sub.add_option("--resonances", a->resonances,
                     "p:q list (spin:orbit), default " + a->resonances);
      sub.add_option("--spin", a->spin,
                     "LO:HI:N section starts at periapsis, theta = 0, spin rate in units of n");
      sub.add_option("--iterates", a->iterates, "orbits per start (default 200)");
      sub.add_flag("--asymmetric", a->asymmetric,
                   "also find periodic solutions without the symmetry assumption (2-D shooting "
                   "from a 12 x 12 grid of starts)");
      sub.add_option("--out", a->out, "section CSV file");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
