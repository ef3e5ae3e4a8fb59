// The orbit's analyses on Python objects (docs/python.md, "Satellites on an orbit"): the relative
// equilibria of a circular orbit, the stability of one, and the DeBra–Delp diagram, as typed
// results whose numeric fields are numpy arrays — the numbers of `newtop equilibria`, `newtop
// stability` and `newtop stability --diagram debra-delp` bit for bit.

#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <complex>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "newtop/orbit/debra_delp.hpp"
#include "newtop/orbit/lvlh.hpp"
#include "newtop/orbit/orbit_equilibria.hpp"
#include "newtop/orbit/orbit_reports.hpp"
#include "orbit_model.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// (N, k) array of rows filled by f (N × k with N = 0 when empty).
template <class Row, class T = double, class F>
py::array_t<T> rows(const std::vector<Row>& v, py::ssize_t k, const F& f) {
  py::array_t<T> a({static_cast<py::ssize_t>(v.size()), k});
  T* p = a.mutable_data();
  for (const Row& r : v) {
    f(r, p);
    p += k;
  }
  return a;
}

template <class Row>
py::array_t<double> column(const std::vector<Row>& v, const std::function<double(const Row&)>& f) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  double* p = a.mutable_data();
  for (const Row& r : v) *p++ = f(r);
  return a;
}

/// lyapunov_stable as the command line writes it: true, false, or None where only gyroscopic.
py::object lyapunov_stable(const RelativeSpectrum& sp) {
  if (sp.verdict == OrbitStability::lyapunov) return py::bool_(true);
  if (sp.verdict == OrbitStability::unstable) return py::bool_(false);
  return py::none();
}

py::array_t<std::complex<double>> eigenvalues(const RelativeSpectrum& sp) {
  return py::array_t<std::complex<double>>(static_cast<py::ssize_t>(sp.eigenvalues.size()),
                                           sp.eigenvalues.data());
}

Mat3 lvlh_of(const RelativeEquilibrium& e) {
  return lvlh_to_body(OrbitState{Vec3::Zero(), e.gamma, e.normal});
}

