// integrate() on the orbit model: one run into numpy arrays, the rows of `newtop simulate`'s orbit
// CSV with `--euler 321` (t[, nu], omega, gamma, normal, the integral, casimir_error, q0..q3,
// roll, pitch, yaw) and m, in one growing buffer that the returned arrays view without a copy.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "newtop/io/orbit_settings.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "orbit_model.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// Rows t[, nu], omega (3), gamma (3), m (3), normal (3), jacobi | hamiltonian_nu, casimir_error,
/// q0..q3 (C(body←LVLH), q0 ≥ 0), roll, pitch, yaw (newtop/orbit/lvlh.hpp).
struct OrbitRows {
  OrbitRows(const OrbitModel& model, double t0) : model_(model), t0_(t0) {
    names = {"t"};
    if (!model.circular()) names.push_back("nu");
    for (const char* v : {"omega", "gamma", "m", "normal"}) {
      for (int i = 1; i <= 3; ++i) names.push_back(v + std::to_string(i));
    }
    names.push_back(model.circular() ? "jacobi" : "hamiltonian_nu");
    for (const char* c : {"casimir_error", "q0", "q1", "q2", "q3", "roll", "pitch", "yaw"}) {
      names.push_back(c);
    }
  }
  /// The state at the run's variable x (t, or ν on an ellipse); `t` the row's time when it was
  /// asked for (t_eval), else the time of x (Kepler's equation on an ellipse).
  void add(double x, const OrbitState& s, std::optional<double> t = std::nullopt) {
    const auto* e = std::get_if<EllipticOrbitModel>(&model_.model);
    data.push_back(t ? *t : e ? t0_ + elapsed_time(e->orbit(), e->orbit().true_anomaly0, x) : x);
    if (e) data.push_back(x);
    const Vec3 w = omega(model_.body(), s);
    for (const Vec3* v : {&w, &s.gamma, &s.m, &s.normal}) {
      for (int i = 0; i < 3; ++i) data.push_back((*v)[i]);
    }
    data.push_back(e ? hamiltonian(*e, s, x)
                     : jacobi_integral(std::get<CircularOrbitModel>(model_.model), s));
    data.push_back(casimir_error(s));
    const Mat3 C = lvlh_to_body(s);
    for (const double q : scalar_first(lvlh_quaternion(C))) data.push_back(q);
    const Vec3 rpy = roll_pitch_yaw(C);
    for (int i = 0; i < 3; ++i) data.push_back(rpy[i]);
  }
  std::vector<std::string> names;
  std::vector<double> data;

 private:
  const OrbitModel& model_;
  double t0_;
};

/// The buffer handed to numpy; every key a view of `table`: each column by its CSV name, and the
/// vectors omega, gamma, m, normal (N, 3), lvlh_quaternion (N, 4), roll_pitch_yaw (N, 3).
py::dict columns(OrbitRows&& rows) {
  const auto width = static_cast<py::ssize_t>(rows.names.size());
  auto* owned = new std::vector<double>(std::move(rows.data));
  const py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  const auto n = static_cast<py::ssize_t>(owned->size()) / width;
  const auto col = static_cast<py::ssize_t>(sizeof(double));
  const py::array_t<double> table({n, width}, {col * width, col}, owned->data(), owner);
  auto view = [&](py::ssize_t first, py::ssize_t count) -> py::object {
    if (count == 1) return table[py::make_tuple(py::slice(0, n, 1), first)];
    return table[py::make_tuple(py::slice(0, n, 1), py::slice(first, first + count, 1))];
  };
  py::dict d;
  for (py::ssize_t k = 0; k < width; ++k) {
    d[py::str(rows.names[static_cast<std::size_t>(k)])] = view(k, 1);
  }
  const py::ssize_t v = width == 23 ? 2 : 1;  // omega's first column (after t[, nu])
  d["omega"] = view(v, 3);
  d["gamma"] = view(v + 3, 3);
  d["m"] = view(v + 6, 3);
  d["normal"] = view(v + 9, 3);
  d["lvlh_quaternion"] = view(v + 14, 4);
  d["roll_pitch_yaw"] = view(v + 18, 3);
  d["table"] = table;
  d["columns"] = rows.names;
  return d;
}

/// Default adaptive method on an orbit and both-or-neither of step and tol as integrate() on the
/// fixed point (method_settings), checked by validate_orbit_method.
MethodSettings orbit_method(const std::optional<std::string>& name, std::optional<double> step,
                            std::optional<double> tol) {
  if (step && tol) throw InputError("step, tol: expected one of them, found both");
  if (!step && !tol) throw InputError("step, tol: expected a step or a tolerance, found neither");
  MethodSettings s;
  s.name = name.value_or(std::string(step ? kDefaultFixedMethod : kOrbitAdaptiveMethod));
  if (step) s.step = *step;
  if (tol) s.abs_tol = s.rel_tol = *tol;
  validate_orbit_method(s);
  return s;
}

