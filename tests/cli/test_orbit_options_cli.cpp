// Every option of every subcommand that takes a scenario, on each model (the fixed point, a
// circular orbit, an elliptic orbit): it works (exit 0) or is refused in one line naming it (exit
// 2) — never a crash, never another exit. The options are read from each subcommand's --help, so
// that a new option joins the enumeration by itself. That a working option is not dropped is
// checked option by option elsewhere (test_orbit_attitude_cli.cpp for simulate on orbits).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace test_orbit_options_cli {
namespace {

using newtop::test::CliResult;

struct Model {
  const char* name;
  const char* example;
  const char* t_end;   ///< a short run
  const char* step;    ///< a step of it
  const char* dt_out;  ///< an output interval inside it
  const char* times;   ///< an output time inside it
};

const Model kModels[] = {
    {"fixed point", "attitude_heavy_top.toml", "1", "0.01", "0.25", "0.5"},
    {"circular orbit", "orbit_leo_lagrange.toml", "600", "10", "100", "300"},
    {"elliptic orbit", "orbit_elliptic_pitch.toml", "1", "0.01", "0.25", "0.5"},
};

/// The subcommands that take a scenario, with the arguments each needs besides the scenario.
const std::map<std::string, std::string> kCommands{
    {"simulate", ""},
    {"integrals", ""},
    {"equilibria", ""},
    {"stability", ""},
    {"section", "--surface gamma1=0"},
    {"chaos", ""},
    {"libration", "--iterates 2 --resonances 1:1"},
    {"analytic", ""},
    {"field", ""},
    {"find-integrals", ""},
    {"rotations", ""},
};

/// The options that integrate take --t-end from the command line to stay short.
const std::set<std::string> kIntegrating{"simulate", "section", "chaos", "analytic"};

/// The options of a subcommand, from its --help.
std::vector<std::string> options_of(const std::string& command) {
  const CliResult r = newtop::test::run_newtop(command + " --help");
  EXPECT_EQ(r.code, 0) << r.out;
  std::vector<std::string> names;
  const std::regex option(R"((?:^|[\s,])(--[a-z][a-z0-9-]*))");
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] != '-') continue;  // option lines only
    std::smatch m;
    if (std::regex_search(line, m, option) && m[1] != "--help") names.push_back(m[1]);
  }
  return names;
}

/// A value for an option on a model ("" for a flag).
std::string value_of(const std::string& option, const Model& m, const std::string& file) {
  const std::map<std::string, std::string> values{
      {"--t-end", m.t_end},
      {"--step", m.step},
      {"--tol", "1e-8"},
      {"--method", "rkf78"},
      {"--split", "axes"},
      {"--out", file},
      {"--every", "2"},
      {"--dt-out", m.dt_out},
      {"--times", m.times},
      {"--euler", "321"},
      {"--samples", "5"},
      {"--gamma", "0,0,1"},
      {"--degree", "2"},
      {"--points", "10"},
      {"--resonances", "1:1"},
      {"--spin", "0.5:1.5:2"},
      {"--iterates", "2"},
      {"--direction", "up"},
      {"--crossings", "2"},
      {"--orbits", "2"},
      {"--energy", "1"},
      {"--area", "0"},
      {"--axis", "z"},
      {"--omega", "1"},
      {"--equilibrium", "1"},
      {"--scan-omega", "0:2:3"},
      {"--scan", "omega=0:2:3"},
      {"--diagram", "debra-delp"},
      {"--potential", "quadratic"},
      {"--surface", "gamma1=0"},
      {"--threads", "2"},
  };
  const auto it = values.find(option);
  return it == values.end() ? "" : it->second;  // a flag, or an option added since (then bare)
}

void expect_works_or_refused(const std::string& args) {
  const CliResult r = newtop::test::run_newtop(args, newtop::test::Stderr::separate);
  if (r.code == 0) return;
  ASSERT_EQ(r.code, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find("newtop: error: "), std::string::npos) << args << "\n" << r.err;
}

TEST(OptionsOnEveryModel, EachOptionWorksOrIsRefusedInOneLine) {
  int n = 0;
  for (const auto& [command, extra] : kCommands) {
    const std::vector<std::string> options = options_of(command);
    ASSERT_FALSE(options.empty()) << command;
    for (const std::string& option : options) {
      for (const Model& m : kModels) {
        const std::string file =
            newtop::test::scratch_path("newtop_options", "out" + std::to_string(n++) + ".csv")
                .string();
        std::string args = command + " " + newtop::test::example_path(m.example) + " " + extra;
        if (kIntegrating.count(command) && option != "--t-end" && option != "--times") {
          args += std::string(" --t-end ") + m.t_end;
        }
        if (option == "--times" && command == "simulate") args += " --out " + file;
        if ((option == "--dt-out" || option == "--euler" || option == "--attitude") &&
            command == "simulate") {
          args += " --out " + file;
        }
        if (extra.find(option) != std::string::npos) continue;  // already given
        args += " " + option + " " + value_of(option, m, file);
        SCOPED_TRACE(m.name);
        expect_works_or_refused(args);
      }
    }
  }
}

