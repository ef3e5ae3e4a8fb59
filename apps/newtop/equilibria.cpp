// newtop equilibria SCENARIO.toml: every equilibrium of the body at rest (docs/model.md §7), its
// type and the count rule.

#include "newtop/analysis/equilibria.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "newtop/io/analysis_json.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "orbit_commands.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct EquilibriaArgs {
  std::string scenario;
  bool json = false;
};

void print_equilibria(std::ostream& os, const EquilibriumSet& set, FieldKind kind) {
  if (set.every_orientation) {
    os << "V is constant on the sphere: every orientation is an equilibrium\n";
    return;
  }
  os << set.equilibria.size() << " isolated equilibria (omega = 0)\n";
  os << "  #   type        gamma                                                        kappa"
        "                   V\n";
  int index = 0;
  for (const auto& e : set.equilibria) {
    os << "  " << std::left << std::setw(4) << ++index << std::setw(10) << to_string(e.type) << "  "
       << std::setw(60) << format_vector(e.gamma) << " " << std::setw(23) << format_number(e.kappa)
       << " " << format_number(e.potential) << "\n";
  }
  for (const auto& c : set.circles) {
    os << "  circle of equilibria: gamma_"
       << "xyz"[c.axis] << " = " << format_number(c.gamma_axis)
       << ", kappa = " << format_number(c.kappa) << ", V = " << format_number(c.potential) << "\n";
  }
  os << "count rule: minima - saddles + maxima = " << set.minima << " - " << set.saddles << " + "
     << set.maxima << " = " << set.euler_characteristic()
     << (set.count_rule_holds() ? " (holds)" : " (does not apply: degenerate points or families)")
     << "\n";
  if (kind == FieldKind::quadratic) {
    os << "each gamma is the generator of the Staude cone gamma.(I gamma x r0) = 0 through it\n";
  } else {
    os << "found on the sphere from the quadratic model's equilibria and " << kSphereStarts
       << " lattice starts; types from the Hessian of the " << to_string(kind) << " field\n";
  }
  if (!set.equilibria.empty()) {
    os << "newtop stability SCENARIO --equilibrium K analyses the K-th (K = 1 to "
       << set.equilibria.size() << ")\n";
  }
}

int run(const EquilibriaArgs& a) {
  if (io::is_orbit_scenario(a.scenario)) return orbit_equilibria(a.scenario, a.json);
  const io::Scenario sc = io::load_scenario(a.scenario);
  const EquilibriumSet set = find_equilibria(sc.model);
  if (a.json) {
    io::Json j = io::to_json(set);
    j["model"] = model_json(sc.model);
    j["field"] = field_json(sc.model);
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop equilibria " << sc.source << "\n";
  print_model(std::cout, sc.model);
  print_equilibria(std::cout, set, sc.model.kind());
  return kExitOk;
}

const RegisterCommand reg_equilibria{
    Command{"equilibria", "Every equilibrium at rest (omega = 0), its type and the count rule",
            [](CLI::App& sub) -> std::function<int()> {
              auto a = std::make_shared<EquilibriaArgs>();
              sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
              sub.add_flag("--json", a->json, "print one JSON object");
              return [a] { return run(*a); };
            }}};

}  // namespace
}  // namespace newtop::app
