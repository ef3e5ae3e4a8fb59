// integrate_ensemble(): many trajectories of the quadratic field at once through the Taylor
// ensemble (newtop/integrate/taylor_ensemble.hpp), into numpy arrays; each trajectory the bits of
// integrate(model, state, t_end, tol=tol) of that point.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "newtop/integrate/taylor.hpp"
#include "newtop/integrate/taylor_ensemble.hpp"
#include "newtop/model/state_checks.hpp"
#include "newtop/phase/chaos_ensemble.hpp"
#include "orbit_ensemble.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// One Model or a sequence of Models (one per state), each of the quadratic field.
std::vector<QuadraticModel> quadratic_models(const py::object& models) {
  std::vector<Model> given;
  try {
    if (py::isinstance<Model>(models)) {
      given.push_back(models.cast<Model>());
    } else {
      given = models.cast<std::vector<Model>>();
    }
  } catch (const py::cast_error&) {
    throw InputError("model_or_models: expected a Model or a sequence of Models, found " +
                     std::string(py::str(py::type::of(models).attr("__name__"))));
  }
  std::vector<QuadraticModel> q;
  for (const Model& m : given) {
    if (m.kind() != FieldKind::quadratic) throw InputError(kTaylorFieldOnly);
    q.push_back(m.quadratic());
  }
  return q;
}

/// A sequence of States, or an (N × 6) array of rows (m, γ).
std::vector<State> states_of(const py::object& states) try {
  if (py::isinstance<py::array>(states)) {
    const auto a = states.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
    if (a.ndim() != 2 || a.shape(1) != 6) {
      throw InputError("states: expected an (N x 6) array of rows (m, gamma), found " +
                       std::to_string(a.ndim()) + " dimensions");
    }
    std::vector<State> x;
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
      x.push_back(
          {Vec3(a.at(i, 0), a.at(i, 1), a.at(i, 2)), Vec3(a.at(i, 3), a.at(i, 4), a.at(i, 5))});
    }
    return x;
  }
  return states.cast<std::vector<State>>();
} catch (const py::cast_error&) {
  throw InputError(
      "states: expected a sequence of State or an (N x 6) array of numbers (rows m, gamma), "
      "found " +
      std::string(py::str(py::type::of(states).attr("__name__"))));
}

/// Sets d["m"], d["omega"], d["gamma"]: arrays of shape `shape` + (3) over `rows` rows in order,
/// row r from at(r) = (body, state), or NaN where at(r) gives no state.
template <class At>
void put_states(py::dict& d, std::vector<py::ssize_t> shape, std::size_t rows, At&& at) {
  std::vector<double> m(3 * rows, std::numeric_limits<double>::quiet_NaN()), w = m, g = m;
  for (std::size_t r = 0; r < rows; ++r) {
    const std::optional<std::pair<const Body*, State>> x = at(r);
    if (!x) continue;
    const Vec3 om = omega(*x->first, x->second);
    for (int c = 0; c < 3; ++c) {
      m[3 * r + c] = x->second.m[c];
      w[3 * r + c] = om[c];
      g[3 * r + c] = x->second.gamma[c];
    }
  }
  shape.push_back(3);
  d["m"] = py::array_t<double>(shape, m.data());
  d["omega"] = py::array_t<double>(shape, w.data());
  d["gamma"] = py::array_t<double>(shape, g.data());
}

py::dict integrate_ensemble(const py::object& model_or_models, const py::object& states_in,
                            double t_end, double tol, double t0,
                            std::optional<std::int64_t> max_steps,
                            const std::optional<std::vector<double>>& t_eval) {
  if (is_orbit_models(model_or_models)) {
    return orbit_integrate_ensemble(model_or_models, states_in, t_end, tol, t0, max_steps,
                                    t_eval.has_value());
  }
  const std::vector<QuadraticModel> models = quadratic_models(model_or_models);
  const std::vector<State> states = states_of(states_in);
  for (const State& x : states) validate(x);
  IntegrateOptions options;
  if (max_steps) options.max_steps = *max_steps;
  check_time_span(t0, t_end);
  std::optional<OutputTimes> times;
  if (t_eval) times = OutputTimes::list(*t_eval, t0, t_end);
  const std::size_t n = states.size(), k = times ? static_cast<std::size_t>(times->size()) : 0;
  std::vector<std::optional<State>> samples(n * k);  // point p, time j at p k + j
  TaylorEnsembleObserver obs;
  if (times) {
    obs.times = &*times;
    obs.sample = [&](std::size_t p, std::int64_t j, double, const State& x) {
      samples[p * k + static_cast<std::size_t>(j)] = x;
    };
  }
  std::vector<Outcome> out;
  {
    TaylorEnsemble ensemble(tol, tol);
    const py::gil_scoped_release unlocked;
    out = ensemble.integrate(models, states, t0, t_end, options, obs);
  }
  auto body = [&](std::size_t p) { return &models[models.size() == 1 ? 0 : p].body; };
  py::dict d;
  const auto N = static_cast<py::ssize_t>(n);
  if (times) {
    d["t"] = py::array_t<double>(static_cast<py::ssize_t>(k), t_eval->data());
    put_states(d, {N, static_cast<py::ssize_t>(k)}, n * k, [&](std::size_t r) {
      const std::optional<State>& x = samples[r];
      return x ? std::optional(std::pair(body(r / k), *x)) : std::nullopt;
    });
  } else {
    std::vector<double> t;
    for (const Outcome& o : out) t.push_back(o.t);
    d["t"] = py::array_t<double>(N, t.data());
    put_states(d, {N}, n,
               [&](std::size_t p) { return std::optional(std::pair(body(p), out[p].state)); });
  }
  py::list outcome;
  std::vector<std::int64_t> steps;
  for (const Outcome& o : out) {
    outcome.append(std::string(to_string(o.status)));
    steps.push_back(o.steps);
  }
  d["outcome"] = outcome;
  d["steps"] = py::array_t<std::int64_t>(N, steps.data());
  d["order"] = TaylorStepper(tol, tol).order();
  return d;
}

