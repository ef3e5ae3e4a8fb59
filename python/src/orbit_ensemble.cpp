// integrate_ensemble() on orbit models: many satellites at once through the orbit's Taylor
// ensemble (newtop/orbit/orbit_taylor_ensemble.hpp), into numpy arrays; each trajectory the bits
// of the end of integrate(model, state, t_end, tol=tol, method='taylor') of that point.

#include "orbit_ensemble.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "newtop/orbit/orbit.hpp"
#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_taylor_ensemble.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

std::vector<OrbitModel> orbit_models(const py::object& models) {
  if (py::isinstance<OrbitModel>(models)) return {models.cast<OrbitModel>()};
  return models.cast<std::vector<OrbitModel>>();
}

/// A sequence of OrbitState, or an (N × 9) array of rows (m, γ, n); each checked as
/// integrate() checks its state.
std::vector<OrbitState> orbit_states(const py::object& states) try {
  std::vector<OrbitState> x;
  if (py::isinstance<py::array>(states)) {
    const auto a = states.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
    if (a.ndim() != 2 || a.shape(1) != 9) {
      throw InputError(
          "states: expected an (N x 9) array of rows (m, gamma, normal), found shape " +
          std::string(py::str(states.attr("shape"))));
    }
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
      x.push_back({Vec3(a.at(i, 0), a.at(i, 1), a.at(i, 2)),
                   Vec3(a.at(i, 3), a.at(i, 4), a.at(i, 5)),
                   Vec3(a.at(i, 6), a.at(i, 7), a.at(i, 8))});
    }
  } else {
    x = states.cast<std::vector<OrbitState>>();
  }
  for (const OrbitState& s : x) check_state(s);
  return x;
} catch (const py::cast_error&) {
  throw InputError(
      "states: expected a sequence of OrbitState or an (N x 9) array of numbers (rows m, gamma, "
      "normal), found " +
      std::string(py::str(py::type::of(states).attr("__name__"))));
}

/// The runs of the points `idx` (all of one kind of orbit; on an ellipse sharing ν0 and ν1), as
/// run_orbit_method runs each: the first trial step |b − a|/1000.
template <class M>
void run_group(const std::vector<M>& models, const std::vector<OrbitState>& x,
               const std::vector<std::size_t>& idx, double a, double b, std::int64_t max_steps,
               double tol, std::vector<OrbitOutcome>& out) {
  std::vector<M> m;
  std::vector<OrbitState> s;
  for (std::size_t i : idx) {
    m.push_back(models.size() == 1 ? models[0] : models[i]);
    s.push_back(x[i]);
  }
  IntegrateOptions o;
  o.max_steps = max_steps;
  o.initial_step = std::abs(b - a) / 1000.0;
  OrbitTaylorEnsemble e(tol, tol);
  const std::vector<OrbitOutcome> r = e.integrate(m, s, a, b, o);
  for (std::size_t j = 0; j < idx.size(); ++j) out[idx[j]] = r[j];
}

void check_models(const std::vector<OrbitModel>& models, std::size_t states) {
  if (models.size() != 1 && models.size() != states) {
    throw InputError("model_or_models: expected 1 or one per state (" + std::to_string(states) +
                     "), found " + std::to_string(models.size()));
  }
  for (const OrbitModel& m : models) {
    if (m.circular() != models[0].circular()) {
      throw InputError("model_or_models: expected orbits of one kind, found circular and elliptic");
    }
  }
}

}  // namespace

bool is_orbit_models(const py::object& models) {
  if (py::isinstance<OrbitModel>(models)) return true;
  if (!py::isinstance<py::sequence>(models) || py::isinstance<py::str>(models)) return false;
  const auto seq = models.cast<py::sequence>();
  return seq.size() > 0 && py::isinstance<OrbitModel>(seq[0]);
}

