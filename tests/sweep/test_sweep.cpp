// Sweeps: the grid, Beletsky's atlas against the closed form of docs/model.md §9, results
// independent of the thread count, a SIGKILLed sweep resumed to the same bytes, and bad sweep
// files.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "newtop/sweep/sweep.hpp"
#include "support/cli.hpp"

namespace test_sweep {
namespace {

namespace fs = std::filesystem;
using newtop::sweep::SweepFile;

fs::path scratch(const std::string& name) {
  return newtop::test::scratch_path("newtop_sweep", name);
}

fs::path write_file(const std::string& name, const std::string& text) {
  return newtop::test::write_text(scratch(name), text);
}

std::string read(const fs::path& p) { return newtop::test::read_text(p); }

std::string example(const char* name) { return newtop::test::example_path(name); }

/// A sweep of runs of the heavy top (drift and final state) over the spin and the step.
std::string heavy_top_sweep(double t_end, int spins) {
  return "scenario = \"" + example("heavy_top.toml") +
         "\"\nquantities = [\"drift\", \"final_state\"]\n[[axes]]\nkey = \"initial.omega[2]\"\n"
         "start = 1.0\nstop = 10.0\ncount = " +
         std::to_string(spins) +
         "\n[[axes]]\nkey = \"integrate.step\"\nvalues = [1e-3, 2e-3]\n[integrate]\nt_end = " +
         newtop::format_number(t_end) + "\n";
}

TEST(Sweep, GridOrderHasTheLastAxisFastestAndZipPairs) {
  const SweepFile s = newtop::sweep::load_sweep(write_file("grid.toml", heavy_top_sweep(1, 3)));
  ASSERT_EQ(newtop::sweep::point_count(s), 6u);
  EXPECT_EQ(newtop::sweep::point_values(s, 0), (std::vector<double>{1.0, 1e-3}));
  EXPECT_EQ(newtop::sweep::point_values(s, 1), (std::vector<double>{1.0, 2e-3}));
  EXPECT_EQ(newtop::sweep::point_values(s, 2), (std::vector<double>{5.5, 1e-3}));
  EXPECT_EQ(newtop::sweep::point_values(s, 5), (std::vector<double>{10.0, 2e-3}));
  std::string zip = heavy_top_sweep(1, 2);
  zip.insert(zip.find("[[axes]]"), "combine = \"zip\"\n");
  const SweepFile z = newtop::sweep::load_sweep(write_file("zip.toml", zip));
  ASSERT_EQ(newtop::sweep::point_count(z), 2u);
  EXPECT_EQ(newtop::sweep::point_values(z, 1), (std::vector<double>{10.0, 2e-3}));
  // The point's scenario carries the swept values exactly.
  const newtop::io::Scenario sc = newtop::sweep::point_scenario(s, 2);
  EXPECT_EQ(newtop::omega(sc.model.body(), sc.initial).z(), 5.5);
  EXPECT_EQ(*sc.integrate.step, 1e-3);
}

// Spec §9: the spin about the largest axis is linearly stable above
// Ω* = √λ (√a + √b)/(1 + √(ab)), a = (C − B)/A, b = (C − A)/B; every grid point farther than one
// cell from Ω* must have that verdict.
TEST(Sweep, BeletskyAtlasHasTheVerdictOfTheClosedForm) {
  const SweepFile s = newtop::sweep::load_sweep(write_file(
      "atlas.toml", "scenario = \"" + example("stability_beletsky.toml") +
                        "\"\nquantities = [\"stability\"]\n[[axes]]\nkey = \"stability.omega\"\n"
                        "start = 0.0\nstop = 3.0\ncount = 61\n[[axes]]\nkey = \"body.inertia[2]\"\n"
                        "start = 1.6\nstop = 2.4\ncount = 9\n[stability]\naxis = \"z\"\n"));
  const double cell = 3.0 / 60.0, A = 1.0, B = 1.5, lambda = 1.0;  // stability_beletsky.toml
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  int checked = 0;
  for (std::size_t i = 0; i < run.results.size(); ++i) {
    const std::vector<double> v = newtop::sweep::point_values(s, i);
    const double Omega = v[0], C = v[1];
    const double a = (C - B) / A, b = (C - A) / B;
    const double threshold =
        std::sqrt(lambda) * (std::sqrt(a) + std::sqrt(b)) / (1 + std::sqrt(a * b));
    ASSERT_EQ(run.results[i].status, "ok");
    if (std::abs(Omega - threshold) <= cell) continue;
    EXPECT_EQ(run.results[i].values[0], Omega > threshold ? 1.0 : 0.0)
        << "Omega = " << Omega << ", C = " << C << ", threshold " << threshold;
    ++checked;
  }
  EXPECT_GT(checked, 61 * 9 * 9 / 10);
}

TEST(Sweep, ResultsAreTheSameBitsForAnyThreadCount) {
  const SweepFile s = newtop::sweep::load_sweep(write_file("threads.toml", heavy_top_sweep(2, 5)));
  newtop::sweep::RunOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = newtop::sweep::run_sweep(s, one), b = newtop::sweep::run_sweep(s, two);
  ASSERT_EQ(a.results.size(), 10u);
  for (std::size_t i = 0; i < a.results.size(); ++i) {
    EXPECT_EQ(a.results[i].status, "ok");
    EXPECT_EQ(a.results[i].values, b.results[i].values) << "point " << i;  // exact equality
  }
  const auto c =
      newtop::test::run_newtop("sweep " + scratch("threads.toml").string() +
                               " --quiet --threads 1 --out " + scratch("t1.csv").string());
  const auto d =
      newtop::test::run_newtop("sweep " + scratch("threads.toml").string() +
                               " --quiet --threads 2 --out " + scratch("t2.csv").string());
  ASSERT_EQ(c.code, 0) << c.out;
  ASSERT_EQ(d.code, 0) << d.out;
  EXPECT_EQ(read(scratch("t1.csv")), read(scratch("t2.csv")));
}

// The kill comes at a random moment of the run: a fraction in [0.25, 0.85] of the uninterrupted
// run's own wall time (measured here, so that a fast machine does not finish first), and at least
// 0.15 s in (the checkpoint exists once the sweep file is read). Drawn again, up to three times,
// if the sweep finished anyway.
TEST(Sweep, KilledAndResumedEqualsUninterrupted) {
  const fs::path file = write_file("kill.toml", heavy_top_sweep(300, 6));
  const auto start = std::chrono::steady_clock::now();
  const auto whole = newtop::test::run_newtop(
      "sweep " + file.string() + " --quiet --threads 1 --out " + scratch("whole.csv").string());
  const double duration =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(whole.code, 0) << whole.out;
  std::random_device seed;
  std::uniform_real_distribution<double> when(0.25, 0.85);
  const fs::path out = scratch("killed.csv");
  bool killed = false;
  for (int attempt = 0; attempt < 3 && !killed; ++attempt) {
    fs::remove(out.string() + ".checkpoint");
    const double at = std::max(0.15, when(seed) * duration);
    const std::string kill = "timeout -s KILL " + std::to_string(at) + " " + NEWTOP_EXE +
                             " sweep " + file.string() + " --quiet --threads 1 --out " +
                             out.string();
    const int status = std::system(kill.c_str());
    killed = WEXITSTATUS(status) != 0;
    if (!killed) fs::remove(out);
  }
  if (!killed) GTEST_SKIP() << "the sweep finished before each of three kills";
  EXPECT_FALSE(fs::exists(out));  // nothing half-written
  ASSERT_TRUE(fs::exists(out.string() + ".checkpoint"));
  const auto again =
      newtop::test::run_newtop("sweep " + file.string() + " --quiet --out " + out.string());
  EXPECT_EQ(again.code, 2) << again.out;  // the checkpoint is not silently overwritten
  EXPECT_NE(again.out.find("--resume"), std::string::npos) << again.out;
  const auto resumed = newtop::test::run_newtop(
      "sweep " + file.string() + " --quiet --resume --json --out " + out.string(),
      newtop::test::Stderr::separate);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_EQ(read(out), read(scratch("whole.csv")));
  EXPECT_FALSE(fs::exists(out.string() + ".checkpoint"));
}

// MEGNO over a small grid of Brun's integrable case (docs/model.md §5): every orbit lies on a
// torus, so ⟨Y⟩ → 2 (Cincotta–Simó) with an oscillating remainder that decays like 1/t: at t = 400
// one of these orbits still had 2.22, at t = 2000 they have 2.010, 2.015 and 2.074 (measured); 0.1
// leaves room for the remainder's amplitude. The point of the base scenario gives the bits of
// `newtop chaos`.
TEST(Sweep, MegnoOfAnIntegrableCaseIsTwoAndThatOfNewtopChaos) {
  const SweepFile s = newtop::sweep::load_sweep(write_file(
      "megno.toml",
      "scenario = \"" + example("section_brun.toml") +
          "\"\nquantities = [\"megno\", \"lyapunov_max\"]\n[[axes]]\n"
          "key = \"initial.omega[0]\"\nvalues = [0.5, 0.3, 0.7]\n[integrate]\nt_end = 2000.0\n"));
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  ASSERT_EQ(run.results.size(), 3u);
  for (const auto& r : run.results) {
    ASSERT_EQ(r.status, "ok");
    EXPECT_NEAR(r.values[0], 2.0, 0.1);
    EXPECT_LT(r.values[1], 0.01);  // λ_max ~ ln t / t on a torus: ln 2000 / 2000 = 0.0038
  }
  const auto chaos =
      newtop::test::run_newtop("chaos " + example("section_brun.toml") + " --t-end 2000 --json",
                               newtop::test::Stderr::separate);
  ASSERT_EQ(chaos.code, 0) << chaos.err;
  const auto j = nlohmann::json::parse(chaos.out);
  EXPECT_EQ(run.results[0].values[0], j["megno"].get<double>());
  EXPECT_EQ(run.results[0].values[1], j["lyapunov_max"].get<double>());
}

// A swept integer key of the base keeps an integer literal: 1e6 is written 1000000 (the scenario
// reader refuses 1e+06 for an integer key such as [output] every).
TEST(Sweep, IntegerKeysTakeIntegralValues) {
  const SweepFile s = newtop::sweep::load_sweep(
      write_file("integer.toml", "scenario = \"" + example("heavy_top.toml") +
                                     "\"\nquantities = [\"drift\"]\n[[axes]]\nkey = "
                                     "\"output.every\"\nvalues = [1e6, 20]\n[integrate]\nt_end = "
                                     "0.01\n"));
  EXPECT_EQ(newtop::sweep::point_scenario(s, 0).output.every, 1000000);
  EXPECT_EQ(newtop::sweep::point_scenario(s, 1).output.every, 20);
}

// [level]: every start on the energy level h (the final state's energy, computed here from the
// spec's formula, equals h within the run's own energy drift), the chosen sign of the solved
// component, and the grid points where h is out of reach `off_level` with no numbers.
TEST(Sweep, LevelPutsEveryStartOnTheEnergyLevel) {
  const double h = 1.5;
  const SweepFile s = newtop::sweep::load_sweep(write_file(
      "level.toml",
      "scenario = \"" + example("section_chaotic.toml") +
          "\"\nquantities = [\"drift\", \"final_state\"]\n[level]\nenergy = 1.5\nsolve = "
          "\"omega2\"\nsign = \"-\"\n[[axes]]\nkey = \"initial.omega[0]\"\nstart = -2.2\nstop = "
          "2.2\ncount = 9\n[integrate]\nt_end = 5.0\nstep = 0.01\n"));
  // The scenario's body (section_chaotic.toml): I, M r0, g, λ of docs/model.md §3.
  const newtop::Vec3 I(1.0, 1.5, 2.2), Mr0(0.3, 0.2, 0.1);
  const double g = -0.4, lambda = -0.8;
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  int ok = 0, off = 0;
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    const auto& r = run.results[k];
    const newtop::io::Scenario sc = newtop::sweep::point_scenario(s, k);
    if (r.status == "off_level") {
      ++off;
      EXPECT_TRUE(r.values.empty());
      continue;
    }
    ASSERT_EQ(r.status, "ok");
    ++ok;
    EXPECT_LT(newtop::omega(sc.model.body(), sc.initial)[1], 0.0);  // sign = "-"
    // values: drift_energy, drift_area, drift_geometric, t, p, q, r, gamma1..3
    const newtop::Vec3 w(r.values[4], r.values[5], r.values[6]);
    const newtop::Vec3 gm(r.values[7], r.values[8], r.values[9]);
    const double e = 0.5 * w.dot(I.cwiseProduct(w)) + g * Mr0.dot(gm) +
                     0.5 * lambda * gm.dot(I.cwiseProduct(gm));
    EXPECT_LE(std::abs(e - h), r.values[0] + 1e-13) << k;
  }
  EXPECT_EQ(ok, 7);  // |omega1| = 2.2 leaves no room on the level (½ 2.2² > h − V − ½ I3 r²)
  EXPECT_EQ(off, 2);
}

struct BadSweep {
  const char* name;
  std::string text;
  const char* names;  // what the one line must name
};

TEST(Sweep, BadSweepFilesGetOneLineAndNoOutput) {
  const std::string base = "scenario = \"" + example("stability_beletsky.toml") + "\"\n";
  const std::string axis = "[[axes]]\nkey = \"body.inertia[2]\"\n";
  const std::vector<BadSweep> cases{
      {"unknown_key", base + "quantities = [\"stability\"]\ncolour = 1\n", "colour"},
      {"unknown_quantity", base + "quantities = [\"stabilty\"]\n", "stabilty"},
      {"empty_values", base + "quantities = [\"drift\"]\n" + axis + "values = []\n", "values"},
      {"empty_range",
       base + "quantities = [\"drift\"]\n" + axis + "start = 1\nstop = 2\ncount = 0\n", "count"},
      {"missing_key",
       base + "quantities = [\"drift\"]\n[[axes]]\nkey = \"body.colour\"\nvalues = [1]\n",
       "body.colour"},
      {"not_numeric",
       "scenario = \"" + example("heavy_top.toml") +
           "\"\nquantities = [\"drift\"]\n[[axes]]\nkey = \"field.kind\"\nvalues = [1]\n",
       "numeric"},
      {"index_out_of_range",
       base + "quantities = [\"drift\"]\n[[axes]]\nkey = \"body.inertia[3]\"\nvalues = [1]\n",
       "index"},
      {"non_physical", base + "quantities = [\"drift\"]\n" + axis + "values = [2.2, 9.0]\n",
       "inertia"},
      {"not_a_fixed_point",
       base +
           "quantities = [\"stability\"]\n[[axes]]\nkey = \"initial.omega[0]\"\nvalues = [0.5]\n",
       "stability"},
      {"level_key", base + "quantities = [\"drift\"]\n[level]\nenergy = 1\nsolve = \"m3\"\n",
       "solve"},
      {"level_with_stability", base + "quantities = [\"stability\"]\n[level]\nenergy = 1\n",
       "level"},
      {"level_without_energy", base + "quantities = [\"drift\"]\n[level]\nsign = \"-\"\n",
       "energy"},
      {"zip_lengths",
       base + "quantities = [\"drift\"]\ncombine = \"zip\"\n" + axis +
           "values = [2.2, 2.3]\n[[axes]]\nkey = \"body.inertia[1]\"\nvalues = [1.5]\n",
       "zip"},
      // Found by tests/fuzz/fuzz_sweep.cpp: the middle value of this range was inf.
      {"range_overflows",
       base + "quantities = [\"drift\"]\n" + axis + "start = -1.7e308\nstop = 1.7e308\ncount = 3\n",
       "stop - start"},
      // Refused before the values are made (they would take 1.6 GB).
      {"huge_grid",
       base + "quantities = [\"drift\"]\n" + axis + "start = 1\nstop = 2\ncount = 2\n" +
           "[[axes]]\nkey = \"body.inertia[1]\"\nstart = 1\nstop = 2\ncount = 100000000\n" +
           "[[axes]]\nkey = \"body.inertia[0]\"\nstart = 1\nstop = 2\ncount = 100000000\n",
       "points"},
  };
  for (const BadSweep& c : cases) {
    const fs::path f = write_file(std::string(c.name) + ".toml", c.text);
    const fs::path out = scratch(std::string(c.name) + ".csv");
    const auto r = newtop::test::run_newtop("sweep " + f.string() + " --out " + out.string());
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << c.name << ": " << r.out;
    EXPECT_NE(r.out.find(c.names), std::string::npos) << c.name << ": " << r.out;
    EXPECT_FALSE(fs::exists(out)) << c.name;
    EXPECT_FALSE(fs::exists(out.string() + ".checkpoint")) << c.name;
  }
}

}  // namespace
}  // namespace test_sweep
