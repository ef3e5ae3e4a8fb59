// The permanent rotations and the exact field of a mass model on Python objects (docs/python.md,
// "The analyses"): newtop.rotations(model) and newtop.field(model, gamma, R=, scan_R=), the
// library's results with numpy arrays, the numbers of `newtop rotations` and `newtop field`.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "bindings.hpp"
#include "newtop/analysis/field_scan.hpp"
#include "newtop/analysis/find_integrals.hpp"
#include "newtop/analysis/rotations.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

py::array_t<double> rows(const std::vector<Vec3>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  double* p = a.mutable_data();
  for (const Vec3& x : v) {
    p[0] = x[0], p[1] = x[1], p[2] = x[2];
    p += 3;
  }
  return a;
}

py::array_t<double> array(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

void bind_rotations(py::module_& m) {
  py::class_<RotationFamilies>(m, "RotationFamilies",
                               "The families of permanent rotations (docs/model.md §8): the "
                               "result of newtop.rotations(model), as `newtop rotations --json`.")
      .def_property_readonly(
          "principal_axes", [](const RotationFamilies& f) { return rows(f.principal_axes); },
          "(K, 3): principal axes about which the body spins uniformly at every Omega")
      .def_readonly("any_axis_omega", &RotationFamilies::any_axis_omega,
                    "Omega = +-sqrt(lambda) about any axis (r0 = 0, lambda > 0), or None")
      .def_readonly("cone_is_whole_sphere", &RotationFamilies::cone_is_whole_sphere)
      .def_property_readonly(
          "cone_gamma",
          [](const RotationFamilies& f) {
            std::vector<Vec3> g;
            for (const auto& c : f.cone) g.push_back(c.gamma);
            return rows(g);
          },
          "(N, 3): sampled axes of the Staude cone")
      .def_property_readonly(
          "cone_omega_squared",
          [](const RotationFamilies& f) {
            std::vector<double> w;
            for (const auto& c : f.cone) w.push_back(c.omega_squared);
            return array(w);
          },
          "(N,): Omega^2 of each sampled axis")
      .def_property_readonly(
          "cone_admissible",
          [](const RotationFamilies& f) {
            py::array_t<bool> a(static_cast<py::ssize_t>(f.cone.size()));
            bool* p = a.mutable_data();
            for (const auto& c : f.cone) *p++ = c.admissible;
            return a;
          },
          "(N,): Omega^2 >= 0");
  m.def(
      "_rotations",
      [](const Model& model, int samples) { return permanent_rotations(model, samples); },
      py::arg("model"), py::arg("samples") = 180);
}

py::dict sample_dict(const FieldSample& s) {
  const FieldValues& v = s.values;
  py::dict d;
  d["potential"] = v.potential;
  d["grad_gamma"] = Vec3(v.grad_gamma);
  d["dV_dR"] = v.dV_dR;
  d["moment"] = Vec3(v.moment);
  d["force"] = Vec3(v.force);
  d["hessian_gamma"] = Mat3(s.hessian);
  return d;
}

py::dict comparison_dict(const FieldComparison& c) {
  py::dict d;
  d["gamma"] = Vec3(c.gamma);
  d["exact"] = sample_dict(c.exact);
  d["approx"] = sample_dict(c.approx);
  d["difference"] = sample_dict(c.difference);
  return d;
}

/// field_report with γ normalised as the command line's --gamma is (io::parse_gamma).
py::dict field(const Model& model, const Vec3& gamma, std::optional<double> R,
               std::optional<std::tuple<double, double, int>> scan_R) {
  if (!gamma.allFinite() || gamma.norm() == 0.0) {
    throw InputError("gamma: expected a finite non-zero vector, found " + format_vector(gamma));
  }
  std::optional<RadiusRange> range;
  if (scan_R) range = RadiusRange{std::get<0>(*scan_R), std::get<1>(*scan_R), std::get<2>(*scan_R)};
  const FieldReport r = field_report(model, gamma.normalized(), R, range);
  py::dict d = comparison_dict(r.principal);
  d["mu"] = r.mu;
  d["R"] = r.R;
  d["frame"] = "principal";
  d["approx_truncation_error"] = py::dict(py::arg("next_term") = r.truncation.next_term,
                                          py::arg("bound") = r.truncation.bound);
  d["input_frame"] = comparison_dict(r.input);
  if (r.scan) {
    const FieldScan& f = *r.scan;
    py::dict s;
    s["R"] = array(f.R);
    s["potential_error"] = array(f.potential_error);
    s["moment_error"] = array(f.moment_error);
    s["moment_relative_error"] = array(f.moment_relative_error);
    s["slope_potential"] = f.slope_potential;
    s["slope_moment"] = f.slope_moment;
    d["scan"] = s;
  }
  return d;
}

void bind_find_integrals(py::module_& m) {
  py::class_<IntegralSearch>(m, "IntegralSearch",
                             "The numerical search for polynomial first integrals (docs/model.md "
                             "§5): the result of newtop.find_integrals(model), as `newtop "
                             "find-integrals --json`.")
      .def_readonly("degree", &IntegralSearch::degree)
      .def_property_readonly(
          "monomials",
          [](const IntegralSearch& s) {
            std::vector<std::string> n;
            for (const auto& x : s.monomials) n.push_back(to_string(x));
            return n;
          },
          "names of the monomials in (omega, gamma), the coefficients' order")
      .def_property_readonly(
          "singular_values", [](const IntegralSearch& s) { return array(s.singular_values); },
          "descending, relative to the largest")
      .def_readonly("rank", &IntegralSearch::rank)
      .def_readonly("gap", &IntegralSearch::gap)
      .def_property_readonly(
          "names",
          [](const IntegralSearch& s) {
            std::vector<std::optional<std::string>> n;
            for (const auto& i : s.integrals) n.push_back(i.name);
            return n;
          },
          "each integral's name where recognised (energy, area*geometric, ...), else None")
      .def_property_readonly(
          "coefficients",
          [](const IntegralSearch& s) {
            py::array_t<double> a({static_cast<py::ssize_t>(s.integrals.size()),
                                   static_cast<py::ssize_t>(s.monomials.size())});
            double* p = a.mutable_data();
            for (const auto& i : s.integrals) {
              for (const double c : i.coefficients) *p++ = c;
            }
            return a;
          },
          "(K, monomials): a basis of the null space, one integral a row");
  m.def(
      "_find_integrals",
      [](const Model& model, int degree, int points) {
        if (model.kind() != FieldKind::quadratic) {
          throw InputError("find_integrals: expected a model of the quadratic field, found " +
                           std::string(to_string(model.kind())));
        }
        return find_integrals(model.quadratic(), SearchOptions{.degree = degree, .points = points});
      },
      py::arg("model"), py::arg("degree") = 2, py::arg("points") = 0);
}

}  // namespace

void bind_fields(py::module_& m) {
  bind_rotations(m);
  bind_find_integrals(m);
  m.def("_field", &field, py::arg("model"), py::arg("gamma"), py::arg("R") = std::nullopt,
        py::arg("scan_R") = std::nullopt,
        "The exact field of the model's mass model against its quadratic model at gamma (the "
        "mass model's frame), as `newtop field --json`: a dict of numpy arrays.");
}

}  // namespace newtop::python
