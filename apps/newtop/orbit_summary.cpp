#include "orbit_summary.hpp"

#include <cmath>
#include <numbers>

#include "cli.hpp"
#include "newtop/orbit/debra_delp.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "summary.hpp"

namespace newtop::app {
namespace {

const EllipticOrbit* ellipse(const io::OrbitScenario& sc) {
  return std::get_if<EllipticOrbit>(&sc.orbit);
}

}  // namespace

void warn_units(const io::OrbitScenario& sc) {
  if (!sc.mu || !sc.radius) return;
  for (const std::string& w : orbit_unit_warnings(*sc.mu, *sc.radius)) warn(sc.source + ": " + w);
}

double start_variable(const io::OrbitScenario& sc) {
  const EllipticOrbit* e = ellipse(sc);
  return e ? e->true_anomaly0 : sc.integrate.t0;
}

double orbit_time(const io::OrbitScenario& sc, double x, double t0) {
  const EllipticOrbit* e = ellipse(sc);
  return e ? t0 + elapsed_time(*e, e->true_anomaly0, x) : x;
}

OrbitValues orbit_values(const io::OrbitScenario& sc, const OrbitState& s, double x) {
  OrbitValues v;
  if (const EllipticOrbit* e = ellipse(sc)) {
    v.integral = hamiltonian(EllipticOrbitModel(sc.body, *e), s, x);
  } else {
    v.integral = jacobi_integral(CircularOrbitModel(sc.body, std::get<CircularOrbit>(sc.orbit)), s);
  }
  v.casimir = casimir_error(s);
  v.casimirs = casimirs(s);
  return v;
}

io::Json orbit_model_json(const io::OrbitScenario& sc) {
  io::Json j;
  j["inertia"] = io::to_json(sc.body.inertia());
  j["mass"] = sc.body.mass();
  j["gyrostat"] = io::to_json(sc.body.gyrostat());
  const Mat3& P = sc.body.principal_axes();
  j["principal_axes"] =
      io::Json::array({io::to_json(P.col(0)), io::to_json(P.col(1)), io::to_json(P.col(2))});
  if (const EllipticOrbit* e = ellipse(sc)) {
    j["orbit"] = {{"kind", "elliptic"},
                  {"eccentricity", e->eccentricity},
                  {"mean_motion", e->mean_motion},
                  {"true_anomaly", e->true_anomaly0},
                  {"period", 2 * std::numbers::pi / e->mean_motion}};
  } else {
    const auto& c = std::get<CircularOrbit>(sc.orbit);
    j["orbit"] = {{"kind", "circular"}, {"rate", c.rate}, {"lambda", c.lambda_}};
    if (c.rate > 0) {
      j["orbit"]["period"] = 2 * std::numbers::pi / c.rate;
      io::Json modes = io::Json::array();
      for (const LibrationMode& m : libration_modes(sc.body, sc.initial, c.rate)) {
        modes.push_back({{"mode", m.name},
                         {"sigma", {m.sigma.real(), m.sigma.imag()}},
                         {"oscillating", m.oscillating},
                         {"frequency", m.frequency},
                         {"period", m.period}});
      }
      j["orbit"]["libration_modes"] = modes;
    }
  }
  j["units"] = sc.mu ? orbit_units(*sc.mu) : "those of the scenario (rate in rad per time unit)";
  set_units(j["units"].get<std::string>());  // the report's own units line and field say the same
  return j;
}

void print_orbit_model(std::ostream& os, const io::OrbitScenario& sc) {
  os << "body      A, B, C = " << format_vector(sc.body.inertia())
     << "   k = " << format_vector(sc.body.gyrostat()) << "\n";
  if (const EllipticOrbit* e = ellipse(sc)) {
    os << "orbit     elliptic   e = " << format_number(e->eccentricity)
       << "   n = " << format_number(e->mean_motion)
       << "   nu0 = " << format_number(e->true_anomaly0)
       << "   period = " << format_number(2 * std::numbers::pi / e->mean_motion) << "\n";
  } else {
    const auto& c = std::get<CircularOrbit>(sc.orbit);
    os << "orbit     circular   rate = " << format_number(c.rate)
       << "   lambda = " << format_number(c.lambda_) << "\n";
    if (c.rate > 0) {
      os << "          period = " << format_number(2 * std::numbers::pi / c.rate) << "\n";
      os << "modes     linear librations about the nearest rest orientation:";
      for (const LibrationMode& m : libration_modes(sc.body, sc.initial, c.rate)) {
        os << "  " << m.name << " "
           << (m.oscillating ? format_number(m.frequency / c.rate) + " rate (period " +
                                   format_number(m.period) + ")"
                             : std::string("unstable"));
      }
      os << "\n";
    }
  }
  // The summary's last line (run_newtop) names them.
  set_units(sc.mu ? orbit_units(*sc.mu) : "those of the scenario (rate in rad per time unit)");
}

io::Json orbit_values_json(const io::OrbitScenario& sc, const OrbitValues& v) {
  io::Json j;
  j[sc.circular() ? "jacobi" : "hamiltonian_nu"] = v.integral;
  j["gamma_gamma"] = v.casimirs.gamma_gamma;
  j["normal_normal"] = v.casimirs.normal_normal;
  j["gamma_normal"] = v.casimirs.gamma_normal;
  return j;
}

std::string orbit_csv_header(const io::OrbitScenario& sc, OrbitAttitudeColumns a) {
  return std::string("t,") + (sc.circular() ? "" : "nu,") +
         "omega1,omega2,omega3,gamma1,gamma2,gamma3,normal1,normal2,normal3," +
         (sc.circular() ? "jacobi" : "hamiltonian_nu") + ",casimir_error" +
         (a.quaternion ? ",q0,q1,q2,q3" : "") + (a.euler == 321 ? ",roll,pitch,yaw" : "") +
         (a.euler == 313 ? ",euler313_phi,euler313_theta,euler313_psi" : "");
}

std::string orbit_csv_row(const io::OrbitScenario& sc, const OrbitState& s, double x,
                          OrbitAttitudeColumns a, std::optional<double> t_row) {
  const double t = t_row ? *t_row : orbit_time(sc, x, sc.integrate.t0);
  std::string row = format_number(t) + ",";
  if (!sc.circular()) row += format_number(x) + ",";
  const Vec3 w = omega(sc.body, s);
  for (const Vec3* v : {&w, &s.gamma, &s.normal}) {
    for (int i = 0; i < 3; ++i) row += format_number((*v)[i]) + ",";
  }
  const OrbitValues v = orbit_values(sc, s, x);
  row += format_number(v.integral) + "," + format_number(v.casimir);
  if (a.quaternion || a.euler) {
    const Mat3 C = lvlh_to_body(s);
    if (a.quaternion) {
      for (const double c : scalar_first(lvlh_quaternion(C))) row += "," + format_number(c);
    }
    const Vec3 e = a.euler == 321 ? roll_pitch_yaw(C) : lvlh_euler_313(C);
    for (int i = 0; a.euler && i < 3; ++i) row += "," + format_number(e[i]);
  }
  return row;
}

io::Json orbit_simulation_json(const OrbitRunReport& r) {
  const OrbitState& s = r.outcome.state;
  io::Json j;
  j["scenario"] = r.scenario.source;
  j["method"] = r.method.name;
  if (is_orbit_adaptive_method(r.method.name)) {
    j["tolerance"] = {{"abs", r.method.abs_tol}, {"rel", r.method.rel_tol}};
  } else {
    j["step"] = r.method.step;
  }
  j["outcome"] = std::string(to_string(r.outcome.status));
  j["steps"] = r.outcome.steps;
  j["rejected_steps"] = r.outcome.rejected;
  j["final"] = {{"t", r.t_final},
                {"omega", io::to_json(omega(r.scenario.body, s))},
                {"gamma", io::to_json(s.gamma)},
                {"normal", io::to_json(s.normal)},
                {"m", io::to_json(s.m)}};
  if (!r.scenario.circular()) j["final"]["nu"] = r.outcome.t;
  const char* name = r.scenario.circular() ? "jacobi" : "hamiltonian_nu";
  j["integrals"] = {{"initial", orbit_values_json(r.scenario, r.initial)},
                    {"final", orbit_values_json(r.scenario, r.final_values)},
                    {"max_abs_drift",
                     {{name, r.max_drift.integral},
                      {"casimir_error", r.max_drift.casimir},
                      {"geometric", r.max_geometric_drift}}}};
  j["model"] = orbit_model_json(r.scenario);
  if (r.csv_path) j["csv"] = *r.csv_path;
  return j;
}

void print_orbit_simulation(std::ostream& os, const OrbitRunReport& r) {
  const OrbitState& s = r.outcome.state;
  os << "newtop simulate " << r.scenario.source << "\n";
  print_orbit_model(os, r.scenario);
  os << "method    " << r.method.name
     << (is_orbit_adaptive_method(r.method.name) ? "  tol = " + format_number(r.method.abs_tol)
                                                 : "  step = " + format_number(r.method.step))
     << "\noutcome   " << to_string(r.outcome.status) << " at t = " << format_number(r.t_final)
     << " after " << r.outcome.steps
     << " steps\nfinal     omega = " << format_vector(omega(r.scenario.body, s))
     << "\n          gamma = " << format_vector(s.gamma)
     << "\n          normal = " << format_vector(s.normal) << "\n"
     << (r.scenario.circular() ? "jacobi    " : "H_nu      ") << format_number(r.initial.integral)
     << " -> " << format_number(r.final_values.integral)
     << "   max |drift| = " << format_number(r.max_drift.integral)
     << "\ncasimirs  max error = " << format_number(r.max_drift.casimir) << "\n";
  if (r.csv_path) os << "trajectory written to " << *r.csv_path << "\n";
}

}  // namespace newtop::app