py::dict chaos_ensemble(const py::object& model_or_models, const py::object& states_in,
                        double t_end, double tol, double t0,
                        std::optional<std::int64_t> max_steps) {
  if (is_orbit_models(model_or_models)) {
    return orbit_chaos_ensemble(model_or_models, states_in, t_end, tol, t0, max_steps);
  }
  const std::vector<QuadraticModel> models = quadratic_models(model_or_models);
  const std::vector<State> states = states_of(states_in);
  for (const State& x : states) validate(x);
  IntegrateOptions options;
  if (max_steps) options.max_steps = *max_steps;
  std::vector<phase::ChaosResult> r;
  {
    const py::gil_scoped_release unlocked;
    r = phase::taylor_chaos_ensemble(models, states, t0, t_end, tol, tol, options);
  }
  std::vector<double> megno, lyapunov, fli;
  py::list outcome;
  for (const phase::ChaosResult& c : r) {
    megno.push_back(c.indicators.megno);
    lyapunov.push_back(c.indicators.lyapunov_max);
    fli.push_back(c.indicators.fli);
    outcome.append(std::string(to_string(c.outcome.status)));
  }
  const auto n = static_cast<py::ssize_t>(r.size());
  py::dict d;
  d["megno"] = py::array_t<double>(n, megno.data());
  d["lyapunov_max"] = py::array_t<double>(n, lyapunov.data());
  d["fli"] = py::array_t<double>(n, fli.data());
  d["outcome"] = outcome;
  return d;
}

}  // namespace

void bind_ensemble(py::module_& m) {
  m.def("chaos_ensemble", &chaos_ensemble, py::arg("model_or_models"), py::arg("states"),
        py::arg("t_end"), py::kw_only(), py::arg("tol"), py::arg("t0") = 0.0,
        py::arg("max_steps") = py::none(),
        "The chaos indicators of N starts at once (docs/chaos.md) through the Taylor ensemble's "
        "tangent runs: each the bits of newtop.chaos(model, state, t_end, tol=tol, "
        "method='taylor'). Arguments as integrate_ensemble. Returns a dict of arrays (N): megno, "
        "lyapunov_max, fli, and 'outcome' (N strings; the indicators of a run that stopped are "
        "those up to where it stopped). With OrbitModels (states as integrate_ensemble's): each "
        "the bits of newtop.chaos(model, state, t_end, tol=tol, method='taylor') on the orbit.");
  m.def("integrate_ensemble", &integrate_ensemble, py::arg("model_or_models"), py::arg("states"),
        py::arg("t_end"), py::kw_only(), py::arg("tol"), py::arg("t0") = 0.0,
        py::arg("max_steps") = py::none(), py::arg("t_eval") = py::none(),
        "Integrates N trajectories of the quadratic field at once with Taylor's method in SIMD "
        "lanes (docs/methods.md, 'Taylor ensemble'): one Model for all or one per state; states a "
        "sequence of State or an (N x 6) array of rows (m, gamma). Each trajectory is the bits of "
        "integrate(model, state, t_end, tol=tol, method='taylor'). Returns a dict: without t_eval "
        "the end of each run, t (N) and m, omega, gamma (N x 3); with t_eval=times (ascending, "
        "in [t0, t_end]) t (k) and m, omega, gamma (N x k x 3), NaN after a run that stopped; "
        "and 'outcome' (N strings), 'steps' (N), 'order'. With OrbitModels (one for all or one "
        "per state, of one kind) and states a sequence of OrbitState or an (N x 9) array of rows "
        "(m, gamma, normal): the satellites through the orbit's Taylor ensemble (docs/orbit.md "
        "§5), each the bits of the last row of integrate(model, state, t_end, tol=tol, "
        "method='taylor'); t (N; and nu on an ellipse), m, omega, gamma, normal (N x 3), "
        "'outcome', 'steps', 'order' (t_eval refused).");
}

}  // namespace newtop::python
