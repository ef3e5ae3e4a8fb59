// Sections and chaos indicators on an orbit (docs/python.md, "Satellites on an orbit"): the
// library's orbit_section and orbit_chaos on an OrbitScenario (a file's or one built in code), as
// typed results whose numeric fields are numpy arrays — the numbers of `newtop section` and
// `newtop chaos` on an orbit scenario, bit for bit.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/orbit_settings.hpp"
#include "newtop/model/attitude.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "newtop/orbit/orbit.hpp"
#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_section.hpp"
#include "orbit_model.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

io::IntegrateOverrides overrides(const std::optional<std::string>& method,
                                 std::optional<double> step, std::optional<double> tol,
                                 std::optional<double> t_end) {
  return {method, step, tol, t_end, std::nullopt};
}

/// The time of the run's variable x: t itself, or t0 + t(ν) − t(ν0) on an ellipse.
double time_of(const io::OrbitScenario& sc, double x) {
  if (const auto* e = std::get_if<EllipticOrbit>(&sc.orbit)) {
    return sc.integrate.t0 + elapsed_time(*e, e->true_anomaly0, x);
  }
  return x;
}

/// ν̇ at a crossing (ω0 on a circular orbit).
double rate_at(const io::OrbitScenario& sc, double x) {
  if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) return c->rate;
  return anomaly_rate(std::get<EllipticOrbit>(sc.orbit), x);
}

struct OrbitSectionOut {
  io::OrbitScenario scenario;
  OrbitSectionResult result;
  std::string surface, direction, method;
};

template <class F>
py::array_t<double> rows_of(const OrbitSectionOut& s, py::ssize_t k, const F& f) {
  const auto& cs = s.result.crossings;
  py::array_t<double> a = k == 1 ? py::array_t<double>(static_cast<py::ssize_t>(cs.size()))
                                 : py::array_t<double>({static_cast<py::ssize_t>(cs.size()), k});
  double* p = a.mutable_data();
  for (const OrbitCrossing& c : cs) {
    f(c, p);
    p += k;
  }
  return a;
}

template <class F>
py::array_t<double> vec3_of(const OrbitSectionOut& s, const F& f) {
  return rows_of(s, 3, [&](const OrbitCrossing& c, double* p) {
    const Vec3 v = f(c);
    p[0] = v[0], p[1] = v[1], p[2] = v[2];
  });
}

OrbitSectionOut section_of(const io::OrbitScenario& sc, const std::optional<double>& t_end,
                           const std::string& surface, std::int64_t crossings,
                           const std::string& direction, const std::optional<std::string>& method,
                           std::optional<double> step, std::optional<double> tol) {
  const phase::Surface sf = phase::parse_surface(surface, "surface");
  const phase::Direction dir = phase::parse_direction(direction, "direction");
  if (crossings < 1) {
    throw InputError("crossings: expected an integer >= 1, found " + std::to_string(crossings));
  }
  phase::SectionRequest request;
  request.method = io::resolve_method(sc, overrides(method, step, tol, std::nullopt));
  request.surface = sf;
  request.direction = dir;
  request.max_crossings = crossings;
  request.t0 = sc.integrate.t0;
  request.t_end = io::resolve_t_end(sc, overrides(std::nullopt, std::nullopt, std::nullopt, t_end));
  request.options.max_steps = sc.integrate.max_steps.value_or(100'000'000);
  const phase::SurfaceFunction g(sf, sc.body, /*with_normal=*/true);  // checks the surface
  OrbitSectionOut out{sc, {}, sf.text, phase::to_string(dir), request.method.name};
  const py::gil_scoped_release unlocked;
  if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) {
    out.result = orbit_section(CircularOrbitModel(sc.body, *c), sc.initial, request);
  } else {
    out.result = orbit_section(EllipticOrbitModel(sc.body, std::get<EllipticOrbit>(sc.orbit)),
                               sc.initial, request);
  }
  return out;
}