void bind_equilibria(py::module_& m) {
  using E = RelativeEquilibrium;
  using S = RelativeEquilibriumSet;
  py::class_<S>(m, "RelativeEquilibria",
                "The relative equilibria of a body on a circular orbit (docs/orbit.md §6), by "
                "increasing Jacobi integral: newtop.equilibria(orbit_model), as `newtop "
                "equilibria --json` on an orbit scenario.")
      .def_property_readonly("count", [](const S& s) { return s.equilibria.size(); })
      .def_property_readonly(
          "gamma",
          [](const S& s) {
            return rows<E>(s.equilibria, 3, [](const E& e, double* p) { Vec3::Map(p) = e.gamma; });
          })
      .def_property_readonly(
          "normal",
          [](const S& s) {
            return rows<E>(s.equilibria, 3, [](const E& e, double* p) { Vec3::Map(p) = e.normal; });
          })
      .def_property_readonly(
          "lvlh_quaternion",
          [](const S& s) {
            return rows<E>(s.equilibria, 4, [](const E& e, double* p) {
              const auto q = scalar_first(lvlh_quaternion(lvlh_of(e)));
              std::copy(q.begin(), q.end(), p);
            });
          },
          "(K, 4): q0..q3 of C(body<-LVLH), q0 >= 0")
      .def_property_readonly(
          "roll_pitch_yaw",
          [](const S& s) {
            return rows<E>(s.equilibria, 3, [](const E& e, double* p) {
              Vec3::Map(p) = roll_pitch_yaw(lvlh_of(e));
            });
          },
          "(K, 3): C(body<-LVLH) = R1(roll) R2(pitch) R3(yaw)")
      .def_property_readonly(
          "jacobi",
          [](const S& s) { return column<E>(s.equilibria, [](const E& e) { return e.jacobi; }); })
      .def_property_readonly(
          "residual",
          [](const S& s) { return column<E>(s.equilibria, [](const E& e) { return e.residual; }); })
      .def_property_readonly(
          "eigenvalues",
          [](const S& s) {
            return rows<E, std::complex<double>>(
                s.equilibria, 6, [](const E& e, std::complex<double>* p) {
                  std::copy(e.stability.eigenvalues.begin(), e.stability.eigenvalues.end(), p);
                });
          },
          "(K, 6) complex: the eigenvalues on the symplectic leaf")
      .def_property_readonly(
          "max_real_part",
          [](const S& s) {
            return column<E>(s.equilibria, [](const E& e) { return e.stability.max_real_part; });
          })
      .def_property_readonly("linearly_stable",
                             [](const S& s) {
                               std::vector<bool> v;
                               for (const E& e : s.equilibria)
                                 v.push_back(e.stability.linearly_stable);
                               return py::array(py::cast(v));
                             })
      .def_property_readonly("lyapunov_stable",
                             [](const S& s) {
                               py::list l;
                               for (const E& e : s.equilibria)
                                 l.append(lyapunov_stable(e.stability));
                               return l;
                             })
      .def_property_readonly(
          "verdict",
          [](const S& s) {
            std::vector<std::string> v;
            for (const E& e : s.equilibria) v.emplace_back(to_string(e.stability.verdict));
            return v;
          },
          "'lyapunov', 'gyroscopic' or 'unstable' for each")
      .def_readonly("lyapunov", &S::lyapunov)
      .def_readonly("gyroscopic", &S::gyroscopic)
      .def_readonly("unstable", &S::unstable)
      .def_readonly("unverified", &S::unverified)
      .def_readonly("resultant_tail", &S::resultant_tail)
      .def_readonly("polish_distance", &S::polish_distance)
      .def("__len__", [](const S& s) { return s.equilibria.size(); })
      .def("__repr__", [](const S& s) {
        return "RelativeEquilibria(count=" + std::to_string(s.equilibria.size()) +
               ", lyapunov=" + std::to_string(s.lyapunov) +
               ", gyroscopic=" + std::to_string(s.gyroscopic) +
               ", unstable=" + std::to_string(s.unstable) + ")";
      });
  m.def(
      "_orbit_equilibria",
      [](const OrbitModel& model) {
        const CircularOrbitModel& c = model.circular_model();
        const py::gil_scoped_release unlocked;
        return find_relative_equilibria(c);
      },
      py::arg("model"));
}

RelativeStabilityReport stability_of(const OrbitModel& model, std::optional<int> equilibrium,
                                     const std::optional<OrbitState>& state) {
  return relative_stability(model.circular_model(), {equilibrium, state});
}

void bind_stability(py::module_& m) {
  using R = RelativeStabilityReport;
  py::class_<R>(m, "RelativeStability",
                "The linear stability of a relative equilibrium (docs/orbit.md §7): "
                "newtop.stability(orbit_model, equilibrium=K | state=x), as `newtop stability "
                "--json` on an orbit scenario.")
      .def_property_readonly(
          "eigenvalues", [](const R& r) { return eigenvalues(r.spectrum); },
          "(6,) complex: the eigenvalues on the symplectic leaf")
      .def_property_readonly(
          "characteristic_polynomial",
          [](const R& r) { return Eigen::Matrix<double, 7, 1>(r.spectrum.characteristic); },
          "(7,): det(s E - Q^T J Q), constant term first")
      .def_property_readonly("max_real_part", [](const R& r) { return r.spectrum.max_real_part; })
      .def_property_readonly("linearly_stable",
                             [](const R& r) { return r.spectrum.linearly_stable; })
      .def_property_readonly("lyapunov_stable",
                             [](const R& r) { return lyapunov_stable(r.spectrum); })
      .def_property_readonly("verdict", [](const R& r) { return to_string(r.spectrum.verdict); })
      .def_readonly("state", &R::state)
      .def_readonly("omega", &R::omega)
      .def_property_readonly("gamma", [](const R& r) { return r.state.gamma; })
      .def_property_readonly("normal", [](const R& r) { return r.state.normal; })
      .def_readonly("jacobi", &R::jacobi)
      .def_readonly("residual", &R::residual)
      .def("__repr__", [](const R& r) {
        return std::string("RelativeStability(verdict='") + to_string(r.spectrum.verdict) + "')";
      });
  m.def("_orbit_stability", &stability_of, py::arg("model"), py::kw_only(),
        py::arg("equilibrium") = py::none(), py::arg("state") = py::none());
}

