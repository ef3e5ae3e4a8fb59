// integrate(): one run of any method into numpy arrays. The samples go into one growing buffer of
// rows (t, omega, gamma, m, integrals[, quaternion]) that the returned arrays view without a copy.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/model/integrals.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// Row layout: t, omega (3), gamma (3), m (3), energy, area, geometric[, brun][, lagrange], then
/// with an attitude the quaternion q0..q3 (body → inertial, scalar first).
struct Rows {
  Rows(const Model& model, bool with_q) : attitude(with_q), model_(model) {
    const IntegralValues v = integrals(model, State{});
    if (v.brun) names.push_back("brun");
    if (v.lagrange) names.push_back("lagrange");
    width = 10 + static_cast<py::ssize_t>(names.size()) + (with_q ? 4 : 0);
  }
  void add(double t, const OrientedState& s) {
    add(t, static_cast<const State&>(s));
    data.push_back(s.q.w());
    data.push_back(s.q.x());
    data.push_back(s.q.y());
    data.push_back(s.q.z());
  }
  void add(double t, const State& s) {
    const Vec3 w = omega(model_.body(), s);
    const IntegralValues v = integrals(model_, s);
    data.push_back(t);
    for (int i = 0; i < 3; ++i) data.push_back(w[i]);
    for (int i = 0; i < 3; ++i) data.push_back(s.gamma[i]);
    for (int i = 0; i < 3; ++i) data.push_back(s.m[i]);
    data.push_back(v.energy);
    data.push_back(v.area);
    data.push_back(v.geometric);
    if (v.brun) data.push_back(*v.brun);
    if (v.lagrange) data.push_back(*v.lagrange);
  }
  std::vector<std::string> names{"energy", "area", "geometric"};
  bool attitude = false;
  py::ssize_t width = 0;
  std::vector<double> data;

 private:
  const Model& model_;
};

/// Hands the rows to numpy (the buffer moves into the array's owner) and returns the columns as
/// views of it.
py::dict columns(Rows&& rows) {
  auto* owned = new std::vector<double>(std::move(rows.data));
  const py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  const auto n = static_cast<py::ssize_t>(owned->size()) / rows.width;
  const auto row = static_cast<py::ssize_t>(sizeof(double)) * rows.width;
  const auto col = static_cast<py::ssize_t>(sizeof(double));
  const py::array_t<double> table({n, rows.width}, {row, col}, owned->data(), owner);
  py::dict d;
  auto view = [&](py::ssize_t first, py::ssize_t count) -> py::object {
    if (count == 1) return table[py::make_tuple(py::slice(0, n, 1), first)];
    return table[py::make_tuple(py::slice(0, n, 1), py::slice(first, first + count, 1))];
  };
  d["t"] = view(0, 1);
  d["omega"] = view(1, 3);
  d["gamma"] = view(4, 3);
  d["m"] = view(7, 3);
  for (std::size_t i = 0; i < rows.names.size(); ++i) {
    d[py::str(rows.names[i])] = view(10 + static_cast<py::ssize_t>(i), 1);
  }
  if (rows.attitude) d["quaternion"] = view(10 + static_cast<py::ssize_t>(rows.names.size()), 4);
  d["table"] = table;
  return d;
}

/// The rows as columns, with the run's outcome and method beside them.
py::dict run_dict(Rows rows, const Outcome& out, const MethodSettings& method) {
  py::dict d = columns(std::move(rows));
  d["outcome"] = std::string(to_string(out.status));
  d["steps"] = out.steps;
  d["rejected"] = out.rejected;
  d["method"] = method.name;
  d["step"] = method.step;
  if (method_info(method.name).kind == MethodKind::adaptive) {
    py::dict tol;
    tol["abs"] = method.abs_tol;
    tol["rel"] = method.rel_tol;
    d["tolerance"] = tol;
  }
  return d;
}

py::dict run(const Model& model, const State& x0, const std::optional<Quaternion>& q0, double t0,
             double t1, const MethodSettings& method, IntegrateOptions options) {
  Rows rows(model, q0.has_value());
  Outcome out;
  {
    const py::gil_scoped_release unlocked;
    if (q0) {
      out = run_method(method, model, with_attitude(x0, *q0), t0, t1, options,
                       [&](double t, const OrientedState& s) { rows.add(t, s); });
    } else {
      out = run_method(method, model, x0, t0, t1, options,
                       [&](double t, const State& s) { rows.add(t, s); });
    }
  }
  return run_dict(std::move(rows), out, method);
}

/// A quaternion [w, x, y, z] given to integrate(): finite and of unit norm within
/// kUnitQuaternionTolerance (then normalised), as the scenario's [initial] quaternion.
Quaternion unit_quaternion(const Eigen::Vector4d& v) {
  const double n = v.norm();
  if (!v.allFinite() || !(std::abs(n - 1.0) <= kUnitQuaternionTolerance)) {
    throw InputError("quaternion: expected a finite unit quaternion [w, x, y, z] (norm 1 within " +
                     format_number(kUnitQuaternionTolerance) + "), found norm " + format_number(n));
  }
  return Quaternion(v[0] / n, v[1] / n, v[2] / n, v[3] / n);
}

}  // namespace

