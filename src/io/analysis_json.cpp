#include "newtop/io/analysis_json.hpp"

#include <cmath>
#include <optional>
#include <string>

namespace newtop::io {
namespace {

template <class T>
Json optional_value(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

}  // namespace

Json to_json(const StabilityReport& r, const Body& body) {
  const Spectrum& sp = r.spectrum;
  Json j;
  j["eigenvalues"] = Json::array();
  for (const auto& z : sp.eigenvalues) j["eigenvalues"].push_back({z.real(), z.imag()});
  j["max_real_part"] = sp.max_real_part;
  j["linearly_stable"] = sp.linearly_stable;
  j["lyapunov_stable"] = optional_value(sp.lyapunov_stable);
  j["threshold_omega_formula"] = optional_value(r.threshold_formula);
  j["threshold_omega_numeric"] = optional_value(r.threshold_numeric);
  j["axis"] = r.axis ? Json(std::string(1, "xyz"[*r.axis])) : Json(nullptr);
  j["axis_class"] = r.axis ? Json(to_string(axis_class(body, *r.axis))) : Json(nullptr);
  j["omega"] = to_json(omega(body, r.state));
  j["gamma"] = to_json(r.state.gamma);
  j["residual"] = r.residual;
  j["polish"] = {{"residual_given", r.polish.residual_given},
                 {"correction", r.polish.correction},
                 {"iterations", r.polish.iterations}};
  return j;
}

Json to_json(const EquilibriumSet& set) {
  Json list = Json::array();
  int index = 0;
  for (const auto& e : set.equilibria) {
    Json j;
    j["index"] = ++index;  // 1-based, the K of newtop stability --equilibrium K
    j["gamma"] = to_json(e.gamma);
    j["kappa"] = e.kappa;
    j["potential"] = e.potential;
    j["type"] = to_string(e.type);
    j["hessian_eigenvalues"] = {e.hessian[0], e.hessian[1]};
    if (!std::isnan(e.staude_residual)) {  // the quadratic field's Staude cone
      j["staude_generator"] = to_json(e.gamma);
      j["staude_residual"] = e.staude_residual;
    }
    list.push_back(j);
  }
  Json circles = Json::array();
  for (const auto& c : set.circles) {
    circles.push_back({{"axis", std::string(1, "xyz"[c.axis])},
                       {"gamma_axis", c.gamma_axis},
                       {"kappa", c.kappa},
                       {"potential", c.potential}});
  }
  Json j;
  j["equilibria"] = list;
  j["count"] = set.equilibria.size();
  j["every_orientation"] = set.every_orientation;
  j["circles"] = circles;
  j["minima"] = set.minima;
  j["saddles"] = set.saddles;
  j["maxima"] = set.maxima;
  j["degenerate"] = set.degenerate;
  j["count_rule"] = {{"minima_minus_saddles_plus_maxima", set.euler_characteristic()},
                     {"holds", set.count_rule_holds()}};
  return j;
}

Json to_json(const std::vector<ScanPoint>& scan) {
  Json list = Json::array();
  for (const auto& p : scan) {
    list.push_back({{"omega", p.omega},
                    {"max_real_part", p.max_real_part},
                    {"linearly_stable", p.linearly_stable},
                    {"lyapunov_stable", optional_value(p.lyapunov_stable)}});
  }
  return list;
}

void write_csv(std::ostream& os, const std::vector<ScanPoint>& scan) {
  os << "omega,max_real_part,linearly_stable,energy_casimir_stable\n";
  for (const auto& p : scan) {
    os << format_number(p.omega) << ',' << format_number(p.max_real_part) << ','
       << (p.linearly_stable ? 1 : 0) << ',' << (p.lyapunov_stable.value_or(false) ? 1 : 0) << '\n';
  }
}

void write_csv(std::ostream& os, const StabilityGrid& g) {
  os << g.first_name << ',' << g.second_name << ",max_real_part,verdict\n";
  const std::size_t n2 = g.second.size();
  for (std::size_t p = 0; p < g.verdict.size(); ++p) {
    const bool physical = g.verdict[p] != GridVerdict::nonphysical;
    os << format_number(g.first[p / n2]) << ',' << format_number(g.second[p % n2]) << ','
       << (physical ? format_number(g.max_real_part[p]) : "nan") << ',' << to_string(g.verdict[p])
       << '\n';
  }
}

}  // namespace newtop::io
