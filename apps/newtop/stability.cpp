// newtop stability SCENARIO.toml: linear and energy–Casimir stability of the scenario's initial
// state (an equilibrium or a permanent rotation) or of the spin --axis/--omega (docs/model.md
// §7–§9); stability diagrams along Ω (--scan-omega) or over two parameters (--scan).

#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "newtop/analysis/stability_report.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/io/analysis_json.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/io/stability_text.hpp"
#include "newtop/sweep/stability_grid.hpp"
#include "orbit_commands.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct StabilityArgs {
  std::string scenario;
  std::optional<std::string> axis, scan_omega, scan, out, diagram;
  std::optional<double> omega;
  std::optional<int> equilibrium;  // 1-based, as `newtop equilibria` numbers its list
  bool json = false;
};

std::optional<int> parse_axis(const std::optional<std::string>& axis) {
  if (!axis) return std::nullopt;
  if (*axis == "x") return 0;
  if (*axis == "y") return 1;
  if (*axis == "z") return 2;
  throw InputError("--axis: expected x, y or z, found '" + *axis + "'");
}

/// The command line's words for a fixed point the library could not analyse: the options and
/// the scenario named.
std::string choice_message(const StabilityChoiceError& e, const io::Scenario& sc,
                           const StabilityArgs& a) {
  using Reason = StabilityChoiceError::Reason;
  switch (e.reason) {
    case Reason::no_equilibrium:
      return "--equilibrium: " + sc.source + " has no isolated equilibrium" +
             (e.every_orientation ? " (every orientation is an equilibrium)" : "");
    case Reason::equilibrium_index:
      return "--equilibrium: expected 1 to " + std::to_string(e.count) +
             " (the equilibria listed by newtop equilibria), found " +
             std::to_string(*a.equilibrium);
    default:
      return (a.equilibrium ? "--equilibrium " + std::to_string(*a.equilibrium)
                            : sc.source + ": [initial]") +
             ": expected an equilibrium or a permanent rotation (to three digits or more), " +
             polish_failure(e.polish) +
             "; see newtop equilibria (and --equilibrium K) / rotations, or use --axis and "
             "--omega";
  }
}

/// The report of the state to analyse: --axis (exact), --equilibrium or [initial] (polished by
/// Newton); the library analyses it, the messages name the options.
StabilityReport chosen_report(const io::Scenario& sc, const StabilityArgs& a) {
  const std::optional<int> axis = parse_axis(a.axis);
  if (a.omega && !axis) throw InputError("--omega: needs --axis x|y|z to say which axis spins");
  if (a.equilibrium && axis) throw InputError("--equilibrium: give either --equilibrium or --axis");
  if (axis) {
    try {
      return stability_of_axis(sc.model, *axis, a.omega.value_or(0.0));
    } catch (const InputError& e) {
      throw InputError("--" + std::string(e.what()));
    }
  }
  try {
    return a.equilibrium ? stability_of_equilibrium(sc.model, *a.equilibrium)
                         : stability_of_state(sc.model, sc.initial);
  } catch (const StabilityChoiceError& e) {
    throw InputError(choice_message(e, sc, a));
  }
}