MethodSettings method_settings(const Model& model, const std::optional<std::string>& name,
                               std::optional<double> step, std::optional<double> tol) {
  if (step && tol) throw InputError("step, tol: expected one of them, found both");
  if (!step && !tol) throw InputError("step, tol: expected a step or a tolerance, found neither");
  MethodSettings s;
  s.name = name.value_or(std::string(
      step ? kDefaultFixedMethod : default_adaptive_method(model.kind() == FieldKind::quadratic)));
  if (step) s.step = *step;
  if (tol) s.abs_tol = s.rel_tol = *tol;
  validate(s);
  return s;
}

namespace {

/// The state at each time of t_eval (ascending, within [t0, t_end]): the method's dense output
/// (run_method_sampled), as simulate --times writes it.
py::dict run_sampled(const Model& model, const State& x0, double t0, double t1,
                     const std::vector<double>& t_eval, const MethodSettings& method,
                     IntegrateOptions options) {
  Rows rows(model, false);
  Outcome out;
  {
    const py::gil_scoped_release unlocked;
    out = run_method_sampled(method, model, x0, t0, t1, OutputTimes::list(t_eval, t0, t1), options,
                             [&](std::int64_t, double t, const State& s) { rows.add(t, s); });
  }
  return run_dict(std::move(rows), out, method);
}

}  // namespace

void bind_trajectory(py::module_& m) {
  m.def(
      "integrate",
      [](const Model& model, const State& state, double t_end, double t0,
         const std::optional<std::string>& method, std::optional<double> step,
         std::optional<double> tol, std::optional<std::int64_t> max_steps,
         const std::optional<Eigen::Vector4d>& quaternion,
         const std::optional<std::vector<double>>& t_eval) {
        IntegrateOptions o;
        if (max_steps) o.max_steps = *max_steps;
        const MethodSettings s = method_settings(model, method, step, tol);
        if (t_eval) {
          if (quaternion) throw InputError("t_eval: not with quaternion (the attitude)");
          check_time_span(t0, t_end);
          return run_sampled(model, state, t0, t_end, *t_eval, s, o);
        }
        std::optional<Quaternion> q;
        if (quaternion) q = unit_quaternion(*quaternion);
        return run(model, state, q, t0, t_end, s, o);
      },
      py::arg("model"), py::arg("state"), py::arg("t_end"), py::kw_only(), py::arg("t0") = 0.0,
      py::arg("method") = py::none(), py::arg("step") = py::none(), py::arg("tol") = py::none(),
      py::arg("max_steps") = py::none(), py::arg("quaternion") = py::none(),
      py::arg("t_eval") = py::none(),
      "Integrates the Euler-Poisson equations (docs/model.md §4) from (t0, state) to t_end with a "
      "method by name (splitting2..8, rk4, dopri5, rkf78, dop853, taylor); a step selects "
      "splitting6 by default and a tolerance taylor on the quadratic field, dop853 on the others. "
      "Returns a dict of numpy arrays over the accepted steps: t (N), "
      "omega, gamma, m (N x 3), energy, area, geometric[, brun][, lagrange] (N), all views of "
      "one (N x W) array 'table'; and 'outcome', 'steps', 'rejected', 'method', 'step'. With "
      "quaternion=[w, x, y, z] (the attitude, body -> inertial, scalar first; a unit one within "
      "1e-6, normalised) the run carries the attitude and adds 'quaternion' (N x 4). With "
      "t_eval=times (ascending, in [t0, t_end]) the rows are the states at those times, from the "
      "method's dense output (fixed-step methods land on each), instead of the accepted steps.");
  m.def(
      "integrate",
      [](const io::Scenario& sc, std::optional<double> t_end,
         const std::optional<std::string>& method, std::optional<double> step,
         std::optional<double> tol, const std::optional<std::string>& split) {
        const io::IntegrateOverrides ov{method, step, tol, t_end, split};
        IntegrateOptions o;
        if (sc.integrate.max_steps) o.max_steps = *sc.integrate.max_steps;
        const double t1 = io::resolve_t_end(sc, ov);
        check_time_span(sc.integrate.t0, t1);
        return run(sc.model, sc.initial, sc.attitude, sc.integrate.t0, t1,
                   io::resolve_method(sc, ov), o);
      },
      py::arg("scenario"), py::kw_only(), py::arg("t_end") = py::none(),
      py::arg("method") = py::none(), py::arg("step") = py::none(), py::arg("tol") = py::none(),
      py::arg("split") = py::none(),
      "Integrates a scenario with its [integrate] settings, overridden as on the command line "
      "(newtop simulate --t-end, --method, --step, --tol, --split). Same result as the other form; "
      "a "
      "scenario with an attitude adds 'quaternion' (N x 4), as simulate's q0..q3 columns.");
}

}  // namespace newtop::python