py::dict run(const OrbitModel& model, const OrbitState& x0, double t0, double t1,
             const MethodSettings& method, std::int64_t max_steps,
             const std::optional<std::vector<double>>& t_eval) {
  OrbitRows rows(model, t0);
  std::optional<OutputTimes> times;
  if (t_eval) times = OutputTimes::list(*t_eval, t0, t1);  // checked in time, as --times
  OrbitOutcome out;
  {
    const py::gil_scoped_release unlocked;
    auto observe = [&](double x, const OrbitState& s) { rows.add(x, s); };
    auto sample = [&](std::int64_t k, double x, const OrbitState& s) {
      rows.add(x, s, (*times)[k]);
    };
    if (const auto* c = std::get_if<CircularOrbitModel>(&model.model)) {
      out = times ? run_orbit_method_sampled(method, *c, x0, t0, t1, *times, max_steps, sample)
                  : run_orbit_method(method, *c, x0, t0, t1, max_steps, observe);
    } else {
      // On an ellipse the run's variable is ν: each time carried to ν by Kepler's equation.
      const auto& e = std::get<EllipticOrbitModel>(model.model);
      const double nu0 = e.orbit().true_anomaly0, nu1 = true_anomaly_at(e.orbit(), t1 - t0);
      if (times) {
        std::vector<double> nu;
        for (const double t : *t_eval) nu.push_back(true_anomaly_at(e.orbit(), t - t0));
        out = run_orbit_method_sampled(
            method, e, x0, nu0, nu1, OutputTimes::list(std::move(nu), nu0, nu1), max_steps, sample);
      } else {
        out = run_orbit_method(method, e, x0, nu0, nu1, max_steps, observe);
      }
    }
  }
  py::dict d = columns(std::move(rows));
  d["outcome"] = std::string(to_string(out.status));
  d["steps"] = out.steps;
  d["rejected"] = out.rejected;
  d["method"] = method.name;
  if (is_orbit_adaptive_method(method.name)) {
    d["tol"] = method.abs_tol;
  } else {
    d["step"] = method.step;
  }
  return d;
}

double checked_t_end(double t0, double t_end) {
  if (!std::isfinite(t0))
    throw InputError("t0: expected a finite time, found " + format_number(t0));
  if (!std::isfinite(t_end) || !(t_end > t0)) {
    throw InputError("t_end: expected a finite time > t0 = " + format_number(t0) + ", found " +
                     format_number(t_end));
  }
  return t_end;
}

}  // namespace

void bind_orbit_run(py::module_& m) {
  m.def(
      "integrate",
      [](const OrbitModel& model, const OrbitState& state, double t_end, double t0,
         const std::optional<std::string>& method, std::optional<double> step,
         std::optional<double> tol, std::optional<std::int64_t> max_steps,
         const std::optional<std::vector<double>>& t_eval) {
        const MethodSettings s = orbit_method(method, step, tol);
        if (max_steps && *max_steps < 1) {
          throw InputError("max_steps: expected an integer >= 1, found " +
                           std::to_string(*max_steps));
        }
        return run(model, state, t0, checked_t_end(t0, t_end), s,
                   max_steps.value_or(OrbitAdaptiveOptions{}.max_steps), t_eval);
      },
      py::arg("model"), py::arg("state"), py::arg("t_end"), py::kw_only(), py::arg("t0") = 0.0,
      py::arg("method") = py::none(), py::arg("step") = py::none(), py::arg("tol") = py::none(),
      py::arg("max_steps") = py::none(), py::arg("t_eval") = py::none(),
      "Integrates the orbit model (docs/orbit.md §5) from (t0, state) to t_end (times on either "
      "orbit; on an ellipse the run advances the true anomaly) with a splitting composition "
      "(step=, splitting6 by default) or rkf78 / dopri5 (tol=). Returns a dict of numpy arrays "
      "over the accepted steps, or at the times t_eval: every column of `newtop simulate "
      "--euler 321`'s orbit CSV by name (t, nu, jacobi | hamiltonian_nu, casimir_error, q0..q3, "
      "roll, pitch, yaw) and omega, gamma, m, normal (N x 3), lvlh_quaternion (N x 4), "
      "roll_pitch_yaw (N x 3), all views of 'table' (columns named by 'columns'); and 'outcome', "
      "'steps', 'rejected', 'method', 'step' or 'tol'.");
  m.def(
      "integrate",
      [](const io::OrbitScenario& sc, std::optional<double> t_end,
         const std::optional<std::string>& method, std::optional<double> step,
         std::optional<double> tol, const std::optional<std::vector<double>>& t_eval) {
        const io::IntegrateOverrides ov{method, step, tol, t_end, std::nullopt};
        const MethodSettings s = io::resolve_method(sc, ov);
        const double t1 = io::resolve_t_end(sc, ov);
        return run(OrbitModel::of(sc), sc.initial, sc.integrate.t0, t1, s,
                   sc.integrate.max_steps.value_or(OrbitAdaptiveOptions{}.max_steps), t_eval);
      },
      py::arg("scenario"), py::kw_only(), py::arg("t_end") = py::none(),
      py::arg("method") = py::none(), py::arg("step") = py::none(), py::arg("tol") = py::none(),
      py::arg("t_eval") = py::none(),
      "Integrates an orbit scenario with its [integrate] settings, overridden as on the command "
      "line (newtop simulate --t-end, --method, --step, --tol; t_eval as --times). The rows of "
      "`newtop simulate --euler 321 --out FILE.csv`, bit for bit.");
}

}  // namespace newtop::python
