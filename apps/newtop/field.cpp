// newtop field SCENARIO.toml --gamma g1,g2,g3: exact and quadratic field of a mass model at one
// orientation (docs/model.md §2, §3), and with --scan-R the error of the quadratic model against R.

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
#include "newtop/analysis/field_scan.hpp"
#include "newtop/exact/multipole.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

struct FieldArgs {
  std::string scenario;
  std::string gamma;
  std::optional<double> R;
  std::optional<std::string> scan;
  bool json = false;
};

io::Json values_json(const FieldSample& x);
void print_values(const char* name, const FieldSample& x);

/// One frame's values: gamma and the exact, approximate and difference values, labelled.
io::Json frame_json(const char* frame, const FieldComparison& c) {
  return {{"frame", frame},
          {"gamma", io::to_json(c.gamma)},
          {"exact", values_json(c.exact)},
          {"approx", values_json(c.approx)},
          {"difference", values_json(c.difference)}};
}

void print_frame(const FieldComparison& c) {
  print_values("exact ", c.exact);
  print_values("approx", c.approx);
  print_values("diff  ", c.difference);
}

io::Json matrix_json(const Mat3& m) {
  io::Json J = io::Json::array();
  for (int i = 0; i < 3; ++i) J.push_back(io::to_json(Vec3(m.row(i))));
  return J;
}

io::Json values_json(const FieldSample& x) {
  const FieldValues& v = x.values;
  return {{"potential", v.potential},
          {"grad_gamma", io::to_json(v.grad_gamma)},
          {"dV_dR", v.dV_dR},
          {"moment", io::to_json(v.moment)},
          {"force", io::to_json(v.force)},
          {"hessian_gamma", matrix_json(x.hessian)}};
}

io::Json mass_properties_json(const MassProperties& mp, const Body& body) {
  const Mat3& P = body.principal_axes();
  return {{"mass", mp.mass},
          {"center_of_mass", io::to_json(mp.center_of_mass)},
          {"inertia_tensor", matrix_json(mp.inertia_tensor)},
          {"principal_moments", io::to_json(body.inertia())},
          {"principal_axes",
           io::Json::array({io::to_json(P.col(0)), io::to_json(P.col(1)), io::to_json(P.col(2))})}};
}

void print_values(const char* name, const FieldSample& x) {
  const FieldValues& v = x.values;
  std::cout << name << "  V = " << format_number(v.potential)
            << "\n        dV/dgamma = " << format_vector(v.grad_gamma)
            << "\n        dV/dR = " << format_number(v.dV_dR)
            << "\n        L = " << format_vector(v.moment)
            << "\n        F = " << format_vector(v.force) << "\n        d2V/dgamma2 = ["
            << format_vector(Vec3(x.hessian.row(0))) << ", "
            << format_vector(Vec3(x.hessian.row(1))) << ", "
            << format_vector(Vec3(x.hessian.row(2))) << "]\n";
}

int run(const FieldArgs& a) {
  const io::Scenario sc = io::load_scenario(a.scenario);
  const std::shared_ptr<const MassModel>& mass_model = sc.model.mass_model();
  if (!mass_model)
    throw InputError(sc.source + ": [mass_model]: missing: newtop field needs a mass model");
  if (sc.model.kind() == FieldKind::quadratic && !a.R) {
    throw InputError(sc.source +
                     ": [field] kind: expected \"exact\" or \"multipole\" with mu and R, "
                     "or give --R");
  }
  const Vec3 given = io::parse_gamma(a.gamma);
  std::optional<RadiusRange> range;
  if (a.scan) {
    const io::RadiusScan s = io::parse_radius_scan(*a.scan);
    range = RadiusRange{s.R1, s.R2, s.n};
  }
  const FieldReport r = field_report(sc.model, given, a.R, range);
  const Body& body = sc.model.body();
  const FieldComparison& principal = r.principal;
  const FieldComparison& input = r.input;
  const double mu = r.mu, R = r.R;
  const Vec3& gamma = r.gamma;
  io::Json j;
  j["scenario"] = sc.source;
  j["gamma"] = io::to_json(gamma);
  j["frame"] = "principal";  // of gamma, exact, approx and difference; input_frame: the user's
  j["mu"] = mu;
  j["R"] = R;
  j["field"] = field_json(sc.model);
  j["mass_properties"] = mass_properties_json(mass_properties(*mass_model), body);
  j["exact"] = values_json(principal.exact);
  j["approx"] = values_json(principal.approx);
  j["difference"] = values_json(principal.difference);
  j["approx_truncation_error"] = {{"next_term", r.truncation.next_term},
                                  {"bound", r.truncation.bound}};
  j["input_frame"] = frame_json("input", input);
  if (r.scan) {
    const FieldScan& f = *r.scan;
    j["scan"] = {{"R", f.R},
                 {"potential_error", f.potential_error},
                 {"moment_error", f.moment_error},
                 {"moment_relative_error", f.moment_relative_error},
                 {"slope_potential", f.slope_potential},
                 {"slope_moment", f.slope_moment}};
  }
  if (a.json) {
    print_json(std::cout, j);
    return kExitOk;
  }
  std::cout << "newtop field " << sc.source << "\nmu = " << format_number(mu)
            << "   R = " << format_number(R)
            << "   gamma (input frame) = " << format_vector(input.gamma)
            << "\nbody  M = " << format_number(body.mass())
            << "   A, B, C = " << format_vector(body.inertia())
            << "   r0 = " << format_vector(body.center_of_mass()) << " (principal axes)\n"
            << "in the principal axes: gamma = " << format_vector(gamma) << "\n";
  print_frame(principal);
  std::cout << "in the input frame (the mass model's): gamma = " << format_vector(input.gamma)
            << "\n";
  print_frame(input);
  if (a.scan) {
    std::cout << "R                        |V - V_q|                |L - L_q|                |L - "
                 "L_q|/|L|\n";
    const auto& sj = j["scan"];
    for (std::size_t i = 0; i < sj["R"].size(); ++i) {
      std::cout << format_number(sj["R"][i]) << "  " << format_number(sj["potential_error"][i])
                << "  " << format_number(sj["moment_error"][i]) << "  "
                << format_number(sj["moment_relative_error"][i]) << "\n";
    }
    std::cout << "log-log slope: potential " << format_number(sj["slope_potential"]) << ", moment "
              << format_number(sj["slope_moment"]) << "\n";
  }
  return kExitOk;
}

const RegisterCommand reg_field{Command{
    "field", "Exact and quadratic field of a mass model: V, dV/dgamma, dV/dR, moment, force",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<FieldArgs>();
      sub.add_option("scenario", a->scenario, "scenario file (TOML) with [mass_model]")->required();
      sub.add_option("--gamma", a->gamma, "g1,g2,g3: direction from the centre to O (user frame)")
          ->required();
      sub.add_option("--R", a->R, "distance of the centre (overrides [field] R)");
      sub.add_option("--scan-R", a->scan, "R1:R2:N: error of the quadratic model on N distances");
      sub.add_flag("--json", a->json, "print one JSON object");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
