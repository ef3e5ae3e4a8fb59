#pragma once
// Shared output of the orbit-scenario subcommands: model, integrals, CSV rows, run summaries.

#include <optional>
#include <ostream>
#include <string>

#include "newtop/io/json.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/orbit_integrate.hpp"

namespace newtop::app {

/// The integral of the run and the Casimirs at one state: the Jacobi integral on a circular orbit,
/// the generator H_ν (not conserved) on an elliptic one.
struct OrbitValues {
  double integral = 0.0;
  double casimir = 0.0;  ///< casimir_error
  OrbitCasimirs casimirs{1.0, 1.0, 0.0};
};

/// The unit-mix warnings of the scenario's μ and radius (orbit_unit_warnings), one line each on
/// stderr unless --quiet.
void warn_units(const io::OrbitScenario& sc);

/// t0 on a circular orbit, ν0 on an elliptic one (the integrators' independent variable).
double start_variable(const io::OrbitScenario& sc);
/// The time at the integrators' variable x (t itself, or t0 + t(ν) − t(ν0) by Kepler's equation).
double orbit_time(const io::OrbitScenario& sc, double x, double t0);
OrbitValues orbit_values(const io::OrbitScenario& sc, const OrbitState& s, double x);

io::Json orbit_model_json(const io::OrbitScenario& sc);
void print_orbit_model(std::ostream& os, const io::OrbitScenario& sc);
io::Json orbit_values_json(const io::OrbitScenario& sc, const OrbitValues& v);

/// The attitude columns of an orbit CSV (LVLH, newtop/orbit/lvlh.hpp).
struct OrbitAttitudeColumns {
  bool quaternion = false;  ///< q0,q1,q2,q3 of C(body←LVLH), q0 ≥ 0
  int euler = 0;            ///< 321: roll,pitch,yaw; 313: euler313_phi,euler313_theta,euler313_psi
};

/// `t,omega1,omega2,omega3,gamma1,gamma2,gamma3,normal1,normal2,normal3,jacobi|hamiltonian_nu,
/// casimir_error` (elliptic orbits add `nu` after t), then the attitude columns asked for.
std::string orbit_csv_header(const io::OrbitScenario& sc, OrbitAttitudeColumns a = {});
/// The row at the integrator's variable x (t, or ν on an ellipse); `t` is the row's time when
/// given (an output time asked for), else the time of x.
std::string orbit_csv_row(const io::OrbitScenario& sc, const OrbitState& s, double x,
                          OrbitAttitudeColumns a = {}, std::optional<double> t = std::nullopt);

struct OrbitRunReport {
  const io::OrbitScenario& scenario;
  const MethodSettings& method;
  const OrbitOutcome& outcome;
  double t_final;
  OrbitValues initial, final_values, max_drift;
  double max_geometric_drift = 0.0;  ///< max |γ·γ − γ0·γ0| over the run
  std::optional<std::string> csv_path;
};

io::Json orbit_simulation_json(const OrbitRunReport& r);
void print_orbit_simulation(std::ostream& os, const OrbitRunReport& r);

}  // namespace newtop::app
