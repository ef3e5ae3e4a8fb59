// newtop field SCENARIO.toml --gamma g1,g2,g3: exact and quadratic field of a mass model at one
// orientation (docs/model.md §2, §3), and with --scan-R the error of the quadratic model against R.

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "command.hpp"
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

io::Json matrix_json(const Mat3& m) {
  io::Json J = io::Json::array();
  for (int i = 0; i < 3; ++i) J.push_back(io::to_json(Vec3(m.row(i))));
  return J;
}

/// The field's values at γ and its Hessian ∂²V/∂γ².
struct Values {
  FieldValues v;
  Mat3 hessian;
};

io::Json values_json(const Values& x) {
  const FieldValues& v = x.v;
  return {{"potential", v.potential},
          {"grad_gamma", io::to_json(v.grad_gamma)},
          {"dV_dR", v.dV_dR},
          {"moment", io::to_json(v.moment)},
          {"force", io::to_json(v.force)},
          {"hessian_gamma", matrix_json(x.hessian)}};
}

Values difference(const Values& a, const Values& b) {
  const FieldValues &x = a.v, &y = b.v;
  return {{x.potential - y.potential, x.grad_gamma - y.grad_gamma, x.dV_dR - y.dV_dR,
           x.moment - y.moment, x.force - y.force},
          a.hessian - b.hessian};
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

/// Least-squares slope of log y against log x.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void print_values(const char* name, const Values& x) {
  const FieldValues& v = x.v;
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
  const FieldKind kind = sc.model.kind();
  const CentreParameters centre = centre_parameters(sc.model);
  if (kind == FieldKind::quadratic && !a.R) {
    throw InputError(sc.source +
                     ": [field] kind: expected \"exact\" or \"multipole\" with mu and R, "
                     "or give --R");
  }
  // Without an exact [field] (only --R) the centre has unit mu.
  const double mu = kind == FieldKind::quadratic ? 1.0 : centre.mu;
  const double R = a.R.value_or(centre.R);
  const Body& body = sc.model.body();
  const Mat3& P = body.principal_axes();
  const Vec3 gamma = P.transpose() * io::parse_gamma(a.gamma);  // user frame → principal axes
  auto at = [&](double r) {
    const ExactField x = ExactField::make(mass_model, mu, r, P);
    const MultipoleField q = MultipoleField::make(*mass_model, 3, mu, r, P);
    return std::pair{Values{field_values(x, gamma), hessian_gamma(body, x, gamma)},
                     Values{field_values(q, gamma), hessian_gamma(body, q, gamma)}};
  };
  io::Json j;
  j["scenario"] = sc.source;
  j["gamma"] = io::to_json(gamma);
  j["mu"] = mu;
  j["R"] = R;
  j["field"] = field_json(sc.model);
  j["mass_properties"] = mass_properties_json(mass_properties(*mass_model), body);
  const auto [ex, ap] = at(R);
  j["exact"] = values_json(ex);
  j["approx"] = values_json(ap);
  j["difference"] = values_json(difference(ex, ap));
  const TruncationError t = truncation_error(MultipoleField::make(*mass_model, 3, mu, R, P), gamma);
  j["approx_truncation_error"] = {{"next_term", t.next_term}, {"bound", t.bound}};
  if (a.scan) {
    const io::RadiusScan s = io::parse_radius_scan(*a.scan);
    std::vector<double> Rs, dV, dL, rel;
    for (int i = 0; i < s.n; ++i) {
      const double r = s.R1 * std::pow(s.R2 / s.R1, static_cast<double>(i) / (s.n - 1));
      const auto [x, q] = at(r);
      Rs.push_back(r);
      dV.push_back(std::abs(x.v.potential - q.v.potential));
      dL.push_back((x.v.moment - q.v.moment).norm());
      rel.push_back(dL.back() / x.v.moment.norm());
    }
    j["scan"] = {{"R", Rs},
                 {"potential_error", dV},
                 {"moment_error", dL},
                 {"moment_relative_error", rel},
                 {"slope_potential", loglog_slope(Rs, dV)},
                 {"slope_moment", loglog_slope(Rs, dL)}};
  }
  if (a.json) {
    std::cout << j.dump(2) << '\n';
    return kExitOk;
  }
  std::cout << "newtop field " << sc.source << "\nmu = " << format_number(mu)
            << "   R = " << format_number(R)
            << "   gamma (principal axes) = " << format_vector(gamma)
            << "\nbody  M = " << format_number(body.mass())
            << "   A, B, C = " << format_vector(body.inertia())
            << "   r0 = " << format_vector(body.center_of_mass()) << "\n";
  print_values("exact ", ex);
  print_values("approx", ap);
  print_values("diff  ", difference(ex, ap));
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

const RegisterCommand reg{Command{
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