py::dict orbit_integrate_ensemble(const py::object& model_or_models, const py::object& states_in,
                                  double t_end, double tol, double t0,
                                  std::optional<std::int64_t> max_steps, bool t_eval) {
  if (t_eval) {
    throw InputError(
        "t_eval: not available for orbit models in integrate_ensemble (the end of each run only; "
        "newtop.integrate(model, state, t_end, tol=..., t_eval=...) samples one satellite)");
  }
  const std::vector<OrbitModel> models = orbit_models(model_or_models);
  const std::vector<OrbitState> x = orbit_states(states_in);
  check_models(models, x.size());
  if (!std::isfinite(t0))
    throw InputError("t0: expected a finite time, found " + format_number(t0));
  if (!std::isfinite(t_end) || !(t_end > t0)) {
    throw InputError("t_end: expected a finite time > t0 = " + format_number(t0) + ", found " +
                     format_number(t_end));
  }
  const std::int64_t limit = max_steps.value_or(OrbitAdaptiveOptions{}.max_steps);
  if (limit < 1)
    throw InputError("max_steps: expected an integer >= 1, found " + std::to_string(limit));
  const OrbitTaylorEnsemble check(tol, tol);  // the tolerance's checks before any work
  const std::size_t n = x.size();
  std::vector<OrbitOutcome> out(n);
  std::vector<double> t(n, t_end);
  {
    const py::gil_scoped_release unlocked;
    auto model = [&](std::size_t i) -> const OrbitModel& {
      return models[models.size() == 1 ? 0 : i];
    };
    if (models[0].circular()) {
      std::vector<CircularOrbitModel> c;
      for (const OrbitModel& m : models) c.push_back(std::get<CircularOrbitModel>(m.model));
      std::vector<std::size_t> all(n);
      for (std::size_t i = 0; i < n; ++i) all[i] = i;
      if (n > 0) run_group(c, x, all, t0, t_end, limit, tol, out);
      for (std::size_t i = 0; i < n; ++i) t[i] = out[i].t;
    } else {
      // In ν: the points that share ν0 and ν1 run together (each the same bits on its own).
      std::vector<EllipticOrbitModel> e;
      for (const OrbitModel& m : models) e.push_back(std::get<EllipticOrbitModel>(m.model));
      std::map<std::pair<double, double>, std::vector<std::size_t>> groups;
      for (std::size_t i = 0; i < n; ++i) {
        const EllipticOrbit& o = std::get<EllipticOrbitModel>(model(i).model).orbit();
        groups[{o.true_anomaly0, true_anomaly_at(o, t_end - t0)}].push_back(i);
      }
      for (const auto& [span, idx] : groups)
        run_group(e, x, idx, span.first, span.second, limit, tol, out);
      for (std::size_t i = 0; i < n; ++i) {  // the time reached, as integrate()'s t column
        const EllipticOrbit& o = std::get<EllipticOrbitModel>(model(i).model).orbit();
        t[i] = t0 + elapsed_time(o, o.true_anomaly0, out[i].t);
      }
    }
  }
  const auto N = static_cast<py::ssize_t>(n);
  std::vector<double> m(3 * n), w(3 * n), g(3 * n), nrm(3 * n);
  py::list outcome;
  std::vector<std::int64_t> steps;
  for (std::size_t i = 0; i < n; ++i) {
    const OrbitState& s = out[i].state;
    const Vec3 om = omega(models[models.size() == 1 ? 0 : i].body(), s);
    for (int c = 0; c < 3; ++c) {
      m[3 * i + c] = s.m[c];
      w[3 * i + c] = om[c];
      g[3 * i + c] = s.gamma[c];
      nrm[3 * i + c] = s.normal[c];
    }
    outcome.append(std::string(to_string(out[i].status)));
    steps.push_back(out[i].steps);
  }
  py::dict d;
  d["t"] = py::array_t<double>(N, t.data());
  if (!models[0].circular()) {
    std::vector<double> nu;
    for (const OrbitOutcome& o : out) nu.push_back(o.t);
    d["nu"] = py::array_t<double>(N, nu.data());
  }
  d["m"] = py::array_t<double>({N, py::ssize_t{3}}, m.data());
  d["omega"] = py::array_t<double>({N, py::ssize_t{3}}, w.data());
  d["gamma"] = py::array_t<double>({N, py::ssize_t{3}}, g.data());
  d["normal"] = py::array_t<double>({N, py::ssize_t{3}}, nrm.data());
  d["outcome"] = outcome;
  d["steps"] = py::array_t<std::int64_t>(N, steps.data());
  d["order"] = check.order();
  return d;
}

