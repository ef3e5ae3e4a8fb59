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

/// An array of shape `shape` filled with NaN.
py::array_t<double> nan_array(std::vector<py::ssize_t> shape) {
  py::array_t<double> a(shape);
  std::fill(a.mutable_data(), a.mutable_data() + a.size(),
            std::numeric_limits<double>::quiet_NaN());
  return a;
}

py::dict integrate_ensemble(const py::object& model_or_models, const py::object& states_in,
                            double t_end, double tol, double t0,
                            std::optional<std::int64_t> max_steps,
                            const std::optional<std::vector<double>>& t_eval) {
  const std::vector<QuadraticModel> models = quadratic_models(model_or_models);
  const std::vector<State> states = states_of(states_in);
  for (const State& x : states) validate(x);
  IntegrateOptions options;
  if (max_steps) options.max_steps = *max_steps;
  check_time_span(t0, t_end);
  std::optional<OutputTimes> times;
  if (t_eval) times = OutputTimes::list(*t_eval, t0, t_end);
  const auto n = static_cast<py::ssize_t>(states.size());
  const py::ssize_t k = times ? static_cast<py::ssize_t>(times->size()) : 0;
  std::vector<double> samples(times ? static_cast<std::size_t>(n * k * 6) : 0,
                              std::numeric_limits<double>::quiet_NaN());
  TaylorEnsembleObserver obs;
  if (times) {
    obs.times = &*times;
    obs.sample = [&](std::size_t p, std::int64_t j, double, const State& x) {
      double* row = samples.data() + (static_cast<std::size_t>(p) * static_cast<std::size_t>(k) +
                                      static_cast<std::size_t>(j)) *
                                         6;
      for (int c = 0; c < 3; ++c) {
        row[c] = x.m[c];
        row[3 + c] = x.gamma[c];
      }
    };
  }
  std::vector<Outcome> out;
  {
    TaylorEnsemble ensemble(tol, tol);
    const py::gil_scoped_release unlocked;
    out = ensemble.integrate(models, states, t0, t_end, options, obs);
  }
  auto body = [&](std::size_t p) -> const Body& { return models[models.size() == 1 ? 0 : p].body; };
  py::dict d;
  py::list outcome;
  py::array_t<std::int64_t> steps(n);
  for (py::ssize_t p = 0; p < n; ++p) {
    const auto i = static_cast<std::size_t>(p);
    outcome.append(std::string(to_string(out[i].status)));
    steps.mutable_at(p) = out[i].steps;
  }
  // m, ω, γ of point p's state x into at[0..8].
  auto fill = [&](std::size_t p, double* at, const State& x) {
    const Vec3 om = omega(body(p), x);
    for (int c = 0; c < 3; ++c) {
      at[c] = x.m[c];
      at[3 + c] = om[c];
      at[6 + c] = x.gamma[c];
    }
  };
  if (times) {
    py::array_t<double> m = nan_array({n, k, 3}), w = nan_array({n, k, 3}),
                        g = nan_array({n, k, 3});
    for (std::size_t p = 0; p < states.size(); ++p) {
      for (py::ssize_t j = 0; j < k; ++j) {
        const double* row = samples.data() + (p * static_cast<std::size_t>(k) + j) * 6;
        if (std::isnan(row[0]) && std::isnan(row[3])) continue;  // after the run stopped
        const State x{Vec3(row[0], row[1], row[2]), Vec3(row[3], row[4], row[5])};
        double v[9];
        fill(p, v, x);
        for (int c = 0; c < 3; ++c) {
          const auto pi = static_cast<py::ssize_t>(p);
          m.mutable_at(pi, j, c) = v[c];
          w.mutable_at(pi, j, c) = v[3 + c];
          g.mutable_at(pi, j, c) = v[6 + c];
        }
      }
    }
    d["t"] = py::array_t<double>(k, t_eval->data());
    d["m"] = m;
    d["omega"] = w;
    d["gamma"] = g;
  } else {
    py::array_t<double> t(n), m = nan_array({n, 3}), w = nan_array({n, 3}), g = nan_array({n, 3});
    for (std::size_t p = 0; p < states.size(); ++p) {
      const auto pi = static_cast<py::ssize_t>(p);
      t.mutable_at(pi) = out[p].t;
      double v[9];
      fill(p, v, out[p].state);
      for (int c = 0; c < 3; ++c) {
        m.mutable_at(pi, c) = v[c];
        w.mutable_at(pi, c) = v[3 + c];
        g.mutable_at(pi, c) = v[6 + c];
      }
    }
    d["t"] = t;
    d["m"] = m;
    d["omega"] = w;
    d["gamma"] = g;
  }
  d["outcome"] = outcome;
  d["steps"] = steps;
  d["order"] = TaylorStepper(tol, tol).order();
  return d;
}

}  // namespace

void bind_ensemble(py::module_& m) {
  m.def("integrate_ensemble", &integrate_ensemble, py::arg("model_or_models"), py::arg("states"),
        py::arg("t_end"), py::kw_only(), py::arg("tol"), py::arg("t0") = 0.0,
        py::arg("max_steps") = py::none(), py::arg("t_eval") = py::none(),
        "Integrates N trajectories of the quadratic field at once with Taylor's method in SIMD "
        "lanes (docs/methods.md, 'Taylor ensemble'): one Model for all or one per state; states a "
        "sequence of State or an (N x 6) array of rows (m, gamma). Each trajectory is the bits of "
        "integrate(model, state, t_end, tol=tol, method='taylor'). Returns a dict: without t_eval "
        "the end of each run, t (N) and m, omega, gamma (N x 3); with t_eval=times (ascending, "
        "in [t0, t_end]) t (k) and m, omega, gamma (N x k x 3), NaN after a run that stopped; "
        "and 'outcome' (N strings), 'steps' (N), 'order'.");
}

}  // namespace newtop::python