void bind_orbit_section(py::module_& m) {
  using S = OrbitSectionOut;
  using C = OrbitCrossing;
  py::class_<S>(m, "OrbitSection",
                "The crossings of a Poincare section on an orbit (docs/section.md \"Orbit "
                "scenarios\"): the result of newtop.section(orbit_scenario), as `newtop section "
                "--json` on an orbit scenario.")
      .def_readonly("surface", &S::surface)
      .def_readonly("direction", &S::direction)
      .def_readonly("method", &S::method)
      .def_property_readonly("count", [](const S& s) { return s.result.crossings.size(); })
      .def_property_readonly(
          "orbit", [](const S& s) { return s.scenario.circular() ? "circular" : "elliptic"; },
          "the kind of orbit")
      .def_property_readonly(
          "t",
          [](const S& s) {
            return rows_of(s, 1, [&](const C& c, double* p) { *p = time_of(s.scenario, c.t); });
          },
          "(N,) the time of each crossing")
      .def_property_readonly(
          "nu",
          [](const S& s) -> std::optional<py::array_t<double>> {
            if (s.scenario.circular()) return std::nullopt;
            return rows_of(s, 1, [](const C& c, double* p) { *p = c.t; });
          },
          "(N,) the true anomaly of each crossing on an ellipse, None on a circle")
      .def_property_readonly("omega",
                             [](const S& s) {
                               return vec3_of(
                                   s, [&](const C& c) { return omega(s.scenario.body, c.x); });
                             })
      .def_property_readonly(
          "gamma", [](const S& s) { return vec3_of(s, [](const C& c) { return c.x.gamma; }); })
      .def_property_readonly(
          "m", [](const S& s) { return vec3_of(s, [](const C& c) { return c.x.m; }); })
      .def_property_readonly(
          "normal", [](const S& s) { return vec3_of(s, [](const C& c) { return c.x.normal; }); })
      .def_property_readonly(
          "euler_321",
          [](const S& s) {
            return vec3_of(s, [&](const C& c) {
              return orbit_frame_coords(s.scenario.body, c.x, rate_at(s.scenario, c.t)).euler_321;
            });
          })
      .def_property_readonly("omega_relative",
                             [](const S& s) {
                               return vec3_of(s, [&](const C& c) {
                                 return orbit_frame_coords(s.scenario.body, c.x,
                                                           rate_at(s.scenario, c.t))
                                     .omega_relative;
                               });
                             })
      .def_property_readonly("roll_pitch_yaw",
                             [](const S& s) {
                               return vec3_of(
                                   s, [](const C& c) { return roll_pitch_yaw(lvlh_to_body(c.x)); });
                             })
      .def_property_readonly("lvlh_quaternion",
                             [](const S& s) {
                               return rows_of(s, 4, [](const C& c, double* p) {
                                 const std::array<double, 4> q =
                                     scalar_first(lvlh_quaternion(lvlh_to_body(c.x)));
                                 std::copy(q.begin(), q.end(), p);
                               });
                             })
      .def_property_readonly(
          "crossing_orbit",
          [](const S& s) {
            py::array_t<int> a(static_cast<py::ssize_t>(s.result.crossings.size()));
            int* p = a.mutable_data();
            for (const C& c : s.result.crossings) *p++ = c.orbit;
            return a;
          },
          "(N,) the start of each crossing (0: one start)")
      .def_property_readonly(
          "stopped_by",
          [](const S& s) {
            return s.result.status == phase::SectionStatus::crossings ? "crossings" : "t_end";
          })
      .def_property_readonly("max_surface_residual",
                             [](const S& s) { return s.result.max_residual; })
      .def_property_readonly("integrals_drift",
                             [](const S& s) {
                               const OrbitSectionDrift& d = s.result.drift;
                               py::dict j;
                               if (!d.started) return j;
                               if (d.has_jacobi) j["jacobi"] = d.jacobi;
                               j["gamma_gamma"] = d.gamma_gamma;
                               j["normal_normal"] = d.normal_normal;
                               j["gamma_normal"] = d.gamma_normal;
                               return j;
                             })
      .def_property_readonly("outcome",
                             [](const S& s) { return std::string(to_string(s.result.outcome)); });
  m.def("_orbit_section", &section_of, py::arg("scenario"), py::kw_only(),
        py::arg("t_end") = py::none(), py::arg("surface") = "gamma3 = 0",
        py::arg("crossings") = 1000, py::arg("direction") = "up", py::arg("method") = py::none(),
        py::arg("step") = py::none(), py::arg("tol") = py::none());
}