using DdPoint = DebraDelpPoint;  // the DeBra–Delp diagram's point and axis (start, end, count)
using DdAxis = std::tuple<double, double, int>;

void bind_debra_delp(py::module_& m) {
  using D = DebraDelpDiagram;
  py::class_<D>(m, "DebraDelpDiagram",
                "The DeBra-Delp diagram over (k_R, k_Y) (docs/orbit.md §8), k_R outer: "
                "newtop.debra_delp(), as `newtop stability --diagram debra-delp --json`.")
      .def_property_readonly("k_R",
                             [](const D& d) {
                               return column<DdPoint>(d.points,
                                                      [](const DdPoint& p) { return p.k_R; });
                             })
      .def_property_readonly("k_Y",
                             [](const D& d) {
                               return column<DdPoint>(d.points,
                                                      [](const DdPoint& p) { return p.k_Y; });
                             })
      .def_property_readonly(
          "region",
          [](const D& d) {
            std::vector<std::string> v;
            for (const DdPoint& p : d.points) v.emplace_back(to_string(p.computed));
            return v;
          },
          "the model's linearisation: 'lagrange', 'debra_delp' or 'unstable'")
      .def_property_readonly("closed_form",
                             [](const D& d) {
                               std::vector<std::string> v;
                               for (const DdPoint& p : d.points)
                                 v.emplace_back(to_string(p.closed_form));
                               return v;
                             })
      .def_property_readonly("boundary",
                             [](const D& d) {
                               std::vector<bool> v;
                               for (const DdPoint& p : d.points) v.push_back(p.boundary);
                               return py::array(py::cast(v));
                             })
      .def_property_readonly("max_real_part",
                             [](const D& d) {
                               return column<DdPoint>(
                                   d.points, [](const DdPoint& p) { return p.max_real_part; });
                             })
      .def_property_readonly("characteristic",
                             [](const D& d) {
                               return rows<DdPoint>(d.points, 7, [](const DdPoint& p, double* q) {
                                 Eigen::Matrix<double, 7, 1>::Map(q) = p.characteristic;
                               });
                             })
      .def_property_readonly("counts",
                             [](const D& d) {
                               py::dict c;
                               c["lagrange"] = d.counts[0];
                               c["debra_delp"] = d.counts[1];
                               c["unstable"] = d.counts[2];
                               return c;
                             })
      .def_readonly("disagreements_with_closed_form", &D::disagreements_with_closed_form)
      .def("__len__", [](const D& d) { return d.points.size(); });
  m.def(
      "debra_delp",
      [](const DdAxis& k_R, const DdAxis& k_Y) {
        const py::gil_scoped_release unlocked;
        return debra_delp_diagram({std::get<0>(k_R), std::get<1>(k_R), std::get<2>(k_R)},
                                  {std::get<0>(k_Y), std::get<1>(k_Y), std::get<2>(k_Y)});
      },
      py::arg("k_R") = DdAxis{-0.99, 0.99, 67}, py::arg("k_Y") = DdAxis{-0.99, 0.99, 67},
      "The DeBra-Delp diagram on a grid (LO, HI, N) of each ratio, ends included (the command "
      "line's --scan k_R=LO:HI:N,k_Y=LO:HI:M; default -0.99:0.99:67 each).");
}

}  // namespace

void bind_orbit_analyses(py::module_& m) {
  bind_equilibria(m);
  bind_stability(m);
  bind_debra_delp(m);
}

}  // namespace newtop::python
