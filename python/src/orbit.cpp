// The satellite on an orbit from Python (docs/python.md, "Satellites on an orbit"): OrbitModel,
// OrbitState, OrbitScenario, and load_scenario / parse_scenario reading orbit files as well.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <numbers>
#include <string>

#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "orbit_model.hpp"

namespace py = pybind11;

namespace newtop::python {

const CircularOrbitModel& OrbitModel::circular_model() const {
  if (!circular()) {
    throw InputError(
        "kind: expected a circular orbit (relative equilibria are at rest in a uniformly turning "
        "frame), found \"elliptic\"");
  }
  return std::get<CircularOrbitModel>(model);
}

OrbitModel OrbitModel::of(const io::OrbitScenario& sc) {
  OrbitModel m{std::visit(
                   [&](const auto& o) -> decltype(OrbitModel::model) {
                     return BasicOrbitModel<std::decay_t<decltype(o)>>(sc.body, o);
                   },
                   sc.orbit),
               sc.mu, sc.radius};
  return m;
}

namespace {

/// |γ| = 1, |n| = 1 and γ·n = 0 to this, as the scenario's [initial] (newtop/io/orbit_scenario):
/// values written with 12 significant digits pass.
constexpr double kOrbitUnitTolerance = 1e-12;

OrbitState checked(const Vec3& m, const Vec3& gamma, const Vec3& normal) {
  const OrbitState s{m, gamma, normal};
  check_orbit_state(s, kOrbitUnitTolerance);
  return s;
}

/// The orbital frame (columns γ, n × γ, n) of the attitude C(body←LVLH) (columns n × γ, −n, −γ).
Mat3 frame_of_lvlh(const Mat3& C) {
  Mat3 F;
  F.col(0) = -C.col(2);
  F.col(1) = C.col(0);
  F.col(2) = -C.col(1);
  return F;
}

double rate_at_start(const OrbitModel& m) {
  if (m.circular()) return std::get<CircularOrbitModel>(m.model).orbit().rate;
  const EllipticOrbit& e = std::get<EllipticOrbitModel>(m.model).orbit();
  return anomaly_rate(e, e.true_anomaly0);
}

OrbitState from_lvlh(const OrbitModel& model, const std::optional<Vec3>& rpy,
                     const std::optional<Eigen::Vector4d>& q, const Vec3& omega_relative) {
  if (rpy.has_value() == q.has_value()) {
    throw InputError("roll_pitch_yaw, lvlh_quaternion: expected exactly one of them, found " +
                     std::string(rpy ? "both" : "neither"));
  }
  Mat3 C;
  if (rpy) {
    if (!rpy->allFinite()) {
      throw InputError("roll_pitch_yaw: expected finite numbers, found " + format_vector(*rpy));
    }
    C = body_from_roll_pitch_yaw(*rpy);
  } else {
    const double n = q->norm();
    if (!q->allFinite() || !(std::abs(n - 1.0) <= kOrbitUnitTolerance)) {
      throw InputError(
          "lvlh_quaternion: expected a unit quaternion (|q| = 1 to 1e-12), found |q| = " +
          format_number(n));
    }
    C = Quaternion((*q)[0], (*q)[1], (*q)[2], (*q)[3]).normalized().toRotationMatrix().transpose();
  }
  if (!omega_relative.allFinite()) {
    throw InputError("omega_relative: expected finite numbers, found " +
                     format_vector(omega_relative));
  }
  return state_from_relative(model.body(), frame_of_lvlh(C), omega_relative, rate_at_start(model));
}

Eigen::Matrix<double, 9, 1> stacked(const OrbitState& d) {
  Eigen::Matrix<double, 9, 1> v;
  v << d.m, d.gamma, d.normal;
  return v;
}

void bind_orbit_model(py::module_& m) {
  py::class_<OrbitModel>(m, "OrbitModel",
                         "A body turning about its centre of mass, which moves on a circular or an "
                         "elliptic Kepler orbit (docs/orbit.md §1-§3).")
      .def_static(
          "circular",
          [](const Body& body, std::optional<double> mu, std::optional<double> radius,
             std::optional<double> rate) {
            if (rate && !mu && !radius)
              return OrbitModel{CircularOrbitModel(body, CircularOrbit::from_rate(*rate)), {}, {}};
            if (!(mu && radius && !rate)) {
              throw InputError("mu, radius: expected either mu and radius, or rate");
            }
            return OrbitModel{CircularOrbitModel(body, CircularOrbit::from_mu_radius(*mu, *radius)),
                              mu, radius};
          },
          py::arg("body"), py::kw_only(), py::arg("mu") = py::none(),
          py::arg("radius") = py::none(), py::arg("rate") = py::none(),
          "Circular orbit of radius R about a centre of parameter mu (omega0 = sqrt(mu/R^3), "
          "lambda = 3 omega0^2), or of the given rate omega0; the body turns about its centre "
          "of mass (r0 = 0).")
      .def_static(
          "elliptic",
          [](const Body& body, double mu, double a, double e, double true_anomaly) {
            return OrbitModel{
                EllipticOrbitModel(body, EllipticOrbit::from_mu_axis(mu, a, e, true_anomaly)), mu,
                a};
          },
          py::arg("body"), py::kw_only(), py::arg("mu"), py::arg("a"), py::arg("e"),
          py::arg("true_anomaly") = 0.0,
          "Kepler ellipse of semi-major axis a and eccentricity 0 <= e < 1 about a centre of "
          "parameter mu, started at the true anomaly nu0 (radians from periapsis).")
      .def_property_readonly(
          "kind", [](const OrbitModel& x) { return x.circular() ? "circular" : "elliptic"; })
      .def_property_readonly("body", [](const OrbitModel& x) { return x.body(); })
      .def_readonly("mu", &OrbitModel::mu, "mu when given, else None")
      .def_readonly("radius", &OrbitModel::radius, "R (circular) or a (elliptic) when given")
      .def_property_readonly(
          "rate",
          [](const OrbitModel& x) {
            return x.circular() ? std::get<CircularOrbitModel>(x.model).orbit().rate
                                : std::get<EllipticOrbitModel>(x.model).orbit().mean_motion;
          },
          "omega0 (circular) or the mean motion n (elliptic)")
      .def_property_readonly(
          "lambda_",
          [](const OrbitModel& x) -> std::optional<double> {
            if (!x.circular()) return std::nullopt;
            return std::get<CircularOrbitModel>(x.model).orbit().lambda_;
          },
          "lambda = 3 mu/R^3 (circular); None on an ellipse (it depends on nu)")
      .def_property_readonly(
          "eccentricity",
          [](const OrbitModel& x) {
            return x.circular() ? 0.0 : std::get<EllipticOrbitModel>(x.model).orbit().eccentricity;
          })
      .def_property_readonly(
          "true_anomaly",
          [](const OrbitModel& x) {
            return x.circular() ? 0.0 : std::get<EllipticOrbitModel>(x.model).orbit().true_anomaly0;
          })
      .def_property_readonly(
          "period",
          [](const OrbitModel& x) {
            const double n = x.circular()
                                 ? std::get<CircularOrbitModel>(x.model).orbit().rate
                                 : std::get<EllipticOrbitModel>(x.model).orbit().mean_motion;
            return 2 * std::numbers::pi / n;
          },
          "2 pi / omega0 or 2 pi / n")
      .def(
          "rhs",
          [](const OrbitModel& x, const OrbitState& s, std::optional<double> nu) {
            if (x.circular()) {
              if (nu)
                throw InputError("nu: not on a circular orbit (the equations are autonomous)");
              return stacked(rhs(std::get<CircularOrbitModel>(x.model), s));
            }
            const auto& e = std::get<EllipticOrbitModel>(x.model);
            return stacked(rhs(e, s, nu.value_or(e.orbit().true_anomaly0)));
          },
          py::arg("state"), py::arg("nu") = py::none(),
          "(9,): dm, dgamma, dnormal per unit time (circular) or per unit true anomaly at nu "
          "(elliptic; nu0 by default)")
      .def(
          "integral",
          [](const OrbitModel& x, const OrbitState& s, std::optional<double> nu) {
            if (x.circular()) return jacobi_integral(std::get<CircularOrbitModel>(x.model), s);
            const auto& e = std::get<EllipticOrbitModel>(x.model);
            return hamiltonian(e, s, nu.value_or(e.orbit().true_anomaly0));
          },
          py::arg("state"), py::arg("nu") = py::none(),
          "The Jacobi integral (circular) or the generator H_nu at nu (elliptic), docs/orbit.md")
      .def("__repr__", [](const OrbitModel& x) {
        return std::string("OrbitModel(") + (x.circular() ? "circular" : "elliptic") + ")";
      });
}

void bind_orbit_state(py::module_& m) {
  py::class_<OrbitState>(
      m, "OrbitState",
      "The orbit model's state in body axes (docs/orbit.md §2): m = I omega + k, "
      "gamma (centre -> body) and the orbit normal n.")
      .def(py::init(&checked), py::arg("m"), py::arg("gamma"), py::arg("normal"),
           "m finite; |gamma| = |normal| = 1 and gamma.normal = 0 to 1e-12")
      .def_static(
          "from_omega",
          [](const Body& body, const Vec3& w, const Vec3& gamma, const Vec3& normal) {
            if (!w.allFinite()) {
              throw InputError("omega: expected finite numbers, found " + format_vector(w));
            }
            return checked(body.inertia().cwiseProduct(w) + body.gyrostat(), gamma, normal);
          },
          py::arg("body"), py::arg("omega"), py::arg("gamma"), py::arg("normal"),
          "m = I omega + k (omega the inertial angular velocity)")
      .def_static("from_lvlh", &from_lvlh, py::arg("model"), py::kw_only(),
                  py::arg("roll_pitch_yaw") = py::none(), py::arg("lvlh_quaternion") = py::none(),
                  py::arg("omega_relative") = Vec3::Zero().eval(),
                  "The state at the attitude relative to LVLH (docs/orbit.md §11: roll, pitch, "
                  "yaw or q0..q3 of C(body<-LVLH)) with the angular velocity relative to the "
                  "orbital frame, as [initial] roll_pitch_yaw / lvlh_quaternion with "
                  "omega_relative; the orbit's rate at its start.")
      .def_readonly("m", &OrbitState::m)
      .def_readonly("gamma", &OrbitState::gamma)
      .def_readonly("normal", &OrbitState::normal)
      .def(
          "omega", [](const OrbitState& s, const Body& b) { return omega(b, s); }, py::arg("body"),
          "omega = I^-1 (m - k)")
      .def(
          "lvlh_quaternion",
          [](const OrbitState& s) { return scalar_first(lvlh_quaternion(lvlh_to_body(s))); },
          "[q0, q1, q2, q3] of C(body<-LVLH), q0 >= 0")
      .def(
          "roll_pitch_yaw", [](const OrbitState& s) { return roll_pitch_yaw(lvlh_to_body(s)); },
          "C(body<-LVLH) = R1(roll) R2(pitch) R3(yaw)")
      .def("__repr__", [](const OrbitState& s) {
        return "OrbitState(m=" + format_vector(s.m) + ", gamma=" + format_vector(s.gamma) +
               ", normal=" + format_vector(s.normal) + ")";
      });
}

void bind_orbit_scenario(py::module_& m) {
  py::class_<io::OrbitScenario>(
      m, "OrbitScenario",
      "An orbit scenario (docs/scenario.md, \"Orbit scenarios\"): a body, "
      "its orbit, the initial state and [integrate].")
      .def(py::init([](const OrbitModel& model, const OrbitState& initial, double t0,
                       std::optional<double> t_end, std::optional<std::string> method,
                       std::optional<double> step, std::optional<double> tol,
                       std::optional<std::int64_t> max_steps) {
             check_orbit_state(initial, kOrbitUnitTolerance);
             io::OrbitScenario s{
                 "<python>",
                 model.body(),
                 std::visit([](const auto& x) -> decltype(s.orbit) { return x.orbit(); },
                            model.model),
                 initial,
                 {},
                 {},
                 model.mu,
                 model.radius};
             s.integrate = {std::move(method), step, tol, t_end, t0, max_steps, std::nullopt};
             return s;
           }),
           py::arg("model"), py::arg("initial"), py::kw_only(), py::arg("t0") = 0.0,
           py::arg("t_end") = py::none(), py::arg("method") = py::none(),
           py::arg("step") = py::none(), py::arg("tol") = py::none(),
           py::arg("max_steps") = py::none())
      .def_readonly("source", &io::OrbitScenario::source)
      .def_property_readonly("model", &OrbitModel::of)
      .def_property(
          "initial", [](const io::OrbitScenario& s) { return s.initial; },
          [](io::OrbitScenario& s, const OrbitState& x) {
            check_orbit_state(x, kOrbitUnitTolerance);
            s.initial = x;
          })
      .def_property_readonly(
          "kind", [](const io::OrbitScenario& s) { return s.circular() ? "circular" : "elliptic"; })
      .def_property(
          "t0", [](const io::OrbitScenario& s) { return s.integrate.t0; },
          [](io::OrbitScenario& s, double v) { s.integrate.t0 = v; })
      .def_property(
          "t_end", [](const io::OrbitScenario& s) { return s.integrate.t_end; },
          [](io::OrbitScenario& s, std::optional<double> v) { s.integrate.t_end = v; })
      .def_property(
          "method", [](const io::OrbitScenario& s) { return s.integrate.method; },
          [](io::OrbitScenario& s, std::optional<std::string> v) { s.integrate.method = v; })
      .def_property(
          "step", [](const io::OrbitScenario& s) { return s.integrate.step; },
          [](io::OrbitScenario& s, std::optional<double> v) { s.integrate.step = v; })
      .def_property(
          "tol", [](const io::OrbitScenario& s) { return s.integrate.tol; },
          [](io::OrbitScenario& s, std::optional<double> v) { s.integrate.tol = v; })
      .def_property_readonly("max_steps",
                             [](const io::OrbitScenario& s) { return s.integrate.max_steps; })
      .def("__repr__",
           [](const io::OrbitScenario& s) { return "OrbitScenario('" + s.source + "')"; });
}

/// load_scenario and parse_scenario as bound by bind_model, now reading orbit files too: an [orbit]
/// table gives an OrbitScenario.
void extend_scenario_readers(py::module_& m) {
  const py::object load = m.attr("load_scenario"), parse = m.attr("parse_scenario");
  m.attr("load_scenario") = py::cpp_function(
      [load](const std::string& path) -> py::object {
        if (io::is_orbit_scenario(path)) return py::cast(io::load_orbit_scenario(path));
        return load(path);
      },
      py::name("load_scenario"), py::arg("path"),
      "Reads and checks a scenario file: a Scenario, or an OrbitScenario for a file with [orbit]; "
      "ValueError with the command line's message otherwise.");
  m.attr("parse_scenario") = py::cpp_function(
      [parse](const std::string& text, const std::string& source) -> py::object {
        if (io::is_orbit_scenario_text(text)) {
          return py::cast(io::parse_orbit_scenario(text, source));
        }
        return parse(text, source);
      },
      py::name("parse_scenario"), py::arg("text"), py::arg("source") = "<string>",
      "Parses scenario text: a Scenario, or an OrbitScenario for text with [orbit].");
}

}  // namespace

void bind_orbit(py::module_& m) {
  bind_orbit_model(m);
  bind_orbit_state(m);
  bind_orbit_scenario(m);
  extend_scenario_readers(m);
}

}  // namespace newtop::python
