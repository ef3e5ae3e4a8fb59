// newtop find-integrals SCENARIO.toml: numerical search for first integrals polynomial in (ω, γ).
// An optional --potential FILE.toml replaces the scenario's V(γ) by a general polynomial
// (newtop/io/potential_file.hpp).

#include "newtop/analysis/find_integrals.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/potential_file.hpp"
#include "newtop/io/scenario.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct FindArgs {
  std::string scenario;
  int degree = 2;
  int points = 0;
  std::optional<std::string> potential;
  bool json = false;
};

io::Json search_json(const IntegralSearch& s) {
  io::Json list = io::Json::array();
  for (const auto& i : s.integrals) {
    io::Json c = io::Json::object();
    for (std::size_t k = 0; k < s.monomials.size(); ++k) {
      if (i.coefficients[k] != 0.0) c[to_string(s.monomials[k])] = i.coefficients[k];
    }
    list.push_back({{"name", i.name ? io::Json(*i.name) : io::Json(nullptr)}, {"coefficients", c}});
  }
  io::Json j;
  j["degree"] = s.degree;
  j["monomials"] = s.monomials.size();
  j["integrals"] = list;
  j["rank"] = s.rank;
  j["independent_integrals"] = s.integrals.size();
  j["gap"] = std::isfinite(s.gap) ? io::Json(s.gap) : io::Json(nullptr);
  j["singular_values"] = s.singular_values;
  return j;
}

void print_search(const IntegralSearch& s) {
  std::cout << "degree    " << s.degree << " (" << s.monomials.size() << " monomials)\n"
            << "rank      " << s.rank << "; null space " << s.integrals.size()
            << "; singular-value gap " << format_number(s.gap) << "\n";
  for (const auto& i : s.integrals) {
    if (i.name) {
      std::cout << "  found " << *i.name << "\n";
      continue;
    }
    std::cout << "  new integral:";
    for (std::size_t k = 0; k < s.monomials.size(); ++k) {
      if (i.coefficients[k] != 0.0) {
        std::cout << " " << (i.coefficients[k] > 0 ? "+" : "") << format_number(i.coefficients[k])
                  << "*" << to_string(s.monomials[k]);
      }
    }
    std::cout << "\n";
  }
}

int run(const FindArgs& a) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  if (!a.potential) {
    require_quadratic(sc.model, sc.source, "newtop find-integrals (without --potential)");
  }
  const SearchOptions opt{.degree = a.degree, .points = a.points};
  const IntegralSearch s =
      a.potential ? find_integrals(
                        BasicModel<PolynomialPotential>{
                            sc.model.body(), io::load_potential(*a.potential, sc.model.body())},
                        opt)
                  : find_integrals(sc.model.quadratic(), opt);
  if (a.json) {
    io::Json j = search_json(s);
    if (!a.potential) j["field"] = field_json(sc.model);
    print_json(std::cout, j);
  } else {
    std::cout << "newtop find-integrals " << sc.source
              << (a.potential ? " with V(gamma) from " + *a.potential : std::string()) << "\n";
    print_search(s);
  }
  return kExitOk;
}

const RegisterCommand reg_find_integrals{Command{
    "find-integrals", "Search numerically for first integrals polynomial in (omega, gamma)",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<FindArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML)")->required();
      sub.add_option("--degree", a->degree, "highest total degree (default 2, at most 6)");
      sub.add_option("--points", a->points, "random phase points (default 3 x monomials)");
      sub.add_option("--potential", a->potential,
                     "TOML file with [potential] terms = [[c, i, j, k], ...] replacing V(gamma)");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
