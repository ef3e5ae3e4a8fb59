// Body, QuadraticField, Model, State and Scenario (docs/model.md §1–§5) as Python classes.

#include "newtop/model/model.hpp"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/model/state_checks.hpp"

namespace py = pybind11;

namespace newtop::python {

py::dict integrals_dict(const IntegralValues& v) {
  py::dict d;
  d["energy"] = v.energy;
  d["area"] = v.area;
  d["geometric"] = v.geometric;
  if (v.brun) d["brun"] = *v.brun;
  if (v.lagrange) d["lagrange"] = *v.lagrange;
  return d;
}

namespace {

void bind_body(py::module_& m) {
  py::class_<Body>(m, "Body",
                   "A rigid body (or gyrostat) about a fixed point O (docs/model.md §1): principal "
                   "moments (A, B, C), mass M, centre of mass r0 and gyrostatic moment k, in the "
                   "principal axes Oxyz.")
      .def_static("from_principal", &Body::from_principal, py::arg("inertia"),
                  py::arg("mass") = 0.0, py::arg("center_of_mass") = Vec3::Zero().eval(),
                  py::arg("gyrostat") = Vec3::Zero().eval(),
                  "Body from principal moments (A, B, C) > 0 with the triangle inequalities, mass "
                  "M >= 0, r0 and k in the principal axes. ValueError names the offending field.")
      .def_static("from_tensor", &Body::from_tensor, py::arg("inertia_tensor"),
                  py::arg("mass") = 0.0, py::arg("center_of_mass") = Vec3::Zero().eval(),
                  py::arg("gyrostat") = Vec3::Zero().eval(),
                  "Body from a symmetric 3x3 inertia tensor J at O in a user frame: J is "
                  "diagonalised, r0 and k are converted by P^T (principal_axes = P).")
      .def_property_readonly("inertia", &Body::inertia, "(A, B, C)")
      .def_property_readonly("A", &Body::A)
      .def_property_readonly("B", &Body::B)
      .def_property_readonly("C", &Body::C)
      .def_property_readonly("mass", &Body::mass, "M")
      .def_property_readonly("center_of_mass", &Body::center_of_mass, "r0 = (x0, y0, z0)")
      .def_property_readonly("gyrostat", &Body::gyrostat, "k = (k1, k2, k3)")
      .def_property_readonly("principal_axes", &Body::principal_axes,
                             "P: columns are the principal axes in the user's frame")
      .def("__repr__", [](const Body& b) {
        return "Body(inertia=" + format_vector(b.inertia()) + ", mass=" + format_number(b.mass()) +
               ", center_of_mass=" + format_vector(b.center_of_mass()) +
               ", gyrostat=" + format_vector(b.gyrostat()) + ")";
      });
}

void bind_field(py::module_& m) {
  py::class_<QuadraticField>(m, "QuadraticField",
                             "The quadratic field of docs/model.md §3: V(gamma) = M g r0.gamma + "
                             "1/2 lambda gamma.I gamma.")
      .def_readonly("g", &QuadraticField::g, "field intensity at O")
      .def_readonly("lambda_", &QuadraticField::lambda_, "lambda (3 g / R for a Newtonian centre)")
      .def_static("coulomb", &QuadraticField::coulomb, py::arg("g"), py::arg("lambda_"),
                  "Any finite (g, lambda)")
      .def_static("from_g_R", &QuadraticField::from_g_R, py::arg("g"), py::arg("R"),
                  "Newtonian centre: lambda = 3 g / R")
      .def_static("from_mu_R", &QuadraticField::from_mu_R, py::arg("mu"), py::arg("R"),
                  "Newtonian centre: g = mu / R^2, lambda = 3 mu / R^3")
      .def_static("uniform", &QuadraticField::uniform, py::arg("g"), "Uniform gravity: lambda = 0")
      .def_static("brun", &QuadraticField::brun, py::arg("N"), py::arg("plane_offset") = 0.0,
                  "Brun's field: lambda = -N, g = -N d")
      .def("__repr__", [](const QuadraticField& f) {
        return "QuadraticField(g=" + format_number(f.g) + ", lambda_=" + format_number(f.lambda_) +
               ")";
      });
}

/// A state the library accepts: check_unit_gamma's words, or gamma rescaled with normalize.
State checked_state(const Vec3& m_, const Vec3& gamma, bool normalize) {
  State s{m_, normalize ? normalized_gamma(gamma) : gamma};
  validate(s);
  return s;
}

void bind_state(py::module_& m) {
  py::class_<State>(m, "State",
                    "The Euler-Poisson state (docs/model.md §4): angular momentum m = I omega + k "
                    "and gamma, the unit vector from the centre towards O, in body axes.")
      .def(py::init([](const Vec3& m_, const Vec3& gamma, bool normalize) {
             return checked_state(m_, gamma, normalize);
           }),
           py::arg("m"), py::arg("gamma"), py::kw_only(), py::arg("normalize") = false,
           "m finite and gamma a unit vector (to 1e-12), as the library checks every state; "
           "normalize=True rescales gamma to unit length instead.")
      .def_static(
          "from_omega",
          [](const Body& body, const Vec3& w, const Vec3& gamma, bool normalize) {
            if (!w.allFinite()) {
              throw InputError("omega: expected finite numbers, found " + format_vector(w));
            }
            const State s = state_from_omega(body, w, gamma);
            return checked_state(s.m, gamma, normalize);
          },
          py::arg("body"), py::arg("omega"), py::arg("gamma"), py::kw_only(),
          py::arg("normalize") = false, "m = I omega + k; gamma checked as by State(m, gamma)")
      .def_readwrite("m", &State::m)
      .def_readwrite("gamma", &State::gamma)
      .def(
          "omega", [](const State& s, const Body& b) { return omega(b, s); }, py::arg("body"),
          "omega = I^-1 (m - k)")
      .def("__repr__", [](const State& s) {
        return "State(m=" + format_vector(s.m) + ", gamma=" + format_vector(s.gamma) + ")";
      });
}

void bind_model_class(py::module_& m) {
  py::class_<Model>(
      m, "Model",
      "A body in a field: quadratic (docs/model.md §3), or, loaded from a scenario, "
      "the exact field of a mass model or its multipole expansion (docs/model.md §2).")
      .def(py::init<const Body&, const QuadraticField&>(), py::arg("body"), py::arg("field"))
      .def_property_readonly("body", &Model::body)
      .def_property_readonly(
          "field",
          [](const Model& x) -> std::optional<QuadraticField> {
            if (x.kind() != FieldKind::quadratic) return std::nullopt;
            return x.quadratic().field;
          },
          "the QuadraticField of a quadratic model; None for an exact or multipole one")
      .def_property_readonly(
          "kind", [](const Model& x) { return std::string(to_string(x.kind())); },
          "'quadratic', 'exact' or 'multipole'")
      .def(
          "potential", [](const Model& x, const Vec3& g) { return potential(x, g); },
          py::arg("gamma"), "V(gamma)")
      .def(
          "grad_gamma", [](const Model& x, const Vec3& g) { return grad_gamma(x, g); },
          py::arg("gamma"), "dV/dgamma")
      .def(
          "hessian_gamma", [](const Model& x, const Vec3& g) { return hessian_gamma(x, g); },
          py::arg("gamma"), "d2V/dgamma2 (3x3)")
      .def(
          "moment", [](const Model& x, const Vec3& g) { return moment(x, g); }, py::arg("gamma"),
          "the field's moment about O: gamma x dV/dgamma")
      .def(
          "rhs",
          [](const Model& x, const py::object& state) {
            State s;
            if (py::isinstance<State>(state)) {
              s = state.cast<State>();
            } else {
              const auto v = state.cast<Eigen::Matrix<double, 6, 1>>();
              s = State{v.head<3>(), v.tail<3>()};
            }
            const State d = rhs(x, s);
            Eigen::Matrix<double, 6, 1> out;
            out << d.m, d.gamma;
            return out;
          },
          py::arg("x"),
          "(dm/dt, dgamma/dt) of the Euler-Poisson equations (docs/model.md §4) as an array of "
          "6, at x = a State or an array (m1, m2, m3, gamma1, gamma2, gamma3)")
      .def(
          "quadratic_approximation",
          [](const Model& x) { return Model(quadratic_approximation(x)); },
          "The quadratic model of the same body and centre (g = mu/R^2, lambda = 3 mu/R^3)");
  m.def(
      "integrals", [](const Model& x, const State& s) { return integrals_dict(integrals(x, s)); },
      py::arg("model"), py::arg("state"),
      "The first integrals of docs/model.md §5 at a state: energy, area m.gamma, geometric "
      "gamma.gamma, and brun / lagrange where they hold.");
  m.def(
      "conserved_integrals", [](const Model& x) { return conserved_integrals(x); },
      py::arg("model"), "Names of the integrals conserved by the model's motion.");
}

void bind_scenario(py::module_& m) {
  py::class_<io::Scenario>(m, "Scenario",
                           "A scenario: a model, an initial state and the [integrate] settings "
                           "(docs/scenario.md), read from a file or built and edited in code.")
      .def(py::init([](const Model& model, const State& initial, double t0,
                       std::optional<double> t_end, std::optional<std::string> method,
                       std::optional<double> step, std::optional<double> tol,
                       std::optional<std::int64_t> max_steps) {
             validate(initial);
             io::Scenario s{"<python>", model, initial, std::nullopt, {}, {}, {}};
             s.integrate.t0 = t0;
             s.integrate.t_end = t_end;
             s.integrate.method = std::move(method);
             s.integrate.step = step;
             s.integrate.tol = tol;
             s.integrate.max_steps = max_steps;
             return s;
           }),
           py::arg("model"), py::arg("initial"), py::kw_only(), py::arg("t0") = 0.0,
           py::arg("t_end") = py::none(), py::arg("method") = py::none(),
           py::arg("step") = py::none(), py::arg("tol") = py::none(),
           py::arg("max_steps") = py::none(),
           "A scenario built in code; the analyses take it as they take a model and a state.")
      .def_readonly("source", &io::Scenario::source, "the file it was read from ('<python>')")
      .def_readwrite("model", &io::Scenario::model)
      .def_property(
          "initial", [](const io::Scenario& s) { return s.initial; },
          [](io::Scenario& s, const State& x) {
            validate(x);
            s.initial = x;
          })
      .def_property_readonly(
          "attitude",
          [](const io::Scenario& s) -> std::optional<Eigen::Vector4d> {
            if (!s.attitude) return std::nullopt;
            return Eigen::Vector4d(s.attitude->w(), s.attitude->x(), s.attitude->y(),
                                   s.attitude->z());
          },
          "the initial attitude [w, x, y, z] (body -> inertial, scalar first), or None")
      .def_property(
          "t0", [](const io::Scenario& s) { return s.integrate.t0; },
          [](io::Scenario& s, const double& v) { s.integrate.t0 = v; })
      .def_property(
          "t_end", [](const io::Scenario& s) { return s.integrate.t_end; },
          [](io::Scenario& s, const std::optional<double>& v) { s.integrate.t_end = v; })
      .def_property(
          "method", [](const io::Scenario& s) { return s.integrate.method; },
          [](io::Scenario& s, const std::optional<std::string>& v) { s.integrate.method = v; })
      .def_property(
          "step", [](const io::Scenario& s) { return s.integrate.step; },
          [](io::Scenario& s, const std::optional<double>& v) { s.integrate.step = v; })
      .def_property(
          "tol", [](const io::Scenario& s) { return s.integrate.tol; },
          [](io::Scenario& s, const std::optional<double>& v) { s.integrate.tol = v; })
      .def_property(
          "max_steps", [](const io::Scenario& s) { return s.integrate.max_steps; },
          [](io::Scenario& s, const std::optional<std::int64_t>& v) { s.integrate.max_steps = v; })
      .def_property_readonly(
          "output",
          [](const io::Scenario& s) {
            py::dict d;
            d["file"] = s.output.file;
            d["every"] = s.output.every;
            d["dt"] = s.output.dt;
            return d;
          },
          "the [output] table: file, every, dt (what simulate writes without out=)")
      .def_readonly("input_files", &io::Scenario::input_files)
      .def("__repr__", [](const io::Scenario& s) { return "Scenario('" + s.source + "')"; });
  m.def("load_scenario", &io::load_scenario, py::arg("path"),
        "Reads and checks a scenario file; ValueError with the command line's message otherwise.");
  m.def("is_orbit_scenario", &io::is_orbit_scenario, py::arg("path"),
        "True for a scenario with an [orbit] table (docs/orbit.md), read by the orbit commands.");
  m.def("parse_scenario", &io::parse_scenario, py::arg("text"), py::arg("source") = "<string>",
        "Parses scenario text (relative file names are relative to the working directory).");
}

}  // namespace

void bind_model(py::module_& m) {
  bind_body(m);
  bind_field(m);
  bind_state(m);
  bind_model_class(m);
  bind_scenario(m);
}

}  // namespace newtop::python