py::dict orbit_chaos_ensemble(const py::object& model_or_models, const py::object& states_in,
                              double t_end, double tol, double t0,
                              std::optional<std::int64_t> max_steps) {
  const std::vector<OrbitModel> models = orbit_models(model_or_models);
  const std::vector<OrbitState> x = orbit_states(states_in);
  check_models(models, x.size());
  OrbitChaosSettings check;  // orbit_chaos's checks before any work
  check.method = MethodSettings("taylor", 0.0, tol, tol);
  check.t0 = t0;
  check.t1 = t_end;
  check.max_steps = max_steps.value_or(check.max_steps);
  check_orbit_chaos_settings(check);
  if (check.max_steps < 1) {
    throw InputError("max_steps: expected an integer >= 1, found " +
                     std::to_string(check.max_steps));
  }
  const std::size_t n = x.size();
  std::vector<OrbitOutcome> out(n);
  std::vector<phase::ChaosIndicators> ind(n, phase::ChaosIndicators(t0, 1));
  {
    const py::gil_scoped_release unlocked;
    auto model = [&](std::size_t i) -> const OrbitModel& {
      return models[models.size() == 1 ? 0 : i];
    };
    // Points that share the run's start and end (on an ellipse ν0 and ν1) run together; each
    // point's indicators accumulated at the time of each of its steps, as orbit_chaos does.
    std::map<std::pair<double, double>, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < n; ++i) {
      if (model(i).circular()) {
        groups[{t0, t_end}].push_back(i);
      } else {
        const EllipticOrbit& o = std::get<EllipticOrbitModel>(model(i).model).orbit();
        groups[{o.true_anomaly0, true_anomaly_at(o, t_end - t0)}].push_back(i);
      }
    }
    for (const auto& [span, idx] : groups) {
      IntegrateOptions o;  // orbit_chaos's
      o.max_steps = check.max_steps;
      o.initial_step = std::abs(span.second - span.first) / 1000.0;
      OrbitTaylorEnsemble e(tol, tol);
      std::vector<OrbitState> s;
      for (std::size_t i : idx) s.push_back(x[i]);
      auto grow = [&](std::size_t j, double t, double g) {
        ind[idx[j]].accumulate(t, {g, 0.0, 0.0, 0.0, 0.0, 0.0});
      };
      std::vector<OrbitOutcome> r;
      if (models[0].circular()) {
        std::vector<CircularOrbitModel> m;
        for (std::size_t i : idx) m.push_back(std::get<CircularOrbitModel>(model(i).model));
        r = e.integrate_chaos(
            m, s, span.first, span.second, o,
            [&](std::size_t j, double t, const OrbitState&, double g) { grow(j, t, g); });
      } else {
        std::vector<EllipticOrbitModel> m;
        for (std::size_t i : idx) m.push_back(std::get<EllipticOrbitModel>(model(i).model));
        r = e.integrate_chaos(m, s, span.first, span.second, o,
                              [&](std::size_t j, double nu, const OrbitState&, double g) {
                                grow(j, t0 + elapsed_time(m[j].orbit(), span.first, nu), g);
                              });
      }
      for (std::size_t j = 0; j < idx.size(); ++j) out[idx[j]] = r[j];
    }
  }
  std::vector<double> megno, lyapunov, fli;
  py::list outcome;
  for (std::size_t i = 0; i < n; ++i) {
    const phase::ChaosSample c = ind[i].sample();
    megno.push_back(c.megno);
    lyapunov.push_back(c.lyapunov_max);
    fli.push_back(c.fli);
    outcome.append(std::string(to_string(out[i].status)));
  }
  const auto N = static_cast<py::ssize_t>(n);
  py::dict d;
  d["megno"] = py::array_t<double>(N, megno.data());
  d["lyapunov_max"] = py::array_t<double>(N, lyapunov.data());
  d["fli"] = py::array_t<double>(N, fli.data());
  d["outcome"] = outcome;
  return d;
}

}  // namespace newtop::python
