#include "summary.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>

#include "integration_options.hpp"
#include "newtop/exact/mass_models.hpp"
#include "newtop/integrate/taylor.hpp"

namespace newtop::app {
namespace {

std::string fmt(double x, int digits = 16) {
  if (x == 0.0) x = 0.0;  // −0 is printed as 0
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string fmt(const Vec3& v, int digits = 16) {
  return "[" + fmt(v.x(), digits) + ", " + fmt(v.y(), digits) + ", " + fmt(v.z(), digits) + "]";
}

/// Replaces every −0 in j by 0.
void clear_negative_zeros(io::Json& j) {
  if (j.is_structured()) {
    for (auto& v : j) clear_negative_zeros(v);
  } else if (j.is_number_float() && j.get<double>() == 0.0) {
    j = 0.0;
  }
}

}  // namespace

namespace {
std::string& units_text() {
  static std::string u = kUnitFree;
  return u;
}
bool& units_printed() {
  static bool printed = false;
  return printed;
}
}  // namespace

const std::string& units() { return units_text(); }
void set_units(std::string text) {
  units_text() = std::move(text);
  units_printed() = false;
}
void print_units_line(std::ostream& os) {
  os << "units: " << units() << '\n';
  units_printed() = true;
}
bool units_line_printed() { return units_printed(); }

void print_json(std::ostream& os, io::Json j) {
  clear_negative_zeros(j);
  if (j.is_object() && !j.contains("units")) j["units"] = units();
  os << j.dump(2) << '\n';
}

io::Json without_negative_zeros(io::Json j) {
  clear_negative_zeros(j);
  return j;
}

io::Json model_json(const Model& m) {
  io::Json j;
  const Body& b = m.body();
  j["inertia"] = io::to_json(b.inertia());
  j["mass"] = b.mass();
  j["center_of_mass"] = io::to_json(b.center_of_mass());
  j["gyrostat"] = io::to_json(b.gyrostat());
  const Mat3& P = b.principal_axes();
  j["principal_axes"] =
      io::Json::array({io::to_json(P.col(0)), io::to_json(P.col(1)), io::to_json(P.col(2))});
  if (m.kind() == FieldKind::quadratic) {
    j["g"] = m.quadratic().field.g;
    j["lambda"] = m.quadratic().field.lambda_;
  }
  clear_negative_zeros(j);  // also for the subcommands that dump their JSON themselves
  return j;
}

const char* mass_model_name(const MassModel& mm) {
  static const char* const names[] = {"point_masses", "polyhedron", "ellipsoid"};
  return names[mm.index()];
}

io::Json field_json(const Model& m) {
  io::Json j;
  j["kind"] = to_string(m.kind());
  if (m.kind() == FieldKind::quadratic) {
    j["g"] = m.quadratic().field.g;
    j["lambda"] = m.quadratic().field.lambda_;
  } else {
    const CentreParameters c = centre_parameters(m);
    j["mu"] = c.mu;
    j["R"] = c.R;
    if (m.kind() == FieldKind::multipole) j["order"] = c.order;
  }
  if (m.mass_model()) j["mass_model"] = mass_model_name(*m.mass_model());
  clear_negative_zeros(j);
  return j;
}

std::string field_line(const Model& m) {
  if (m.kind() == FieldKind::quadratic) {
    const QuadraticField& f = m.quadratic().field;
    return "g = " + fmt(f.g) + "   lambda = " + fmt(f.lambda_);
  }
  const CentreParameters c = centre_parameters(m);
  std::string line = std::string(to_string(m.kind())) + " (mu = " + fmt(c.mu) + ", R = " + fmt(c.R);
  if (m.kind() == FieldKind::multipole) line += ", order = " + std::to_string(c.order);
  if (m.mass_model()) line += std::string(", mass model: ") + mass_model_name(*m.mass_model());
  return line + ")";
}

void print_model(std::ostream& os, const Model& m) {
  const Body& b = m.body();
  os << "body      A, B, C = " << fmt(b.inertia()) << "   M = " << fmt(b.mass())
     << "\n          r0 = " << fmt(b.center_of_mass()) << "   k = " << fmt(b.gyrostat()) << "\n";
  if (!b.principal_axes().isIdentity(0.0)) {
    const Mat3& P = b.principal_axes();
    os << "          principal axes (user frame): x' = " << fmt(Vec3(P.col(0)), 6)
       << "  y' = " << fmt(Vec3(P.col(1)), 6) << "  z' = " << fmt(Vec3(P.col(2)), 6) << "\n";
  }
  os << "field     " << field_line(m) << "\n";
}

void require_quadratic(const Model& m, const std::string& source, const std::string& what) {
  if (m.kind() == FieldKind::quadratic) return;
  throw InputError(source + ": [field] kind: " + what + " needs the quadratic field, found the " +
                   field_line(m) + " field");
}

std::string casimir_warning(const CasimirDrift& c) {
  return "the Casimirs drifted by |d(gamma.gamma)|/gamma.gamma = " + fmt(c.geometric, 3) +
         " and |d(m.gamma)|/max|m| = " + fmt(c.area, 3) + ", beyond " +
         fmt(CasimirDrift::kThreshold, 3) +
         ": the state is wrong by at least half that (relative); tighten the tolerance or the "
         "step";
}

io::Json simulation_json(const SimulationReport& r) {
  io::Json j;
  const Vec3 w = omega(r.scenario.model.body(), r.outcome.state);
  j["scenario"] = r.scenario.source;
  j["method"] = r.method.name;
  const MethodInfo& info = method_info(r.method.name);
  if (info.kind == MethodKind::adaptive) {
    j["tolerance"] = {{"abs", r.method.abs_tol}, {"rel", r.method.rel_tol}};
    if (r.method.name == "taylor") {
      j["order"] = detail::taylor_order(std::min(r.method.abs_tol, r.method.rel_tol));
    }
  } else {
    j["step"] = r.method.step;
  }
  if (const auto split = split_of(r.method)) j["split"] = *split;
  j["outcome"] = std::string(to_string(r.outcome.status));
  j["steps"] = r.outcome.steps;
  j["rejected_steps"] = r.outcome.rejected;
  j["final"] = {{"t", r.outcome.t},
                {"omega", io::to_json(w)},
                {"gamma", io::to_json(r.outcome.state.gamma)},
                {"m", io::to_json(r.outcome.state.m)}};
  if (r.outcome.attitude) {
    const auto q = scalar_first(*r.outcome.attitude);
    j["final"]["quaternion"] = {q[0], q[1], q[2], q[3]};
    j["attitude"] = {
        {"frame", "principal axes to inertial, scalar first"},
        {"inertial_direction",
         io::to_json(inertial_direction(with_attitude(r.outcome.state, *r.outcome.attitude)))},
        {"max_renormalization", r.outcome.attitude_projection}};
  }
  j["integrals"] = {{"initial", io::to_json(r.initial)},
                    {"final", io::to_json(r.final_values)},
                    {"max_abs_drift", io::to_json(r.max_drift)}};
  j["casimir_drift"] = {{"geometric", r.casimir.geometric},
                        {"area", r.casimir.area},
                        {"threshold", CasimirDrift::kThreshold},
                        {"exceeded", r.casimir.exceeded()}};
  j["warnings"] = io::Json::array();
  if (r.casimir.exceeded()) j["warnings"].push_back(casimir_warning(r.casimir));
  j["conserved"] = conserved_integrals(r.scenario.model);
  j["model"] = model_json(r.scenario.model);
  if (r.csv_path) j["csv"] = *r.csv_path;
  j["field"] = field_json(r.scenario.model);
  clear_negative_zeros(j);
  return j;
}

void print_simulation_summary(std::ostream& os, const SimulationReport& r) {
  const Outcome& o = r.outcome;
  os << "newtop simulate " << r.scenario.source << "\n";
  print_model(os, r.scenario.model);
  os << "method    " << r.method.name;
  if (method_info(r.method.name).kind == MethodKind::adaptive) {
    os << "  tol = " << fmt(r.method.abs_tol, 3);
    if (r.method.name == "taylor") {
      os << "  (order " << detail::taylor_order(std::min(r.method.abs_tol, r.method.rel_tol))
         << ")";
    }
  } else {
    os << "  step = " << fmt(r.method.step);
  }
  if (const auto split = split_of(r.method)) os << "  (" << *split << " split)";
  os << "\noutcome   " << to_string(o.status) << " at t = " << fmt(o.t) << " after " << o.steps
     << " steps";
  if (o.rejected) os << " (" << o.rejected << " rejected)";
  os << "\nfinal     omega = " << fmt(omega(r.scenario.model.body(), o.state))
     << "\n          gamma = " << fmt(o.state.gamma) << "\n";
  if (o.attitude) {
    const auto q = scalar_first(*o.attitude);
    os << "          quaternion = [" << fmt(q[0]) << ", " << fmt(q[1]) << ", " << fmt(q[2]) << ", "
       << fmt(q[3]) << "]  (principal axes to inertial; renormalized by at most "
       << fmt(o.attitude_projection, 3) << " per step)\n";
  }
  os << "integral          initial                  final                    max |drift|\n";
  auto row = [&](const char* name, double a, double b, double d) {
    os << "  " << std::left << std::setw(10) << name << std::setw(25) << fmt(a) << std::setw(25)
       << fmt(b) << fmt(d, 3) << "\n";
  };
  row("energy", r.initial.energy, r.final_values.energy, r.max_drift.energy);
  row("area", r.initial.area, r.final_values.area, r.max_drift.area);
  row("geometric", r.initial.geometric, r.final_values.geometric, r.max_drift.geometric);
  if (r.initial.brun) row("brun", *r.initial.brun, *r.final_values.brun, *r.max_drift.brun);
  if (r.initial.lagrange) {
    row("lagrange", *r.initial.lagrange, *r.final_values.lagrange, *r.max_drift.lagrange);
  }
  if (r.csv_path) os << "trajectory written to " << *r.csv_path << "\n";
}

}  // namespace newtop::app
