// simulate natively (docs/python.md, "The analyses"): the summary of a run from its rows (the
// library's integral-drift observer and Casimir check), and the trajectory CSV through the io
// writer the program uses, so that newtop.simulate(..., out=) writes the bytes of `newtop
// simulate --out`.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/model/attitude.hpp"
#include "newtop/model/integrals.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

State row_state(const Rows& m, const Rows& gamma, py::ssize_t i) {
  return State{Vec3(m.at(i, 0), m.at(i, 1), m.at(i, 2)),
               Vec3(gamma.at(i, 0), gamma.at(i, 1), gamma.at(i, 2))};
}

void check_rows(const Rows& t, const Rows& m, const Rows& gamma) {
  if (t.ndim() != 1 || m.ndim() != 2 || gamma.ndim() != 2 || m.shape(1) != 3 ||
      gamma.shape(1) != 3 || m.shape(0) != t.shape(0) || gamma.shape(0) != t.shape(0) ||
      t.shape(0) < 1) {
    throw InputError("rows: expected t (N), m and gamma (N, 3) with N >= 1");
  }
}

/// The drift of the integrals over the rows (the first is the start) and the Casimir check.
py::dict summary(const Model& model, const Rows& t, const Rows& m, const Rows& gamma) {
  check_rows(t, m, gamma);
  IntegralsDrift drift;
  drift.observe(integrals(model, row_state(m, gamma, 0)));
  // Every row, the start too (max |m| over the run's states, as simulate observes them).
  for (py::ssize_t i = 0; i < t.shape(0); ++i) {
    drift.observe(model, row_state(m, gamma, i));
  }
  const CasimirDrift c = casimir_drift(drift);
  py::dict casimir;
  casimir["geometric"] = c.geometric;
  casimir["area"] = c.area;
  casimir["threshold"] = CasimirDrift::kThreshold;
  casimir["exceeded"] = c.exceeded();
  py::dict d;
  d["initial"] = integrals_dict(drift.initial);
  d["final"] = integrals_dict(integrals(model, row_state(m, gamma, t.shape(0) - 1)));
  d["max_abs_drift"] = integrals_dict(drift.max_drift);
  d["casimir_drift"] = casimir;
  return d;
}

/// Every `every`-th row and the last, as `newtop simulate --out --every` writes them.
void write_csv(const std::string& path, const Model& model, const Rows& t, const Rows& m,
               const Rows& gamma, const std::optional<Rows>& quaternion, std::int64_t every,
               int euler, const std::vector<std::string>& inputs) {
  check_rows(t, m, gamma);
  if (every < 1)
    throw InputError("every: expected an integer >= 1, found " + std::to_string(every));
  if (euler && !quaternion) {
    throw InputError("euler: expected a run with an attitude (quaternion), found none");
  }
  if (quaternion && (quaternion->ndim() != 2 || quaternion->shape(0) != t.shape(0) ||
                     quaternion->shape(1) != 4)) {
    throw InputError("quaternion: expected (N, 4) rows");
  }
  io::AtomicFile file(path, inputs);
  io::CsvTrajectory csv(file.stream(), model, io::AttitudeColumns{quaternion.has_value(), euler});
  const py::ssize_t n = t.shape(0);
  for (py::ssize_t i = 0; i < n; ++i) {
    if (i % every != 0 && i != n - 1) continue;
    const State s = row_state(m, gamma, i);
    if (quaternion) {
      const auto& q = *quaternion;
      csv.write(t.at(i),
                with_attitude(s, Quaternion(q.at(i, 0), q.at(i, 1), q.at(i, 2), q.at(i, 3))));
    } else {
      csv.write(t.at(i), s);
    }
  }
  file.commit();
}

}  // namespace

void bind_simulate(py::module_& m) {
  m.def("_simulation_summary", &summary, py::arg("model"), py::arg("t"), py::arg("m"),
        py::arg("gamma"),
        "The integrals at the first and last rows, their largest drift over the rows and the "
        "relative drift of the Casimirs (as `newtop simulate --json`).");
  m.def("_write_trajectory_csv", &write_csv, py::arg("path"), py::arg("model"), py::arg("t"),
        py::arg("m"), py::arg("gamma"), py::arg("quaternion") = py::none(), py::arg("every") = 1,
        py::arg("euler") = 0, py::arg("inputs") = std::vector<std::string>{},
        "The trajectory CSV of `newtop simulate --out` from the rows of a run.");
}

}  // namespace newtop::python
