// newtop integrals SCENARIO.toml: the first integrals at the initial state and which are conserved.

#include <iostream>
#include <memory>

#include "command.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "orbit_commands.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct IntegralsArgs {
  std::string scenario;
  bool json = false;
};

int run(const IntegralsArgs& a) {
  if (io::is_orbit_scenario(a.scenario)) return orbit_integrals(a.scenario, a.json);
  const io::Scenario sc = io::load_scenario(a.scenario);
  const IntegralValues v = integrals(sc.model, sc.initial);
  const auto conserved = conserved_integrals(sc.model);
  if (a.json) {
    io::Json j;
    j["integrals"] = io::to_json(v);
    j["conserved"] = conserved;
    j["model"] = model_json(sc.model);
    j["field"] = field_json(sc.model);
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop integrals " << sc.source << "\n";
  print_model(std::cout, sc.model);
  std::cout << "energy     " << format_number(v.energy) << "\narea       " << format_number(v.area)
            << "\ngeometric  " << format_number(v.geometric) << "\n";
  if (v.brun) std::cout << "brun       " << format_number(*v.brun) << "\n";
  if (v.lagrange) std::cout << "lagrange   " << format_number(*v.lagrange) << "\n";
  std::cout << "conserved:";
  for (const auto& c : conserved) std::cout << " " << c;
  std::cout << "\n";
  return kExitOk;
}

const RegisterCommand reg_integrals{Command{
    "integrals", "First integrals at the initial state, and which are conserved for the model",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<IntegralsArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
