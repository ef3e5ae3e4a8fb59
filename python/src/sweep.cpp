// newtop.sweep without files (docs/python.md, "Sweeps"): a sweep's text over a base scenario's
// text, run by the library's sweep engine (threads, results by point), the columns as numpy
// arrays: the numbers of `newtop sweep --json`, bit for bit.

#include "newtop/sweep/sweep.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "newtop/io/scenario_text.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

py::dict run_file(const sweep::SweepFile& s, int threads) {
  sweep::RunOptions options;
  options.threads = threads;
  sweep::SweepRun r;
  {
    py::gil_scoped_release release;
    r = sweep::run_sweep(s, options);
  }
  const auto n = static_cast<py::ssize_t>(r.results.size());
  py::dict results;
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    py::array_t<double> a(n);
    double* p = a.mutable_data();
    for (std::size_t i = 0; i < r.results.size(); ++i) p[i] = sweep::point_values(s, i)[k];
    results[py::str(s.axes[k].key)] = a;
  }
  const std::vector<std::string> columns = sweep::quantity_columns(s);
  std::size_t failed = 0, off_level = 0;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    py::array_t<double> a(n);
    double* p = a.mutable_data();
    for (const auto& x : r.results) {
      *p++ = x.status == "ok" ? x.values[k] : std::numeric_limits<double>::quiet_NaN();
    }
    results[py::str(columns[k])] = a;
  }
  std::vector<std::string> status;
  for (const auto& x : r.results) {
    status.push_back(x.status);
    off_level += x.status == "off_level";
    failed += x.status != "ok" && x.status != "off_level";
  }
  results["status"] = status;
  py::dict d;
  d["points"] = r.results.size();
  d["failed"] = failed;
  d["off_level"] = off_level;
  d["threads"] = r.threads;
  d["quantities"] = s.quantities;
  d["results"] = results;
  return d;
}

void check_threads(int threads) {
  if (threads < 0) {
    throw InputError("threads: expected 0 (all cores) or more, found " + std::to_string(threads));
  }
}

py::dict run_sweep_text(const std::string& text, const std::string& base_source,
                        const std::string& base_text, int threads) {
  check_threads(threads);
  return run_file(sweep::make_sweep(text, base_source, base_text), threads);
}

/// A sweep file on disk, read as `newtop sweep FILE` reads it.
py::dict run_path(const std::string& path, int threads) {
  check_threads(threads);
  return run_file(sweep::load_sweep(path), threads);
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("_scenario_text", &io::scenario_text, py::arg("model"), py::arg("state"),
        "[body], [mass_model], [field] and [initial] of a model and state built in code, as "
        "scenario TOML (io::scenario_text): what a sweep of a Model runs on.");
  m.def("_sweep", &run_sweep_text, py::arg("text"), py::arg("base_source"), py::arg("base_text"),
        py::arg("threads") = 0,
        "A sweep's text (as a sweep file's) over the base scenario's text: points, failed, "
        "off_level, threads, quantities and results (one numpy array per axis and column, NaN "
        "where a point failed or a verdict is inconclusive; status a list).");
  m.def("_sweep_file", &run_path, py::arg("path"), py::arg("threads") = 0,
        "A sweep file (docs/sweep.md) as `newtop sweep FILE` reads it; the result of _sweep.");
}

}  // namespace newtop::python
