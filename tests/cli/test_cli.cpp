// The newtop program end to end: JSON and CSV contracts, exit codes, one-line errors, no partial
// output files.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace test_cli {
namespace {

namespace fs = std::filesystem;

using newtop::test::CliResult;

// Standard error is kept apart: the tests count its lines and parse standard output as JSON.
CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string example(const char* name) { return newtop::test::example_path(name); }

fs::path scratch(const std::string& name) { return newtop::test::scratch_path("newtop_cli", name); }

fs::path write_file(const std::string& name, const std::string& text) {
  return newtop::test::write_text(scratch(name), text);
}

TEST(Cli, SimulateJsonContract) {
  const CliResult r = run("simulate " + example("brun.toml") + " --t-end 5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["final"]["t"], 5.0);
  EXPECT_EQ(j["final"]["omega"].size(), 3u);
  EXPECT_EQ(j["final"]["gamma"].size(), 3u);
  for (const char* k : {"energy", "area", "geometric", "brun"}) {
    EXPECT_TRUE(j["integrals"]["initial"].contains(k)) << k;
    EXPECT_TRUE(j["integrals"]["final"].contains(k)) << k;
    EXPECT_TRUE(j["integrals"]["max_abs_drift"].contains(k)) << k;
  }
  EXPECT_FALSE(j["integrals"]["initial"].contains("lagrange"));
  EXPECT_EQ(j["steps"], 500);
  EXPECT_EQ(j["method"], "splitting6");
  EXPECT_EQ(j["outcome"], "finished");
  // The drift reported is the drift measured: a splitting method keeps it at round-off, a random
  // walk of ε per sub-flow (tests/integrate/test_round_off.cpp): splitting6 applies about 42
  // sub-flows a step (7 stages of 5 rotations, 7 kicks), so 500 steps give an RMS of
  // ε √(42 · 500 / 3) = 1.8e-14; three times that bounds the maximum.
  const double round_off = 3 * std::numeric_limits<double>::epsilon() * std::sqrt(42 * 500 / 3.0);
  EXPECT_LT(j["integrals"]["max_abs_drift"]["geometric"].get<double>(), round_off);
}

TEST(Cli, ToleranceSelectsAdaptiveAndMethodOverrides) {
  const CliResult r = run("simulate " + example("brun.toml") + " --t-end 1 --tol 1e-9 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["method"], "taylor");  // the quadratic field
  const CliResult r2 =
      run("simulate " + example("brun.toml") + " --t-end 1 --tol 1e-9 --method dopri5 --json");
  ASSERT_EQ(r2.code, 0) << r2.err;
  EXPECT_EQ(nlohmann::json::parse(r2.out)["method"], "dopri5");
}

// --split chooses the free body's split: each run is splitting6 on its own split (the JSON says
// which), all three agree with rkf78 at tol 1e-13 to splitting6's error at h = 0.01 over t = 5
// (order 6: ~1e-10 here; bound 1e-7), and the splits differ from one another (the option reached
// the stepper).
TEST(Cli, SplitChoosesTheFreeBodySplit) {
  const std::string base = "simulate " + example("brun.toml") + " --t-end 5 --step 0.01 --json";
  const CliResult ref = run("simulate " + example("brun.toml") + " --t-end 5 --tol 1e-13 --json");
  ASSERT_EQ(ref.code, 0) << ref.err;
  const auto reference = nlohmann::json::parse(ref.out)["final"]["gamma"];
  std::vector<nlohmann::json> finals;
  for (const char* split : {"axes", "spin", "exact"}) {
    const CliResult r = run(base + " --split " + split);
    ASSERT_EQ(r.code, 0) << split << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["split"], split);
    EXPECT_EQ(j["method"], "splitting6");
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(j["final"]["gamma"][i].get<double>(), reference[i].get<double>(), 1e-7) << split;
    }
    finals.push_back(j["final"]["gamma"]);
  }
  EXPECT_NE(finals[0], finals[1]);
  EXPECT_NE(finals[1], finals[2]);
  // Without --split the JSON names the default split.
  EXPECT_EQ(nlohmann::json::parse(run(base).out)["split"], "axes");
  // Bad: an unknown split, a split with an adaptive method, the exact flow with a gyrostat.
  for (const std::string& args :
       {base + " --split rotations",
        "simulate " + example("brun.toml") + " --t-end 1 --tol 1e-9 --split spin",
        "simulate " + example("coulomb.toml") + " --t-end 1 --step 0.01 --split exact"}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_NE(r.err.find("split"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST(Cli, IntegralsJson) {
  const CliResult r = run("integrals " + example("lagrange_like.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["conserved"], nlohmann::json::array({"energy", "area", "geometric", "lagrange"}));
  EXPECT_EQ(j["integrals"]["lagrange"], 1.2 * 4.0);  // C r + k3 with k = 0
}

TEST(Cli, CsvColumnsAndRows) {
  const fs::path csv = scratch("traj.csv");
  const CliResult r = run("simulate " + example("lagrange_like.toml") +
                          " --t-end 1 --step 0.01 --every 10 --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "t,p,q,r,gamma1,gamma2,gamma3,energy,area,geometric,lagrange");
  int rows = 0;
  std::string last;
  while (std::getline(in, line)) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, 11);  // t = 0, 0.1, …, 1.0
  EXPECT_EQ(last.substr(0, 2), "1,");
}

TEST(Cli, BadInputIsOneLineAndExitCodeTwo) {
  const std::string good =
      "[body]\ninertia = [1.0, 1.5, 2.2]\n[field]\ng = 1.0\nlambda = 0.5\n"
      "[initial]\nomega = [0.1, 0.2, 0.3]\ngamma = [0.0, 0.0, 1.0]\n"
      "[integrate]\nt_end = 1.0\nstep = 0.1\n";
  struct Case {
    std::string from, to, names;
  };
  const Case cases[] = {
      {"inertia = [1.0, 1.5, 2.2]", "inertia = [1.0, 1.5, 9.0]", "[body] inertia: triangle"},
      {"g = 1.0", "gg = 1.0", "unknown key 'gg' in [field]"},
      {"step = 0.1", "step = \"big\"", "[integrate] step: expected a number"},
      {"gamma = [0.0, 0.0, 1.0]", "gamma = [0.0, 1.0]", "[initial] gamma: expected an array of 3"},
      {"lambda = 0.5", "lambda = nan", "[field] lambda: expected a finite number"},
      {"[body]", "[body", "malformed TOML"},
  };
  for (const auto& [from, to, names] : cases) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    const fs::path f = write_file("bad.toml", text);
    const fs::path csv = scratch("never.csv");
    const CliResult r = run("simulate " + f.string() + " --out " + csv.string());
    EXPECT_EQ(r.code, 2) << to;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(csv)) << "partial output left for " << to;
  }
  const CliResult missing = run("simulate /nonexistent/none.toml");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos);
  const CliResult bad_flag = run("simulate " + example("brun.toml") + " --step -1");
  EXPECT_EQ(bad_flag.code, 2) << bad_flag.err;
}

TEST(Cli, UnwritableOutputLeavesNothing) {
  const CliResult r = run("simulate " + example("brun.toml") + " --out /nonexistent/dir/x.csv");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("x.csv"), std::string::npos);
}

TEST(Cli, NonFiniteOutcomeExitsThreeWithCompleteFile) {
  const std::string text =
      "[body]\ninertia = [1.0, 1.5, 2.2]\n[field]\ng = 1.0\nlambda = 0.5\n"
      "[initial]\nomega = [1000.0, -2000.0, 500.0]\ngamma = [0.0, 0.0, 1.0]\n"
      "[integrate]\nt_end = 1e6\nstep = 10.0\nmethod = \"rk4\"\n";
  const fs::path f = write_file("blowup.toml", text);
  const fs::path csv = scratch("blowup.csv");
  const CliResult r = run("simulate " + f.string() + " --json --out " + csv.string());
  EXPECT_EQ(r.code, 3);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "non_finite");
  EXPECT_TRUE(fs::exists(csv));
  std::ifstream in(csv);
  std::string all((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(all.find("nan"), std::string::npos);
  EXPECT_EQ(all.back(), '\n');
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The t column of a CSV trajectory.
std::vector<double> csv_times(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::vector<double> t;
  while (std::getline(in, line)) t.push_back(std::stod(line.substr(0, line.find(','))));
  return t;
}

// Issue 8, item 1: a first trial step of span/1000 (10 time units here) overflowed, and the
// non-finite trial ended the run at t = 10 after 0 steps.
TEST(Cli, LongAdaptiveRunsFinish) {
  for (const std::string& args : std::vector<std::string>{
           "simulate " + example("lagrange_like.toml") + " --t-end 10000",
           "simulate " + example("brun.toml") + " --t-end 30000 --tol 1e-10"}) {
    const CliResult r = run(args + " --json");
    ASSERT_EQ(r.code, 0) << args << "\n" << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["outcome"], "finished") << args;
    EXPECT_GT(j["steps"].get<long>(), 1000) << args;
    EXPECT_FALSE(j["casimir_drift"]["exceeded"].get<bool>()) << args;
  }
}

// Issue 8, item 3: runs that never happen were reported as finished at t = 0 after 0 steps.
TEST(Cli, RunsThatCannotHappenAreBadInput) {
  struct Case {
    std::string args, names;
  };
  const Case cases[] = {
      {"--step 1e-12 --t-end 1e7", "1e+19"},  // the count, beyond 2^53
      {"--t-end 1e300", "step"},              // 1e302 steps
      {"--t-end 1e12", "max_steps"},          // 1e14 steps: countable, beyond max_steps
      {"--t-end inf", "t_end"},
      {"--t-end nan", "t_end"},
      {"--t-end=-inf --tol 1e-9", "t_end"},
      {"--t-end 0", "t_end"},  // t0 = 0: no run at all
  };
  for (const auto& [args, names] : cases) {
    const CliResult r = run("simulate " + example("brun.toml") + " " + args + " --json");
    EXPECT_EQ(r.code, 2) << args << ": " << r.out;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

// Issue 8, item 4: an output that cannot be created was found only after the integration.
TEST(Cli, UncreatableOutputIsFoundBeforeIntegrating) {
  const fs::path dir = scratch("outdir");
  fs::create_directories(dir);
  const fs::path fifo = scratch("fifo");
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& out : std::vector<std::string>{dir.string(), std::string("''"),
                                                         dir.string() + "/", fifo.string()}) {
    const CliResult r = run("simulate " + example("brun.toml") + " --json --out " + out);
    EXPECT_EQ(r.code, 2) << out;
    EXPECT_TRUE(r.out.empty()) << out << ": the run went ahead";
    EXPECT_EQ(r.err.find("cannot move"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_TRUE(fs::is_fifo(fifo));  // not replaced by a regular file
}

// Issue 9: --out naming an input file (the scenario, its point-mass file) would overwrite it.
TEST(Cli, OutputNeverReplacesAnInput) {
  const fs::path dir = scratch("inputs");
  fs::create_directories(dir);
  const std::string points = "m,x,y,z\n1,1,0,0\n1,-1,0,0\n2,0,0.5,0\n2,0,-0.5,0\n3,0,0,0.2\n";
  std::ofstream(dir / "points.csv") << points;
  const std::string scenario =
      "[mass_model]\nkind = \"points\"\nfile = \"points.csv\"\n[field]\nkind = \"exact\"\n"
      "mu = 1.0\nR = 20.0\n[initial]\nomega = [0.1, 0.2, 0.3]\ngamma = [0.0, 0.0, 1.0]\n"
      "[integrate]\nt_end = 1.0\nstep = 0.1\n";
  std::ofstream(dir / "s.toml") << scenario;
  ASSERT_EQ(run("simulate " + (dir / "s.toml").string()).code, 0);
  for (const fs::path& out :
       std::vector<fs::path>{dir / "s.toml", dir / "." / "points.csv", dir / "points.csv"}) {
    const CliResult r = run("simulate " + (dir / "s.toml").string() + " --out " + out.string());
    EXPECT_EQ(r.code, 2) << out;
    EXPECT_NE(r.err.find("input file"), std::string::npos) << r.err;
  }
  EXPECT_EQ(read_all(dir / "s.toml"), scenario);
  EXPECT_EQ(read_all(dir / "points.csv"), points);
  // Every subcommand that writes a file: rotations, the stability diagrams, the viewer page.
  const std::string quad = read_all(example("stability_beletsky.toml"));
  std::ofstream(dir / "q.toml") << quad;
  const std::string q = (dir / "q.toml").string();
  const fs::path traj = dir / "traj.csv";
  ASSERT_EQ(run("simulate " + q + " --out " + traj.string()).code, 0);
  const std::string traj_text = read_all(traj);
  for (const std::string& args : std::vector<std::string>{
           "rotations " + q + " --out " + q, "stability " + q + " --scan-omega 0:3:7 --out " + q,
           "stability " + q + " --scan omega=1:2:2,lambda=0:1:2 --out " + q,
           "view " + traj.string() + " -o " + traj.string(),
           "view " + traj.string() + " --scenario " + q + " -o " + q}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_NE(r.err.find("input file"), std::string::npos) << args << ": " << r.err;
  }
  EXPECT_EQ(read_all(dir / "q.toml"), quad);
  EXPECT_EQ(read_all(traj), traj_text);
}

/// Runs a long simulation in the background, sends it `sig` once its partial file exists, and
/// returns the exit status the shell saw, with the run's stderr in `err`.
int interrupted_run(const fs::path& csv, const char* sig, std::string& err) {
  const fs::path err_file = scratch("signal.err");
  const std::string script =
      std::string(NEWTOP_EXE) + " simulate " + example("brun.toml") +
      " --t-end 1e5 --step 0.001 --out " + csv.string() + " 2>" + err_file.string() +
      " & pid=$!; n=0; while [ ! -e " + csv.string() +
      ".partial-$pid ] && [ $n -lt 3000 ]; do sleep 0.01; n=$((n+1)); done; kill -" + sig +
      " $pid; wait $pid; exit $?";
  const int status = std::system(("sh -c '" + script + "'").c_str());
  err = read_all(err_file);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Issue 8, item 5: a signal left an empty FILE.partial-PID behind.
TEST(Cli, SignalRemovesPartialOutputAndExits128PlusSignal) {
  const std::pair<const char*, int> signals[] = {{"INT", 130}, {"TERM", 143}};
  for (const auto& [sig, code] : signals) {
    const fs::path dir = scratch(std::string("signal_") + sig);
    fs::create_directories(dir);
    std::string err;
    EXPECT_EQ(interrupted_run(dir / "traj.csv", sig, err), code) << sig;
    EXPECT_TRUE(fs::is_empty(dir)) << sig << ": partial output left behind";
    EXPECT_NE(err.find(std::string("interrupted by SIG") + sig), std::string::npos) << err;
  }
}

// The commands that do not stop gracefully (a scan, rotations, view) left FILE.partial-PID behind
// when a signal killed them: the program's handler removes the temporaries of the open output
// files, then the signal terminates the process as usual.
TEST(Cli, ScanKilledBySignalLeavesNoPartialFile) {
  const std::pair<const char*, int> signals[] = {{"INT", 130}, {"TERM", 143}};
  for (const auto& [sig, code] : signals) {
    const fs::path dir = scratch(std::string("scan_signal_") + sig);
    fs::create_directories(dir);
    const fs::path csv = dir / "map.csv";
    const std::string script =
        std::string(NEWTOP_EXE) + " stability " + example("stability_beletsky.toml") +
        " --axis z --scan omega=0:3:1000,C=0.4:2.6:1000 --out " + csv.string() +
        " 2>/dev/null & pid=$!; n=0; while [ ! -e " + csv.string() +
        ".partial-$pid ] && [ $n -lt 3000 ]; do sleep 0.01; n=$((n+1)); done; kill -" + sig +
        " $pid; wait $pid; exit $?";
    const int status = std::system(("sh -c '" + script + "'").c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), code) << sig;
    EXPECT_TRUE(fs::is_empty(dir)) << sig << ": partial output left behind";
  }
}

// Issue 9: a loose tolerance ended `finished` with |γ| ≈ 135 and no warning.
TEST(Cli, CasimirDriftWarns) {
  const CliResult bad =
      run("simulate " + example("brun.toml") + " --method dopri5 --tol 1e-2 --json");
  ASSERT_EQ(bad.code, 0) << bad.err;  // the run still ends with its outcome
  const auto j = nlohmann::json::parse(bad.out);
  EXPECT_TRUE(j["casimir_drift"]["exceeded"].get<bool>()) << j["casimir_drift"];
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_NE(bad.err.find("newtop: warning: the Casimirs drifted"), std::string::npos) << bad.err;
  const CliResult good = run("simulate " + example("brun.toml") + " --json");
  ASSERT_EQ(good.code, 0);
  const auto g = nlohmann::json::parse(good.out);
  EXPECT_FALSE(g["casimir_drift"]["exceeded"].get<bool>());
  EXPECT_LT(g["casimir_drift"]["geometric"].get<double>(), 1e-12);  // splitting: round-off
  EXPECT_TRUE(g["warnings"].empty());
  EXPECT_TRUE(good.err.empty()) << good.err;
}

// Issue 10, part 3: rows at t0 + kD, by dense output (adaptive) or landing (fixed step).
TEST(Cli, RowsAtRequestedTimes) {
  const fs::path csv = scratch("dt.csv");
  for (const char* method : {"--tol 1e-10", "--tol 1e-10 --method dopri5", "--step 0.03"}) {
    const CliResult r = run("simulate " + example("lagrange_like.toml") + " --t-end 2 " + method +
                            " --dt-out 0.1 --out " + csv.string());
    ASSERT_EQ(r.code, 0) << method << r.err;
    const std::vector<double> t = csv_times(csv);
    ASSERT_EQ(t.size(), 21u) << method;
    for (std::size_t k = 0; k < t.size(); ++k) EXPECT_EQ(t[k], 0.1 * static_cast<double>(k));
  }
  // --times: sorted, t_end defaults to the last one; [output] dt in the file.
  ASSERT_EQ(
      run("simulate " + example("brun.toml") + " --times 0.5,0.25,1 --out " + csv.string()).code,
      0);
  EXPECT_EQ(csv_times(csv), (std::vector<double>{0.25, 0.5, 1.0}));
  std::string text = read_all(example("brun.toml"));
  text += "\n[output]\ndt = 0.5\n";
  const fs::path f = write_file("dt.toml", text);
  ASSERT_EQ(run("simulate " + f.string() + " --t-end 2 --out " + csv.string()).code, 0);
  EXPECT_EQ(csv_times(csv), (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
  // Conflicts and impossible requests are bad input.
  for (const std::string& bad : std::vector<std::string>{
           " --dt-out 0.1 --every 2 --out " + csv.string(), " --dt-out 0.1",
           " --dt-out 0 --out " + csv.string(), " --times 0.5,200 --out " + csv.string(),
           " --times 0.5,0.5 --out " + csv.string(), " --times 1,x --out " + csv.string()}) {
    const CliResult r = run("simulate " + example("brun.toml") + bad);
    EXPECT_EQ(r.code, 2) << bad;
  }
  // More rows than max_steps (1e11 here) would never be written: refused before the run.
  const CliResult many =
      run("simulate " + example("brun.toml") + " --dt-out 1e-9 --out " + csv.string());
  EXPECT_EQ(many.code, 2);
  EXPECT_EQ(many.err.rfind("newtop: error: --dt-out: 100000000", 0), 0u) << many.err;
  EXPECT_NE(many.err.find(" output times, more than max_steps = 1000000000"), std::string::npos)
      << many.err;
}

// Issue 8, item 11: the exact field's line came above the header.
TEST(Cli, ExactFieldSummaryLineUnderTheHeader) {
  const CliResult r = run("simulate " + example("exact_box_multipole.toml") + " --t-end 0.5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("newtop simulate ", 0), 0u) << r.out;
  const auto field = r.out.find("field     multipole (mu = 50");
  EXPECT_NE(field, std::string::npos) << r.out;
  EXPECT_LT(field, r.out.find("method    ")) << r.out;
}

// Issue 9: find-integrals --points 2147483647 ended in std::bad_alloc (exit 1).
TEST(Cli, FindIntegralsPointsBounded) {
  const CliResult r =
      run("find-integrals " + example("analytic_lagrange.toml") + " --points 2147483647");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("points: expected at most 621378"), std::string::npos) << r.err;
}

// Issue 8, item 2: a failed numerical reference was compared with as if it were the motion.
TEST(Cli, AnalyticReportsAFailedReference) {
  std::string text = read_all(example("analytic_lagrange.toml"));
  text.replace(text.find("step = 1e-2"), 11, "max_steps = 200");
  const fs::path f = write_file("analytic_limited.toml", text);
  const CliResult r = run("analytic " + f.string() + " --times 1,50000,100000 --json");
  EXPECT_EQ(r.code, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["reference"]["outcome"], "step_limit");
  EXPECT_EQ(j["reference"]["compared_samples"], 1);
  EXPECT_FALSE(j["samples"][0]["numeric"].is_null());
  EXPECT_TRUE(j["samples"][1]["numeric"].is_null());
  EXPECT_TRUE(j["samples"][2]["numeric"].is_null());
  EXPECT_LT(j["max_abs_error"].get<double>(), 1e-10);  // only the sample it reached
  const CliResult human = run("analytic " + f.string() + " --times 1,50000");
  EXPECT_EQ(human.code, 3);
  EXPECT_NE(human.out.find("reference FAILED: step_limit"), std::string::npos) << human.out;
}

// Issue 8, item 9: without t_end, analytic failed with "t_end: missing".
TEST(Cli, AnalyticWithoutSpanSamplesOnePeriod) {
  // The pendulum's quadrature at a full period costs seconds (src/analysis/pendulum.cpp): one
  // interval there, the default 20 for the Lagrange case.
  struct Case {
    const char *name, *period_key, *samples;
    std::size_t n;
  };
  for (const Case& c : {Case{"analytic_pendulum.toml", "period", " --samples 1", 2},
                        Case{"analytic_lagrange.toml", "nutation_period", "", 21}}) {
    std::string text = read_all(example(c.name));
    text = text.substr(0, text.find("[integrate]"));
    const fs::path f = write_file(std::string("no_span_") + c.name, text);
    const CliResult r = run("analytic " + f.string() + c.samples + " --json");
    ASSERT_EQ(r.code, 0) << c.name << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double T = j[c.period_key].get<double>();
    EXPECT_GT(T, 0.0) << c.name;
    EXPECT_EQ(j["span_source"], "one period");
    ASSERT_EQ(j["samples"].size(), c.n);
    EXPECT_EQ(j["samples"][c.n - 1]["t"].get<double>(), T);
    EXPECT_LT(j["max_abs_error"].get<double>(), 1e-10) << c.name;
    EXPECT_FALSE(j["turning_points"].empty()) << c.name;
  }
}

}  // namespace
}  // namespace test_cli
