// The continued families (docs/continuation.md): resonance_family, rotation_family,
// equilibrium_family, rest_family, lyapunov_family, each a dict of numpy arrays with the located
// events.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "newtop/analysis/lyapunov_family.hpp"
#include "newtop/analysis/rest_family.hpp"
#include "newtop/analysis/rotation_family.hpp"
#include "newtop/orbit/orbit_families.hpp"
#include "newtop/orbit/resonance_continuation.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// {"parameter": (n,), "values": (n, m), "period": (n,), "multipliers": complex (n, k),
///  "stability": [str], "end": str, "events": [{"type", "value", "values", "multipliers"}]}.
py::dict family_dict(const Family& f) {
  const py::ssize_t n = static_cast<py::ssize_t>(f.points.size());
  const py::ssize_t m = n ? f.points[0].values.size() : 0;
  const py::ssize_t k = n ? static_cast<py::ssize_t>(f.points[0].multipliers.size()) : 0;
  py::array_t<double> parameter(n), period(n), values({n, m});
  py::array_t<std::complex<double>> multipliers({n, k});
  py::list stability;
  for (py::ssize_t i = 0; i < n; ++i) {
    const FamilyPoint& p = f.points[i];
    parameter.mutable_at(i) = p.parameter;
    period.mutable_at(i) = p.period;
    for (py::ssize_t j = 0; j < m; ++j) values.mutable_at(i, j) = p.values[j];
    for (py::ssize_t j = 0; j < k; ++j) multipliers.mutable_at(i, j) = p.multipliers[j];
    stability.append(p.stability);
  }
  py::list events;
  for (const BifurcationEvent& e : f.events) {
    py::dict d;
    d["type"] = to_string(e.type);
    d["value"] = e.value;
    d["values"] = Eigen::VectorXd(e.point.values);
    d["multipliers"] = e.point.multipliers;
    events.append(d);
  }
  py::dict out;
  out["parameter"] = parameter;
  out["values"] = values;
  out["period"] = period;
  out["multipliers"] = multipliers;
  out["stability"] = stability;
  out["end"] = f.end;
  out["events"] = events;
  return out;
}

}  // namespace

void bind_continuation(py::module_& m) {
  m.def(
      "resonance_family",
      [](double eccentricity, double k, const std::string& parameter, double end, int p, int q,
         double line, bool switch_branches) {
        const SpinOrbitResonance r = resonance(p, q);
        PitchPath path;
        double start = 0.0;
        if (parameter == "eccentricity") {
          path = eccentricity_path(k);
          start = eccentricity;
        } else if (parameter == "k") {
          path = [eccentricity](double kk) { return pitch_problem(eccentricity, kk); };
          start = k;
        } else {
          throw InputError("parameter: expected 'eccentricity' or 'k', found '" + parameter + "'");
        }
        ResonanceRequest request{path, start, end, r, line, std::nullopt, switch_branches};
        const ResonanceContinuation c = continue_resonance(request);
        py::dict out = family_dict(c.family);
        if (switch_branches) {
          py::list branches;
          for (const FamilyBranch& b : c.branches) {
            py::dict d = family_dict(b.family);
            d["event"] = b.event;
            d["type"] = to_string(c.family.events[b.event].type);
            branches.append(d);
          }
          out["branches"] = branches;
        }
        return out;
      },
      py::arg("eccentricity"), py::arg("k"), py::arg("parameter"), py::arg("end"), py::arg("p") = 1,
      py::arg("q") = 1, py::arg("line") = 0.0, py::arg("switch") = false,
      "The symmetric periodic solutions of the p:q resonance of Beletsky's equation on the line "
      "theta(0) = line, continued in 'eccentricity' or 'k' from the given value to `end` "
      "(docs/continuation.md §2); values columns theta0, dtheta0. switch=True adds 'branches': "
      "the family from each located flip (period-doubled) and branch point (asymmetric), each "
      "with 'event' (its index in 'events') and 'type'.");
  m.def(
      "rotation_family",
      [](const Body& body, double lambda, double omega0, double omega1, std::optional<int> axis) {
        const QuadraticModel model{body, QuadraticField{0.0, lambda}};
        return family_dict(
            rotation_family(model, axis ? *axis : largest_axis(body), omega0, omega1));
      },
      py::arg("body"), py::arg("lambda_"), py::arg("omega0"), py::arg("omega1"),
      py::arg("axis") = py::none(),
      "The spin about a principal axis (default the largest) pointing at the centre in Omega, "
      "with Krein collisions located (docs/continuation.md §3).");
  m.def(
      "rest_family",
      [](const Body& body, double g, double lambda, const std::string& key, double p0, double p1,
         const Eigen::Vector3d& gamma) {
        const QuadraticModel model{body, QuadraticField{g, lambda}};
        return family_dict(rest_family(quadratic_path(model, key), gamma, p0, p1));
      },
      py::arg("body"), py::arg("g"), py::arg("lambda_"), py::arg("key"), py::arg("p0"),
      py::arg("p1"), py::arg("gamma"),
      "The equilibrium at rest gamma of the fixed-point model in the quadratic field (g, lambda_) "
      "continued in `key` (body.inertia[i], body.center_of_mass[i], body.mass, field.g, "
      "field.lambda; its value in body/field replaced by p0) from p0 to p1 "
      "(docs/continuation.md §4b); values columns gamma_x, gamma_y, gamma_z, kappa.");
  m.def(
      "lyapunov_family",
      [](const Body& body, double g, double lambda, const Eigen::Vector3d& gamma, int mode,
         double p0, double p1) {
        const QuadraticModel model{body, QuadraticField{g, lambda}};
        return family_dict(lyapunov_family(model, gamma, mode, p0, p1));
      },
      py::arg("body"), py::arg("g"), py::arg("lambda_"), py::arg("gamma"), py::arg("mode"),
      py::arg("p0"), py::arg("p1"),
      "The periodic orbits born from normal mode `mode` (0 lower, 1 higher frequency) of the "
      "stable equilibrium at rest gamma, continued in the energy above it from p0 > 0 to p1 "
      "(docs/continuation.md §4c); values columns m (3), gamma (3) at t = 0, six multipliers.");
  m.def(
      "equilibrium_family",
      [](const Eigen::Vector3d& inertia, int radial, int normal, int index, double p0, double p1) {
        return family_dict(equilibrium_family(inertia, radial, normal, index, p0, p1));
      },
      py::arg("inertia"), py::arg("radial"), py::arg("normal"), py::arg("index"), py::arg("p0"),
      py::arg("p1"),
      "The relative equilibrium with the radius along principal axis `radial` and the orbit normal "
      "along `normal` (circular orbit, rate 1) as moment `index` moves from p0 to p1 "
      "(docs/continuation.md §4).");
}

}  // namespace newtop::python