// The options that were refused on orbits and now work: chaos (every embedded pair and taylor,
// the spectrum) and dop853 and taylor on simulate.
TEST(OptionsOnEveryModel, ChaosAndDop853RunOnOrbits) {
  for (const Model& m : kModels) {
    if (std::string(m.name) == "fixed point") continue;
    SCOPED_TRACE(m.name);
    const std::string ex = newtop::test::example_path(m.example) + " --t-end " + m.t_end;
    for (const char* method : {"rkf78", "dopri5", "dop853", "taylor"}) {
      const CliResult r = newtop::test::run_newtop(
          "chaos " + ex + " --method " + method + " --tol 1e-9 --spectrum --json",
          newtop::test::Stderr::separate);
      ASSERT_EQ(r.code, 0) << method << "\n" << r.err;
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["method"], method);
      EXPECT_EQ(j["spectrum"].size(), 6u);
      EXPECT_TRUE(std::isfinite(j["megno"].get<double>()));
    }
    EXPECT_EQ(newtop::test::run_newtop("simulate " + ex + " --method dop853 --tol 1e-9").code, 0);
    const CliResult t = newtop::test::run_newtop(
        "simulate " + ex + " --method taylor --tol 1e-9 --json", newtop::test::Stderr::separate);
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_EQ(nlohmann::json::parse(t.out)["method"], "taylor");
    // A splitting has no tangent map on an orbit: refused in one line.
    expect_works_or_refused("chaos " + ex);
    EXPECT_EQ(newtop::test::run_newtop("chaos " + ex).code, 2);
  }
}

// Section CSV on an orbit: roll, pitch, yaw (LVLH) beside the orbital coordinates, equal to the
// JSON's roll_pitch_yaw of each crossing.
TEST(OptionsOnEveryModel, OrbitSectionCsvHasRollPitchYaw) {
  const std::string csv = newtop::test::scratch_path("newtop_options", "section_rpy.csv").string();
  const CliResult r =
      newtop::test::run_newtop("section " + newtop::test::example_path("satellite_700km.toml") +
                                   " --surface gamma1=0 --crossings 3 --out " + csv + " --json",
                               newtop::test::Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::istringstream in(newtop::test::read_text(csv));
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find(",roll,pitch,yaw"), std::string::npos) << header;
  std::size_t k = 0;
  for (std::string line; std::getline(in, line); ++k) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) v.push_back(std::stod(c));
    ASSERT_LT(k, j["crossings"].size());
    const auto& rpy = j["crossings"][k]["coords"]["roll_pitch_yaw"];
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(v[v.size() - 3 + i], rpy[i].get<double>()) << "row " << k << " angle " << i;
    }
  }
  EXPECT_EQ(k, 3u);
}

/// The quantities of `newtop sweep` (docs/sweep.md) on each model, and those that must work there.
const char* const kSweepQuantities[] = {"stability",   "drift",          "equilibria",
                                        "final_state", "megno",          "lyapunov_max",
                                        "debra_delp",  "synchronous_odd"};

bool sweep_must_work(const std::string& model, const std::string& q) {
  if (q == "drift" || q == "final_state") return true;
  if (model != "fixed point" && (q == "megno" || q == "lyapunov_max")) return true;  // rkf78
  if (model == "circular orbit") return q == "debra_delp";
  if (model == "elliptic orbit") return q == "synchronous_odd";
  return q != "debra_delp" && q != "synchronous_odd" && q != "stability";
}

std::string sweep_file(const Model& m, const std::string& quantity, int n) {
  const std::string text =
      "scenario = \"" + newtop::test::example_path(m.example) + "\"\nquantities = [\"" + quantity +
      "\"]\n[integrate]\nt_end = " + m.t_end + "\n" +
      // The chaos indicators of an orbit need an embedded pair (orbit.md §13).
      (std::string(m.name) != "fixed point" && (quantity == "megno" || quantity == "lyapunov_max")
           ? "method = \"rkf78\"\ntol = 1e-9\n"
           : "");
  return newtop::test::write_text(
             newtop::test::scratch_path("newtop_options", "sweep" + std::to_string(n) + ".toml"),
             text)
      .string();
}

// `sweep` takes a sweep file over a scenario: every quantity on every model works or is refused
// in one line naming it and the model, and so does every option of `sweep` on each model.
TEST(OptionsOnEveryModel, EverySweepQuantityAndOptionWorksOrIsRefusedInOneLine) {
  int n = 0;
  for (const Model& m : kModels) {
    SCOPED_TRACE(m.name);
    for (const char* q : kSweepQuantities) {
      const std::string args = "sweep " + sweep_file(m, q, n++) + " --quiet";
      const CliResult r = newtop::test::run_newtop(args, newtop::test::Stderr::separate);
      if (sweep_must_work(m.name, q)) {
        EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
      } else if (r.code != 0) {
        expect_works_or_refused(args);
        EXPECT_NE(r.err.find(q), std::string::npos) << r.err;
      }
      if (std::string(m.name) != "fixed point" && r.code != 0) {
        EXPECT_NE(r.err.find(std::string("the ") + m.name + " model"), std::string::npos) << r.err;
      }
    }
    for (const std::string& option : options_of("sweep")) {
      const std::string file =
          newtop::test::scratch_path("newtop_options", "sweep" + std::to_string(n) + ".csv")
              .string();
      std::filesystem::remove(file + ".checkpoint");
      expect_works_or_refused("sweep " + sweep_file(m, "final_state", n++) + " --quiet " + option +
                              " " + value_of(option, m, file));
    }
  }
}

}  // namespace
}  // namespace test_orbit_options_cli