int run(const StabilityArgs& a) {
  if (a.diagram) {
    if (!a.scenario.empty() || a.axis || a.omega || a.scan_omega || a.equilibrium) {
      throw InputError(
          "--diagram: takes no scenario, --axis, --omega, --equilibrium or --scan-omega (only "
          "--scan, "
          "--out, --json)");
    }
    return stability_diagram(*a.diagram, a.scan, a.out, a.json);
  }
  if (a.scenario.empty())
    throw InputError("scenario: missing: give a scenario file (or --diagram)");
  if (io::is_orbit_scenario(a.scenario)) {
    if (a.axis || a.omega || a.scan_omega || a.scan || a.out) {
      throw InputError(
          "--axis, --omega, --scan-omega, --scan, --out: not available on an orbit scenario (its "
          "initial state, or --equilibrium K, must be a relative equilibrium)");
    }
    return orbit_stability(a.scenario, a.json, a.equilibrium);
  }
  // Every option is checked before any work is done.
  if (a.scan && a.scan_omega) {
    throw InputError("--scan: give either --scan or --scan-omega, not both");
  }
  if (a.scan && !a.out) throw InputError("--scan: needs --out FILE for the CSV diagram");
  if (a.out && !a.scan && !a.scan_omega) {
    throw InputError("--out: needs --scan-omega or --scan (the diagram it holds)");
  }
  const std::optional<io::Range> omega_range =
      a.scan_omega ? std::optional(io::parse_range("--scan-omega", *a.scan_omega, false))
                   : std::nullopt;
  const std::optional<std::pair<io::Range, io::Range>> grid =
      a.scan ? std::optional(io::parse_grid(*a.scan)) : std::nullopt;
  const io::Scenario sc = io::load_scenario(a.scenario);
  if (a.axis || a.scan || a.scan_omega) {
    require_quadratic(sc.model, sc.source,
                      std::string(a.axis   ? "--axis"
                                  : a.scan ? "--scan"
                                           : "--scan-omega") +
                          " (spins about principal axes and their thresholds)");
  }
  const StabilityReport c = chosen_report(sc, a);
  if ((a.scan_omega || a.scan) && !c.axis) {
    throw InputError(
        std::string(a.scan ? "--scan" : "--scan-omega") +
        ": needs a spin about a principal axis: give --axis x|y|z (with M g r0 along it)");
  }
  // The diagram's file is created (and checked against the inputs) before any work.
  std::unique_ptr<io::AtomicFile> file;
  if (a.out) file = std::make_unique<io::AtomicFile>(*a.out, sc.input_files);
  io::Json j = io::to_json(c, sc.model.body());
  if (a.equilibrium) j["equilibrium"] = *a.equilibrium;
  if (omega_range) {
    const auto& r = *omega_range;
    const std::vector<ScanPoint> scan = scan_omega(sc.model.quadratic(), *c.axis, r.lo, r.hi, r.n);
    j["scan"] = io::to_json(scan);
    if (file) io::write_csv(file->stream(), scan);
  }
  if (grid) {
    const auto& [r1, r2] = *grid;
    io::write_csv(file->stream(),
                  sweep::stability_grid(sc.model.quadratic(), *c.axis, a.omega.value_or(0.0),
                                        {r1.name, r1.values()}, {r2.name, r2.values()}));
  }
  if (file) file->commit();
  if (a.out) j["csv"] = *a.out;
  j["model"] = model_json(sc.model);
  j["field"] = field_json(sc.model);
  if (a.json) {
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop stability " << sc.source << "\n";
  print_model(std::cout, sc.model);
  if (a.equilibrium) std::cout << "equilibrium " << *a.equilibrium << " of newtop equilibria\n";
  io::write_stability_text(std::cout, j, c.formula_note);
  if (omega_range) {
    print_units_line(
        std::cout);  // before the table, so that the table ends the output (as sweep's)
    io::write_omega_scan_text(std::cout, j["scan"]);
  }
  if (a.out) std::cout << "diagram written to " << *a.out << "\n";
  return kExitOk;
}

const RegisterCommand reg_stability{Command{
    "stability",
    "Linear and energy-Casimir stability of an equilibrium or permanent rotation; diagrams",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<StabilityArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML); none with --diagram");
      sub.add_option("--axis", a->axis,
                     "analyse the spin about this principal axis (x, y or z), "
                     "pointing at the centre, instead of the initial state");
      sub.add_option("--omega", a->omega, "spin rate Omega about --axis (default 0)");
      sub.add_option("--equilibrium", a->equilibrium,
                     "analyse the K-th equilibrium listed by newtop equilibria (K = 1, 2, ...)");
      sub.add_option("--scan-omega", a->scan_omega, "W1:W2:N: stability along Omega (JSON, CSV)");
      sub.add_option("--scan", a->scan,
                     "P1=LO:HI:N,P2=LO:HI:M with P in omega, lambda, A, B, C: 2-D diagram to CSV");
      sub.add_option("--out", a->out, "CSV file for --scan-omega, --scan or --diagram");
      sub.add_option("--diagram", a->diagram,
                     "debra-delp: the DeBra-Delp diagram of a gravity-gradient satellite over "
                     "--scan k_R=LO:HI:N,k_Y=LO:HI:M (default -0.99:0.99:67 each)");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