struct OrbitChaosOut {
  OrbitChaosResult result;
  std::string method, orbit;
  double tol = 0;
  std::vector<phase::ChaosSample> history;
};

OrbitChaosOut chaos_of(const io::OrbitScenario& sc, const std::optional<double>& t_end,
                       const std::optional<std::string>& method, std::optional<double> tol,
                       bool spectrum, bool history) {
  OrbitChaosSettings st;
  st.method = io::resolve_method(sc, overrides(method, std::nullopt, tol, std::nullopt));
  st.t0 = sc.integrate.t0;
  st.t1 = io::resolve_t_end(sc, overrides(std::nullopt, std::nullopt, std::nullopt, t_end));
  st.spectrum = spectrum;
  st.max_steps = sc.integrate.max_steps.value_or(100'000'000);
  check_orbit_chaos_settings(st);
  OrbitChaosOut out;
  out.method = st.method.name;
  out.tol = st.method.abs_tol;
  out.orbit = sc.circular() ? "circular" : "elliptic";
  if (history) st.history = [&out](const phase::ChaosSample& s) { out.history.push_back(s); };
  const py::gil_scoped_release unlocked;
  if (const auto* c = std::get_if<CircularOrbit>(&sc.orbit)) {
    out.result = orbit_chaos(CircularOrbitModel(sc.body, *c), sc.initial, st);
  } else {
    out.result =
        orbit_chaos(EllipticOrbitModel(sc.body, std::get<EllipticOrbit>(sc.orbit)), sc.initial, st);
  }
  return out;
}

py::array_t<double> history_column(const OrbitChaosOut& c, double phase::ChaosSample::*f) {
  py::array_t<double> a(static_cast<py::ssize_t>(c.history.size()));
  double* p = a.mutable_data();
  for (const auto& s : c.history) *p++ = s.*f;
  return a;
}

void bind_orbit_chaos(py::module_& m) {
  using O = OrbitChaosOut;
  using S = phase::ChaosSample;
  py::class_<O>(m, "OrbitChaosResult",
                "Chaos indicators on an orbit (docs/orbit.md §13): the result of "
                "newtop.chaos(orbit_scenario), as `newtop chaos --json` on an orbit scenario.")
      .def_property_readonly("lyapunov_max",
                             [](const O& c) { return c.result.indicators.lyapunov_max; })
      .def_property_readonly("megno", [](const O& c) { return c.result.indicators.megno; })
      .def_property_readonly("megno_y", [](const O& c) { return c.result.indicators.megno_y; })
      .def_property_readonly("fli", [](const O& c) { return c.result.indicators.fli; })
      .def_property_readonly(
          "spectrum",
          [](const O& c) -> std::optional<py::array_t<double>> {
            const auto& s = c.result.indicators.spectrum;
            if (!s) return std::nullopt;
            py::array_t<double> a(6);
            std::copy(s->begin(), s->end(), a.mutable_data());
            return a;
          },
          "(6,) the exponents of the symplectic leaf, or None without spectrum=True")
      .def_property_readonly("t_end", [](const O& c) { return c.result.t; })
      .def_property_readonly(
          "outcome", [](const O& c) { return std::string(to_string(c.result.outcome.status)); })
      .def_readonly("method", &O::method)
      .def_readonly("tol", &O::tol)
      .def_readonly("orbit", &O::orbit)
      .def_property_readonly(
          "history",
          [](const O& c) -> py::object {
            if (c.history.empty()) return py::none();
            py::dict d;
            d["t"] = history_column(c, &S::t);
            d["lyapunov_max"] = history_column(c, &S::lyapunov_max);
            d["megno_y"] = history_column(c, &S::megno_y);
            d["megno"] = history_column(c, &S::megno);
            d["fli"] = history_column(c, &S::fli);
            return d;
          },
          "with history=True: the indicators after every step (arrays), else None");
  m.def("_orbit_chaos", &chaos_of, py::arg("scenario"), py::kw_only(),
        py::arg("t_end") = py::none(), py::arg("method") = py::none(), py::arg("tol") = py::none(),
        py::arg("spectrum") = false, py::arg("history") = false);
}

}  // namespace

void bind_orbit_phase(py::module_& m) {
  bind_orbit_section(m);
  bind_orbit_chaos(m);
}

}  // namespace newtop::python
