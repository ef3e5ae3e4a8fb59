// Time spans end to end: backward runs of section and chaos work (the library tests compare them
// with the forward runs they mirror), every span a command cannot run is refused in one line
// (exit 2), `section --crossings N` without a t_end runs until the crossings under a reported
// cap, the summary says how many orbits were seeded and why fewer than asked, every report
// states its units, and --quiet silences warnings.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace test_spans_cli {
namespace {

namespace fs = std::filesystem;
using newtop::test::CliResult;

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string example(const char* name) { return newtop::test::example_path(name); }

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Brun's body without [integrate] t_end (and `extra` keys of [integrate]).
std::string no_t_end(const std::string& extra = "") {
  const std::string name = "no_t_end_" + std::to_string(std::hash<std::string>{}(extra)) + ".toml";
  return newtop::test::write_text(newtop::test::scratch_path("newtop_spans", name),
                                  "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\n"
                                  "[field]\nkind = \"brun\"\nN = 0.8\n"
                                  "[initial]\nomega = [0.5, 1.1, -0.4]\n"
                                  "gamma = [0.48, -0.6, 0.64]\n"
                                  "[integrate]\nstep = 0.02\n" +
                                      extra)
      .string();
}

const char* const kUnitsLine = "units: those of the scenario (newtop is unit-free)";

// The command: a backward section is a section, not an internal error.
TEST(SpansCli, BackwardSectionRuns) {
  const CliResult r =
      run("section " + example("brun.toml") + " --surface 'gamma3 = 0' --t-end -50 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_GE(j["count"].get<int>(), 3);
  double t_prev = 0.0;
  for (const auto& c : j["crossings"]) {
    const double t = c["t"].get<double>();
    EXPECT_LT(t, t_prev);  // in the order of the run, backwards
    EXPECT_GE(t, -50.0);
    t_prev = t;
  }
  EXPECT_EQ(j["outcome"], "finished");
}

// Every span no command can run is refused in one line, never an internal error; a backward
// span runs.
TEST(SpansCli, EveryTimeSpanRunsOrIsRefusedInOneLine) {
  const std::vector<std::string> commands{
      "section " + example("brun.toml") + " --surface 'gamma3 = 0' --crossings 3",
      "chaos " + example("brun.toml"), "simulate " + example("brun.toml")};
  for (const std::string& c : commands) {
    for (const char* t : {"0", "nan", "inf", "-inf", "1e308", "-1e308"}) {
      const CliResult r = run(c + " --t-end " + t);
      EXPECT_EQ(r.code, 2) << c << " --t-end " << t << "\n" << r.err;
      EXPECT_EQ(lines(r.err).size(), 1u) << c << " --t-end " << t << "\n" << r.err;
      EXPECT_EQ(r.err.find("internal error"), std::string::npos) << c << "\n" << r.err;
      EXPECT_NE(r.err.find("t_end"), std::string::npos) << c << " --t-end " << t << "\n" << r.err;
    }
    const CliResult back = run(c + " --t-end -10");
    EXPECT_EQ(back.code, 0) << c << " --t-end -10\n" << back.err;
  }
  // analytic samples forward from t0 only: a backward span is refused in one line.
  const CliResult a = run("analytic " + example("analytic_brun.toml") + " --t-end -5");
  EXPECT_EQ(a.code, 2);
  EXPECT_EQ(lines(a.err).size(), 1u) << a.err;
}

// The command: the indicators of the backward flow, never the zeros of a run that did not
// happen (tests/phase/test_chaos.cpp checks them against the forward flow they mirror).
TEST(SpansCli, BackwardChaosGivesIndicators) {
  const CliResult r = run("chaos " + example("section_chaotic.toml") + " --t-end -50 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["flow"], "backward");
  EXPECT_EQ(j["t_end"], -50.0);
  EXPECT_EQ(j["outcome"], "finished");
  for (const char* k : {"lyapunov_max", "megno", "fli"}) {
    ASSERT_TRUE(j[k].is_number()) << k;
    EXPECT_GT(j[k].get<double>(), 0.0) << k;  // |δ| grows along any orbit: none of them is 0
  }
  const CliResult h = run("chaos " + example("section_chaotic.toml") + " --t-end -50");
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_NE(h.out.find("(the backward flow from t0 = 0)"), std::string::npos) << h.out;
}

// sweep's megno: a backward span gives the backward flow's indicators (never zeros), a span of no
// length is refused in one line before any point runs.
TEST(SpansCli, SweepSpans) {
  auto sweep = [](const std::string& t_end) {
    const fs::path p = newtop::test::scratch_path("newtop_spans", "sweep" + t_end + ".toml");
    newtop::test::write_text(p, "scenario = \"" + example("section_chaotic.toml") +
                                    "\"\nquantities = [\"megno\", \"lyapunov_max\"]\n"
                                    "[[axes]]\nkey = \"initial.omega[0]\"\nstart = -1.5\n"
                                    "stop = 1.5\ncount = 2\n[integrate]\nt_end = " +
                                    t_end + "\nstep = 0.02\n");
    return run("sweep " + p.string() + " --threads 1 --json");
  };
  const CliResult back = sweep("-20.0");
  ASSERT_EQ(back.code, 0) << back.err;
  const auto j = nlohmann::json::parse(back.out);
  for (const char* q : {"megno", "lyapunov_max"}) {
    for (const auto& v : j["results"][q]) EXPECT_GT(v.get<double>(), 0.0) << q;
  }
  const CliResult none = sweep("0.0");
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(lines(none.err).size(), 1u) << none.err;
  EXPECT_NE(none.err.find("t_end: expected a time different from t0"), std::string::npos)
      << none.err;
}

// --crossings without a t_end runs until the crossings; the cap is reported.
TEST(SpansCli, CrossingsWithoutTEndRunUntilThem) {
  const CliResult r = run("section " + no_t_end() + " --surface 'gamma3 = 0' --crossings 7 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["count"], 7);
  EXPECT_EQ(j["stopped_by"], "crossings");
  EXPECT_EQ(j["cap"]["max_steps"], 1000000);
  EXPECT_EQ(j["cap"]["hit"], false);
  const CliResult h = run("section " + no_t_end() + " --surface 'gamma3 = 0' --crossings 7");
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_NE(h.out.find("7 crossings of 1 orbit(s), stopped by crossings"), std::string::npos)
      << h.out;
  EXPECT_NE(h.out.find("at most 1000000 steps (the cap"), std::string::npos) << h.out;
  // Without --crossings a t_end is still needed.
  const CliResult none = run("section " + no_t_end() + " --surface 'gamma3 = 0'");
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("t_end: missing"), std::string::npos) << none.err;
}

// A surface the orbit never meets: the cap ([integrate] max_steps here) stops the run, and the
// report says so (exit 3: the run ended before what it was asked).
TEST(SpansCli, CrossingsCapIsReportedWhenHit) {
  for (const char* method : {"", " --tol 1e-9"}) {
    const std::string sc = no_t_end("max_steps = 2000\n");
    const CliResult r =
        run("section " + sc + " --surface 'omega1 = 50' --crossings 3 --json" + method);
    ASSERT_EQ(r.code, 3) << method << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["count"], 0);
    EXPECT_EQ(j["stopped_by"], "cap");
    EXPECT_EQ(j["cap"]["max_steps"], 2000);
    EXPECT_EQ(j["cap"]["hit"], true);
    EXPECT_EQ(j["outcome"], "step_limit");
    const CliResult h = run("section " + sc + " --surface 'omega1 = 50' --crossings 3" + method);
    EXPECT_NE(h.out.find("the cap was hit on 1 orbit(s)"), std::string::npos) << h.out;
  }
}

// --orbits 12 on a low energy level: 4 of the 12 seed points are reachable (the kinetic energy is
// negative at the others), and the summary says so.
TEST(SpansCli, SummarySaysHowManyOrbitsWereSeeded) {
  const std::string args = "section " + example("section_brun.toml") +
                           " --surface 'gamma3 = 0' --orbits 12 --energy 0.1 --crossings 2";
  const CliResult h = run(args);
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_NE(h.out.find("orbits 4 seeded of 12 asked: at the other 8 seed points the level energy "
                       "= 0.1, area = "),
            std::string::npos)
      << h.out;
  EXPECT_NE(h.out.find("does not meet the surface (the kinetic energy would be negative there)"),
            std::string::npos)
      << h.out;
  const auto j = nlohmann::json::parse(run(args + " --json").out);
  EXPECT_EQ(j["levels"]["orbits"], 4);
  EXPECT_EQ(j["levels"]["orbits_asked"], 12);
  const CliResult all = run("section " + example("section_brun.toml") +
                            " --surface 'gamma3 = 0' --orbits 12 --crossings 2");
  EXPECT_NE(all.out.find("orbits 12 seeded of 12 asked\n"), std::string::npos) << all.out;
}

// Every report states its units once: the last line of a summary, "units" in a JSON object.
TEST(SpansCli, EveryReportStatesItsUnits) {
  const std::vector<std::string> commands{
      "simulate " + example("brun.toml") + " --t-end 1",
      "section " + example("brun.toml") + " --surface 'gamma3 = 0' --crossings 2",
      "chaos " + example("brun.toml") + " --t-end 1",
      "integrals " + example("brun.toml"),
      "equilibria " + example("equilibria_newtonian.toml"),
      "rotations " + example("rotation_staude_cone.toml"),
      "find-integrals " + example("brun.toml"),
      "analytic " + example("analytic_brun.toml"),
      "stability " + example("stability_beletsky.toml"),
      "sweep " + example("sweep_beletsky.toml") + " --threads 1"};
  for (const std::string& c : commands) {
    const CliResult h = run(c);
    ASSERT_EQ(h.code, 0) << c << "\n" << h.err;
    const std::vector<std::string> l = lines(h.out);
    const auto count = std::count(l.begin(), l.end(), std::string(kUnitsLine));
    EXPECT_EQ(count, 1) << c << "\n" << h.out;
    if (c.rfind("sweep", 0) != 0) {
      ASSERT_FALSE(l.empty());
      EXPECT_EQ(l.back(), kUnitsLine) << c;
    }
    const CliResult j = run(c + " --json");
    ASSERT_EQ(j.code, 0) << c << "\n" << j.err;
    EXPECT_EQ(nlohmann::json::parse(j.out)["units"], "those of the scenario (newtop is unit-free)")
        << c;
    EXPECT_EQ(j.out.find("units: "), std::string::npos) << c;  // no line after the JSON
  }
  // sweep's table comes last, after the units line: it stays a CSV to its end.
  const CliResult s = run("sweep " + example("sweep_beletsky.toml") + " --threads 1");
  const std::vector<std::string> l = lines(s.out);
  ASSERT_GE(l.size(), 4u);
  EXPECT_EQ(l[2], kUnitsLine);
  EXPECT_NE(l.back().find(",ok"), std::string::npos) << l.back();
}

// A warning is one line on stderr with exit 0; --quiet silences it, on every subcommand.
TEST(SpansCli, QuietSilencesWarnings) {
  const std::string args = "section " + example("section_brun.toml") +
                           " --surface 'gamma3 = 0' --orbits 4 --energy 0.01 --crossings 2";
  const CliResult loud = run(args);
  EXPECT_EQ(loud.code, 0) << loud.err;
  ASSERT_EQ(lines(loud.err).size(), 1u) << loud.err;
  EXPECT_EQ(loud.err.rfind("newtop: warning: the level energy = 0.01", 0), 0u) << loud.err;
  const CliResult quiet = run(args + " --quiet");
  EXPECT_EQ(quiet.code, 0);
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(quiet.out, loud.out);
  for (const char* sub :
       {"analytic", "chaos", "equilibria", "field", "find-integrals", "integrals", "libration",
        "rotations", "section", "simulate", "stability", "sweep", "view"}) {
    const CliResult help = run(std::string(sub) + " --help");
    EXPECT_NE(help.out.find("--quiet"), std::string::npos) << sub;
  }
}

// Times beyond double precision: an elliptic orbit far in time runs (Kepler's equation is solved on
// the mean anomaly reduced by whole turns); Brun's closed form refuses a time whose phase has no
// digit left, in one line naming `times`, before any work.
TEST(SpansCli, TimesBeyondDoublePrecision) {
  for (const char* name : {"orbit_elliptic_pitch.toml", "orbit_spin_orbit.toml"}) {
    const CliResult r = run("simulate " + example(name) + " --t-end 1e17 --step 1e16 --json");
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << name << r.err;
    EXPECT_NE(r.code, 2) << name << r.err;
  }
  const CliResult r = run("analytic " + example("analytic_brun.toml") + " --times 1,1e17 --json");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  ASSERT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("times: expected"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace test_spans_cli
