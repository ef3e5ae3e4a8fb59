// view natively (docs/python.md): the self-contained 3D page of a trajectory CSV, built by the
// viewer's page builder (viewer/page.hpp) and written through io::AtomicFile — the bytes of
// `newtop view CSV -o OUT [--scenario S]`.

#include <pybind11/stl.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "page.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the trajectory CSV");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

using AnyScenario = std::variant<std::monostate, io::Scenario, io::OrbitScenario>;

/// The page of `csv` with the scenario's body (none, a body scenario or an orbit scenario).
std::size_t view(const std::string& csv, const std::string& out, const AnyScenario& scenario,
                 std::int64_t max_frames) {
  if (max_frames < 2) {
    throw InputError("max_frames: expected an integer >= 2, found " + std::to_string(max_frames));
  }
  // Every input is read and checked before the output file is opened.
  const viewer::Trajectory tr = viewer::parse_trajectory(read_text(csv), csv);
  const auto* sc = std::get_if<io::Scenario>(&scenario);
  const auto* orbit = std::get_if<io::OrbitScenario>(&scenario);
  if (orbit && !tr.orbit()) {
    throw InputError("scenario: expected the scenario of " + csv +
                     " (a fixed-point run), found an orbit scenario ([orbit])");
  }
  if (sc && tr.orbit()) {
    throw InputError("scenario: expected the orbit scenario ([orbit]) of " + csv +
                     " (an orbit run), found " + sc->source + ", a fixed-point scenario");
  }
  const viewer::PageOptions options{static_cast<std::size_t>(max_frames)};
  const std::string page =
      orbit ? viewer::make_page(tr, *orbit, options) : viewer::make_page(tr, sc, options);
  std::vector<std::string> inputs{csv};
  if (sc) inputs.insert(inputs.end(), sc->input_files.begin(), sc->input_files.end());
  if (orbit) inputs.push_back(orbit->source);
  io::AtomicFile file(out, inputs);
  file.stream() << page;
  file.commit();
  return std::min<std::size_t>(tr.rows(), options.max_frames);
}

}  // namespace

void bind_view(py::module_& m) {
  m.def(
      "_view",
      [](const std::string& csv, const std::string& out, const py::object& scenario,
         std::int64_t max_frames) {
        AnyScenario s;
        if (py::isinstance<io::Scenario>(scenario)) s = scenario.cast<io::Scenario>();
        if (py::isinstance<io::OrbitScenario>(scenario)) s = scenario.cast<io::OrbitScenario>();
        return view(csv, out, s, max_frames);
      },
      py::arg("csv"), py::arg("out"), py::arg("scenario") = py::none(),
      py::arg("max_frames") = 5000,
      "Writes the 3D page of a trajectory CSV (with the scenario's body: a Scenario or an "
      "OrbitScenario) to out; returns the number of frames.");
}

}  // namespace newtop::python
