#include "newtop/io/orbit_json.hpp"

#include "newtop/model/attitude.hpp"
#include "newtop/orbit/lvlh.hpp"

namespace newtop::io {

Json to_json(const RelativeSpectrum& sp) {
  Json list = Json::array();
  for (const auto& z : sp.eigenvalues) list.push_back({z.real(), z.imag()});
  Json j;
  j["eigenvalues"] = list;
  j["max_real_part"] = sp.max_real_part;
  j["linearly_stable"] = sp.linearly_stable;
  j["lyapunov_stable"] = sp.verdict == OrbitStability::lyapunov   ? Json(true)
                         : sp.verdict == OrbitStability::unstable ? Json(false)
                                                                  : Json(nullptr);
  j["verdict"] = to_string(sp.verdict);
  return j;
}

Json to_json(const RelativeEquilibriumSet& set) {
  Json list = Json::array();
  int number = 0;
  for (const auto& e : set.equilibria) {
    const Mat3 C = lvlh_to_body(OrbitState{Vec3::Zero(), e.gamma, e.normal});
    Json j{{"number", ++number},
           {"gamma", to_json(e.gamma)},
           {"normal", to_json(e.normal)},
           {"lvlh_quaternion", scalar_first(lvlh_quaternion(C))},
           {"roll_pitch_yaw", to_json(roll_pitch_yaw(C))},
           {"jacobi", e.jacobi},
           {"residual", e.residual}};
    j.update(to_json(e.stability));
    list.push_back(j);
  }
  return Json{{"equilibria", list},
              {"count", set.equilibria.size()},
              {"lyapunov", set.lyapunov},
              {"gyroscopic", set.gyroscopic},
              {"unstable", set.unstable}};
}

Json to_json(const RelativeStabilityReport& r) {
  Json j = to_json(r.spectrum);
  j["characteristic_polynomial"] = Json::array();
  for (int k = 0; k < 7; ++k)
    j["characteristic_polynomial"].push_back(r.spectrum.characteristic[k]);
  j["omega"] = to_json(r.omega);
  j["gamma"] = to_json(r.state.gamma);
  j["normal"] = to_json(r.state.normal);
  j["jacobi"] = r.jacobi;
  j["residual"] = r.residual;
  return j;
}

Json to_json(const DebraDelpDiagram& d) {
  Json list = Json::array();
  for (const auto& p : d.points) {
    list.push_back({{"k_R", p.k_R},
                    {"k_Y", p.k_Y},
                    {"region", to_string(p.computed)},
                    {"closed_form", to_string(p.closed_form)},
                    {"boundary", p.boundary},
                    {"max_real_part", p.max_real_part}});
  }
  return Json{{"diagram", "debra-delp"},
              {"parameters",
               "k_R = (B - C)/A, k_Y = (B - A)/C; A roll (velocity), B pitch "
               "(orbit normal), C yaw (radius)"},
              {"points", list},
              {"counts",
               {{"lagrange", d.counts[0]}, {"debra_delp", d.counts[1]}, {"unstable", d.counts[2]}}},
              {"disagreements_with_closed_form", d.disagreements_with_closed_form}};
}

void write_csv(std::ostream& os, const DebraDelpDiagram& d) {
  os << "k_R,k_Y,region,closed_form,boundary,max_real_part\n";
  for (const auto& p : d.points) {
    os << format_number(p.k_R) << ',' << format_number(p.k_Y) << ',' << to_string(p.computed) << ','
       << to_string(p.closed_form) << ',' << (p.boundary ? "true" : "false") << ','
       << format_number(p.max_real_part) << '\n';
  }
}

}  // namespace newtop::io
