// newtop find-integrals SCENARIO.toml: numerical search for first integrals polynomial in (ω, γ).
// An optional --potential FILE.toml replaces the scenario's V(γ) by a general polynomial:
//   [potential]
//   terms = [[coefficient, i, j, k], ...]   # V = Σ coefficient γ1^i γ2^j γ3^k

#include "newtop/analysis/find_integrals.hpp"

#include <toml++/toml.h>

#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::app {
namespace {

constexpr int kMaxPotentialDegree = 8;

struct FindArgs {
  std::string scenario;
  int degree = 2;
  int points = 0;
  std::optional<std::string> potential;
  bool json = false;
};

[[noreturn]] void bad_term(const std::string& path, std::size_t i, const std::string& what) {
  throw InputError(path + ": [potential] terms[" + std::to_string(i) + "]: " + what);
}

PolynomialPotential read_potential(const std::string& path) {
  toml::table doc;
  try {
    doc = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line) +
                     ": malformed TOML: " + std::string(e.description()));
  }
  const toml::table* pot = doc["potential"].as_table();
  if (!pot) throw InputError(path + ": [potential]: missing section");
  for (const auto& [key, node] : *pot) {
    if (key.str() != "terms") {
      throw InputError(path + ": [potential] " + std::string(key.str()) +
                       ": unknown key (expected only terms)");
    }
  }
  const toml::array* terms = (*pot)["terms"].as_array();
  if (!terms) throw InputError(path + ": [potential] terms: expected an array of [c, i, j, k]");
  PolynomialPotential v;
  for (std::size_t i = 0; i < terms->size(); ++i) {
    const toml::array* t = (*terms)[i].as_array();
    if (!t || t->size() != 4) bad_term(path, i, "expected [coefficient, i, j, k]");
    const auto c = (*t)[0].value<double>();
    if (!c || !std::isfinite(*c)) bad_term(path, i, "expected a finite coefficient");
    PotentialTerm term{*c, {}};
    for (int k = 0; k < 3; ++k) {
      const auto e = (*t)[k + 1].value<std::int64_t>();
      if (!e || *e < 0 || *e > kMaxPotentialDegree) {
        bad_term(path, i,
                 "expected integer exponents in 0.." + std::to_string(kMaxPotentialDegree));
      }
      term.power[k] = static_cast<int>(*e);
    }
    v.terms.push_back(term);
  }
  return v;
}

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
  const SearchOptions opt{.degree = a.degree, .points = a.points};
  const IntegralSearch s =
      a.potential
          ? find_integrals(
                BasicModel<PolynomialPotential>{sc.model.body, read_potential(*a.potential)}, opt)
          : find_integrals(sc.model, opt);
  if (a.json) {
    std::cout << search_json(s).dump(2) << '\n';
  } else {
    std::cout << "newtop find-integrals " << sc.source
              << (a.potential ? " with V(gamma) from " + *a.potential : std::string()) << "\n";
    print_search(s);
  }
  return kExitOk;
}

const RegisterCommand reg{Command{
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
