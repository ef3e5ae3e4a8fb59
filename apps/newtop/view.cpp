// newtop view RESULT.csv [--scenario S.toml] -o view.html: one self-contained HTML page (three.js
// included) that plays a trajectory in 3D beside the drift of its integrals (viewer/).

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "newtop/io/orbit_scenario.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "page.hpp"

namespace newtop::app {
namespace {

struct ViewArgs {
  std::string csv;
  std::optional<std::string> scenario;
  std::string out;
  std::int64_t max_frames = 5000;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the trajectory CSV");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int run(const ViewArgs& a) {
  if (a.max_frames < 2) {
    throw InputError("--max-frames: expected an integer >= 2, found " +
                     std::to_string(a.max_frames));
  }
  // Every input is read and checked before the output file is opened.
  const viewer::Trajectory tr = viewer::parse_trajectory(read_text(a.csv), a.csv);
  std::optional<io::Scenario> sc;
  std::optional<io::OrbitScenario> orbit;
  if (a.scenario && io::is_orbit_scenario(*a.scenario)) {
    if (!tr.orbit()) {
      throw InputError("--scenario: expected the scenario of " + a.csv +
                       " (a fixed-point run), found an orbit scenario ([orbit])");
    }
    orbit = io::load_orbit_scenario(*a.scenario);
  } else if (a.scenario) {
    if (tr.orbit()) {
      throw InputError("--scenario: expected the orbit scenario ([orbit]) of " + a.csv +
                       " (an orbit run), found " + *a.scenario + ", a fixed-point scenario");
    }
    sc = io::load_scenario(*a.scenario);
  }
  const viewer::PageOptions options{static_cast<std::size_t>(a.max_frames)};
  const std::string page = orbit ? viewer::make_page(tr, *orbit, options)
                                 : viewer::make_page(tr, sc ? &*sc : nullptr, options);
  std::vector<std::string> inputs{a.csv};
  if (sc) inputs.insert(inputs.end(), sc->input_files.begin(), sc->input_files.end());
  if (orbit) inputs.push_back(orbit->source);
  io::AtomicFile file(a.out, inputs);
  file.stream() << page;
  file.commit();
  std::cout << a.out << ": " << std::min<std::size_t>(tr.rows(), options.max_frames) << " of "
            << tr.rows() << " rows, "
            << (tr.orbit()          ? "orbit run (body frame, LVLH triad and orbit)"
                : tr.has_attitude() ? "attitude q0..q3 (inertial frame)"
                                    : "no attitude columns (body frame)")
            << (sc      ? ", body from " + sc->source
                : orbit ? ", body from " + orbit->source
                        : std::string(", no scenario"))
            << "\n";
  return kExitOk;
}

const RegisterCommand reg_view{Command{
    "view", "Write a self-contained HTML page that plays a trajectory CSV in 3D",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<ViewArgs>();
      sub.add_option("csv", a->csv,
                     "trajectory CSV written by newtop simulate --out (an orbit run too)")
          ->required();
      sub.add_option("--scenario", a->scenario,
                     "the run's scenario: draws the body (inertia ellipsoid or mass model) and "
                     "the angular momentum");
      sub.add_option("-o,--out", a->out, "the HTML page to write")->required();
      sub.add_option("--max-frames", a->max_frames,
                     "rows kept at most, evenly spaced (default 5000)");
      return [a] { return run(*a); };
    }}};

}  // namespace
}  // namespace newtop::app
