// The libration report on an orbit scenario (docs/python.md, "Satellites on an orbit"): the
// library's libration_report as a typed result whose numeric fields are numpy arrays — the numbers
// of `newtop libration --json` bit for bit; out= writes the section CSV through the io writer
// the program uses (the same bytes).

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <complex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "newtop/io/libration_json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/libration_report.hpp"
#include "orbit_model.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

template <class T, class Row, class F>
py::array_t<T> column(const std::vector<Row>& v, const F& f) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  T* p = a.mutable_data();
  for (const Row& r : v) *p++ = f(r);
  return a;
}

/// The periodic solutions of one resonance as arrays (K each).
py::dict solutions_dict(const std::vector<PeriodicSolution>& s, double e) {
  using P = PeriodicSolution;
  py::dict d;
  d["theta0"] = column<double>(s, [](const P& x) { return x.theta0; });
  d["dtheta0"] = column<double>(s, [](const P& x) { return x.dtheta0; });
  d["spin0"] = column<double>(s, [&](const P& x) { return spin_from_dtheta(e, x.dtheta0); });
  py::array_t<std::complex<double>> m({static_cast<py::ssize_t>(s.size()), py::ssize_t{2}});
  std::complex<double>* p = m.mutable_data();
  for (const P& x : s) *p++ = x.multipliers[0], *p++ = x.multipliers[1];
  d["multipliers"] = m;
  d["trace"] = column<double>(s, [](const P& x) { return x.monodromy.trace(); });
  std::vector<std::string> stability;
  for (const P& x : s) stability.emplace_back(to_string(x.stability));
  d["stability"] = stability;
  d["residual"] = column<double>(s, [](const P& x) { return x.residual; });
  d["max_deviation"] = column<double>(s, [](const P& x) { return x.max_deviation; });
  d["symmetry_distance"] = column<double>(s, [](const P& x) { return x.symmetry_distance; });
  d["symmetric"] =
      column<bool>(s, [](const P& x) { return x.symmetry_distance <= kSymmetryTolerance; });
  return d;
}

LibrationReport report(const io::OrbitScenario& sc, const std::string& resonances,
                       const std::optional<std::string>& spin, int iterates, bool asymmetric,
                       const std::optional<std::string>& out) {
  LibrationRequest request;
  request.resonances = io::parse_resonances(resonances);
  request.iterates = iterates;
  request.asymmetric = asymmetric;
  if (spin) {
    const io::SpinScan s = io::parse_spin(*spin);
    request.spin = SpinStarts{s.lo, s.hi, s.n};
  }
  const std::string context = sc.source + ": ";
  pitch_orbit(sc.orbit, context);  // bad input before the output file is opened
  std::unique_ptr<io::AtomicFile> file;
  if (out) {
    const std::string inputs[] = {sc.source};
    file = std::make_unique<io::AtomicFile>(*out, inputs);
  }
  LibrationReport r;
  {
    const py::gil_scoped_release unlocked;
    r = libration_report(sc.body, sc.orbit, sc.initial, request, context);
  }
  if (file) {
    io::write_csv(file->stream(), r);
    file->commit();
  }
  return r;
}

}  // namespace

void bind_orbit_libration(py::module_& m) {
  using R = LibrationReport;
  using S = SectionOrbit;
  py::class_<R>(m, "LibrationReport",
                "Planar pitch on a Kepler orbit (docs/orbit.md §9): the spin-orbit resonances "
                "with their Floquet multipliers and the periapsis section; the result of "
                "newtop.libration, as `newtop libration --json`.")
      .def_readonly("eccentricity", &R::eccentricity)
      .def_readonly("k", &R::k, "(B - A)/C about the pitch axis")
      .def_readonly("iterates", &R::iterates)
      .def_readonly("chaos_threshold", &R::chaos_threshold)
      .def_readonly("chaotic_starts", &R::chaotic_starts)
      .def_property_readonly(
          "resonances",
          [](const R& r) {
            py::list list;
            for (const LibrationResonance& x : r.resonances) {
              py::dict d;
              d["resonance"] = std::to_string(x.resonance.p) + ":" + std::to_string(x.resonance.q);
              d["spin_ratio"] = x.spin_ratio;
              d["periods"] = x.resonance.periods;
              d["half_turns"] = x.resonance.half_turns;
              d["strength"] = x.strength;
              d["averaged_half_width"] = x.averaged_half_width;
              d["solutions"] = solutions_dict(x.solutions, r.eccentricity);
              d["asymmetric_solutions"] =
                  x.asymmetric_solutions
                      ? py::object(solutions_dict(*x.asymmetric_solutions, r.eccentricity))
                      : py::object(py::none());
              list.append(d);
            }
            return list;
          },
          "one dict per resonance: resonance ('p:q'), spin_ratio, periods, half_turns, strength, "
          "averaged_half_width, solutions (a dict of arrays: theta0, dtheta0, spin0, multipliers "
          "(K, 2) complex, trace, stability (list), residual, max_deviation, symmetry_distance, "
          "symmetric), asymmetric_solutions (the same, or None)")
      .def_property_readonly(
          "theta0",
          [](const R& r) { return column<double>(r.starts, [](const S& s) { return s.theta0; }); })
      .def_property_readonly(
          "dtheta0",
          [](const R& r) { return column<double>(r.starts, [](const S& s) { return s.dtheta0; }); })
      .def_property_readonly("spin0",
                             [](const R& r) {
                               return column<double>(r.starts, [&](const S& s) {
                                 return spin_from_dtheta(r.eccentricity, s.dtheta0);
                               });
                             })
      .def_property_readonly("lyapunov",
                             [](const R& r) {
                               return column<double>(r.starts,
                                                     [](const S& s) { return s.lyapunov; });
                             })
      .def_property_readonly(
          "chaotic",
          [](const R& r) { return column<bool>(r.starts, [](const S& s) { return s.chaotic; }); })
      .def_property_readonly(
          "points",
          [](const R& r) {
            py::list list;
            for (const S& s : r.starts) {
              py::array_t<double> a({static_cast<py::ssize_t>(s.points.size()), py::ssize_t{2}});
              double* p = a.mutable_data();
              for (const Vec2& x : s.points) *p++ = x[0], *p++ = x[1];
              list.append(a);
            }
            return list;
          },
          "per start, the (iterates, 2) section points (theta mod pi, theta') at periapsis");
  m.def("_libration", &report, py::arg("scenario"), py::kw_only(),
        py::arg("resonances") = "1:2,1:1,3:2,2:1,5:2", py::arg("spin") = py::none(),
        py::arg("iterates") = 200, py::arg("asymmetric") = false, py::arg("out") = py::none());
}

}  // namespace newtop::python
