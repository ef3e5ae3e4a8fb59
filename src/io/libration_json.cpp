#include "newtop/io/libration_json.hpp"

namespace newtop::io {
namespace {

Json solution_json(const PeriodicSolution& s, double e) {
  Json m = Json::array();
  for (const auto& z : s.multipliers) m.push_back({z.real(), z.imag()});
  return {{"theta0", s.theta0},
          {"dtheta0", s.dtheta0},
          {"spin0", spin_from_dtheta(e, s.dtheta0)},
          {"multipliers", m},
          {"trace", s.monodromy.trace()},
          {"stability", to_string(s.stability)},
          {"residual", s.residual},
          {"max_deviation", s.max_deviation},
          {"symmetry_distance", s.symmetry_distance},
          {"symmetric", s.symmetry_distance <= kSymmetryTolerance}};
}

Json resonance_json(const LibrationResonance& r, double e) {
  Json sols = Json::array();
  for (const PeriodicSolution& s : r.solutions) sols.push_back(solution_json(s, e));
  Json entry{{"resonance", std::to_string(r.resonance.p) + ":" + std::to_string(r.resonance.q)},
             {"spin_ratio", r.spin_ratio},
             {"periods", r.resonance.periods},
             {"half_turns", r.resonance.half_turns},
             {"strength", r.strength},
             {"averaged_half_width", r.averaged_half_width},
             {"solutions", sols}};
  if (r.asymmetric_solutions) {
    Json asym = Json::array();
    for (const PeriodicSolution& s : *r.asymmetric_solutions) asym.push_back(solution_json(s, e));
    entry["asymmetric_solutions"] = asym;
  }
  return entry;
}

}  // namespace

Json to_json(const LibrationReport& r, const std::string& scenario,
             const std::optional<std::string>& csv) {
  const double e = r.eccentricity;
  Json res = Json::array();
  for (const LibrationResonance& x : r.resonances) res.push_back(resonance_json(x, e));
  Json section = Json::array();
  for (std::size_t i = 0; i < r.starts.size(); ++i) {
    const SectionOrbit& o = r.starts[i];
    section.push_back({{"start", i},
                       {"theta0", o.theta0},
                       {"dtheta0", o.dtheta0},
                       {"spin0", spin_from_dtheta(e, o.dtheta0)},
                       {"lyapunov", o.lyapunov},
                       {"chaotic", o.chaotic}});
  }
  Json j{{"scenario", scenario},
         {"eccentricity", e},
         {"k", r.k},
         {"iterates", r.iterates},
         {"chaos_threshold", r.chaos_threshold},
         {"resonances", res},
         {"starts", section},
         {"chaotic_starts", r.chaotic_starts}};
  if (csv) j["csv"] = *csv;
  return j;
}

void write_csv(std::ostream& os, const LibrationReport& r) {
  const double e = r.eccentricity;
  os << "start,orbit,theta,dtheta,spin,lyapunov,chaotic\n";
  for (std::size_t i = 0; i < r.starts.size(); ++i) {
    const SectionOrbit& o = r.starts[i];
    for (std::size_t j = 0; j < o.points.size(); ++j) {
      const Vec2& x = o.points[j];
      os << i << ',' << j + 1 << ',' << format_number(x[0]) << ',' << format_number(x[1]) << ','
         << format_number(spin_from_dtheta(e, x[1])) << ',' << format_number(o.lyapunov) << ','
         << (o.chaotic ? 1 : 0) << '\n';
    }
  }
}

}  // namespace newtop::io
