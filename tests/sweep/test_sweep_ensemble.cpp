// Sweeps of trajectory quantities through the ensemble stepper: every point's result (status and
// values, bit for bit) is the one evaluate_point computes for the point alone, for any batch of
// points, any thread count, and points whose runs differ (model, step, step limit) in one batch.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "newtop/sweep/sweep.hpp"
#include "newtop/sweep/sweep_ensemble.hpp"
#include "support/cli.hpp"

namespace test_sweep_ensemble {
namespace {

namespace fs = std::filesystem;
using newtop::sweep::PointResult;
using newtop::sweep::SweepFile;

fs::path write_file(const std::string& name, const std::string& text) {
  return newtop::test::write_text(newtop::test::scratch_path("newtop_sweep_ensemble", name), text);
}

// Status and values with the same bits (NaN included).
void expect_same(const PointResult& a, const PointResult& b, std::size_t i) {
  ASSERT_EQ(a.status, b.status) << "point " << i;
  ASSERT_EQ(a.values.size(), b.values.size()) << "point " << i;
  for (std::size_t k = 0; k < a.values.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.values[k]), std::bit_cast<std::uint64_t>(b.values[k]))
        << "point " << i << " column " << k << ": " << a.values[k] << " vs " << b.values[k];
  }
}

// The heavy top of examples/heavy_top.toml (with a step limit) over its initial angular velocity:
// 5 × 30 points, more than two blocks of lanes of any path; `extra` adds axes.
std::string heavy_top_sweep(const std::string& quantities, const std::string& extra) {
  const fs::path base =
      write_file("heavy_top.toml",
                 "[body]\ninertia = [2.0, 2.0, 1.0]\nmass = 1.0\ncenter_of_mass = [0.0, 0.0, 0.5]\n"
                 "[field]\nkind = \"uniform\"\ng = 9.81\n"
                 "[initial]\nomega = [0.3, 0.0, 20.0]\ngamma = [0.5, 0.0, 0.8660254037844386]\n"
                 "[integrate]\nt_end = 0.5\nstep = 2e-3\nmax_steps = 1000000\n");
  return "scenario = \"" + base.string() + "\"\nquantities = [" + quantities +
         "]\n[[axes]]\nkey = \"initial.omega[0]\"\nstart = -1.0\nstop = 1.0\ncount = 5\n"
         "[[axes]]\nkey = \"initial.omega[2]\"\nstart = 1.0\nstop = 30.0\ncount = 30\n" +
         extra;
}

// `runs`: the number of ensemble runs the whole sweep takes as one batch.
// Points i and j computed and different in column c (the sweep is not one point repeated).
void expect_points_differ(const SweepFile& s, std::size_t i, std::size_t j, std::size_t c) {
  const PointResult a = newtop::sweep::evaluate_point(s, i),
                    b = newtop::sweep::evaluate_point(s, j);
  ASSERT_EQ(a.status, "ok");
  ASSERT_EQ(b.status, "ok");
  EXPECT_NE(a.values[c], b.values[c]);
}

void expect_point_by_point(const SweepFile& s, std::size_t runs = 1) {
  ASSERT_TRUE(newtop::sweep::ensemble_sweep(s));
  // Every point goes through the ensemble stepper (none falls back to evaluate_point).
  std::vector<std::size_t> all(newtop::sweep::point_count(s));
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  std::size_t in_ensemble = 0, batch_runs = 0;
  const std::vector<PointResult> batch =
      newtop::sweep::evaluate_points(s, all, &in_ensemble, &batch_runs);
  EXPECT_EQ(in_ensemble, all.size());
  EXPECT_EQ(batch_runs, runs);
  for (std::size_t i = 0; i < all.size(); ++i) {
    expect_same(batch[i], newtop::sweep::evaluate_point_safely(s, i), i);
  }
  for (int threads : {1, 2}) {
    newtop::sweep::RunOptions o;
    o.threads = threads;
    const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, o);
    ASSERT_EQ(run.results.size(), newtop::sweep::point_count(s));
    for (std::size_t i = 0; i < run.results.size(); ++i) {
      expect_same(run.results[i], newtop::sweep::evaluate_point_safely(s, i), i);
    }
  }
}

TEST(SweepEnsemble, FinalStateAndDriftAreEvaluatePointsBits) {
  const SweepFile s = newtop::sweep::load_sweep(
      write_file("both.toml", heavy_top_sweep("\"final_state\", \"drift\"", "")));
  expect_point_by_point(s);
  // The points did run and drift a little (a run that stood still would agree trivially).
  const PointResult r = newtop::sweep::evaluate_point(s, 7);
  ASSERT_EQ(r.status, "ok");
  EXPECT_EQ(r.values[0], 0.5);                 // t
  EXPECT_GT(r.values[7], 0.0);                 // drift_energy
  EXPECT_NE(r.values[6], 0.8660254037844386);  // gamma3 moved
}

// An orbit scenario with method taylor over its start and its body (a model per lane): every
// point through the orbit's Taylor ensemble, each evaluate_point's bits; on a circle (the Jacobi
// integral's drift too) and on an ellipse (in ν, the time reached from Kepler's equation).
std::string orbit_taylor_sweep(const char* example, const char* t_end, const char* start_key,
                               const char* inertia) {
  return "scenario = \"" + newtop::test::example_path(example) +
         "\"\nquantities = [\"final_state\", \"drift\"]\n[integrate]\nmethod = \"taylor\"\n"
         "tol = 1e-10\nt_end = " +
         t_end + "\n[[axes]]\nkey = \"" + start_key +
         "\"\nvalues = [0.0, 0.03, 0.06, 0.09, 0.12]\n[[axes]]\nkey = \"body.inertia[0]\"\n"
         "values = " +
         inertia + "\n";
}

TEST(SweepEnsemble, OrbitTaylorFinalStateAndDriftAreEvaluatePointsBits) {
  const SweepFile circle = newtop::sweep::load_sweep(
      write_file("orbit_circle.toml",
                 orbit_taylor_sweep("satellite_700km.toml", "3000.0", "initial.roll_pitch_yaw[1]",
                                    "[1200.0, 1300.0, 1400.0]")));
  expect_point_by_point(circle);
  const PointResult r = newtop::sweep::evaluate_point(circle, 4);
  ASSERT_EQ(r.status, "ok");
  EXPECT_EQ(r.values[0], 3000.0);  // t
  EXPECT_GT(r.values[10], 0.0);    // drift_jacobi: the run moved
  const SweepFile ellipse = newtop::sweep::load_sweep(write_file(
      "orbit_ellipse.toml", orbit_taylor_sweep("orbit_elliptic_pitch.toml", "3.0",
                                               "initial.euler_321[0]", "[1.0, 1.1, 1.2]")));
  expect_point_by_point(ellipse);
  EXPECT_EQ(newtop::sweep::evaluate_point(ellipse, 2).values[0], 3.0);
}

// MEGNO and λ_max of an orbit scenario with method taylor: every point through the orbit's Taylor
// ensemble's chaos runs, each evaluate_point's bits (newtop chaos's numbers on that point).
TEST(SweepEnsemble, OrbitTaylorMegnoIsEvaluatePointsBits) {
  const std::string base = orbit_taylor_sweep(
      "satellite_700km.toml", "3000.0", "initial.roll_pitch_yaw[1]", "[1200.0, 1300.0, 1400.0]");
  const std::string chaos = std::regex_replace(base, std::regex("\\[\"final_state\", \"drift\"\\]"),
                                               "[\"megno\", \"lyapunov_max\"]");
  ASSERT_NE(chaos, base);
  const SweepFile circle = newtop::sweep::load_sweep(write_file("orbit_megno.toml", chaos));
  expect_point_by_point(circle);
  const PointResult r = newtop::sweep::evaluate_point(circle, 4);
  ASSERT_EQ(r.status, "ok");
  EXPECT_GT(r.values[0], 0.0);  // MEGNO of a run that moved
  const std::string ell =
      std::regex_replace(orbit_taylor_sweep("orbit_elliptic_pitch.toml", "3.0",
                                            "initial.euler_321[0]", "[1.0, 1.1, 1.2]"),
                         std::regex("\\[\"final_state\", \"drift\"\\]"), "[\"lyapunov_max\"]");
  expect_point_by_point(newtop::sweep::load_sweep(write_file("orbit_ellipse_megno.toml", ell)));
}

TEST(SweepEnsemble, FinalStateAloneIsEvaluatePointsBits) {
  // Without drift the state is checked for non-finite numbers every 256 steps only.
  expect_point_by_point(
      newtop::sweep::load_sweep(write_file("final.toml", heavy_top_sweep("\"final_state\"", ""))));
}

// Points of one batch with different models (C) and step limits: grouped by step limit, the
// models held per lane.
TEST(SweepEnsemble, PointsWithDifferentRunsInOneBatch) {
  const std::string extra =
      "[[axes]]\nkey = \"body.inertia[2]\"\nvalues = [1.0, 1.5]\n"
      "[[axes]]\nkey = \"integrate.max_steps\"\nvalues = [249, 250]\n";
  const SweepFile s = newtop::sweep::load_sweep(
      write_file("mixed.toml", heavy_top_sweep("\"drift\", \"final_state\"", extra)));
  expect_point_by_point(s, 2);
  // Both outcomes, at the edge: the run takes 250 steps.
  EXPECT_EQ(newtop::sweep::evaluate_point(s, 0).status, "step_limit");
  EXPECT_EQ(newtop::sweep::evaluate_point(s, 1).status, "ok");
  // Any subset, in any order, as one batch.
  std::vector<std::size_t> some;
  for (std::size_t i = newtop::sweep::point_count(s); i-- > 0;) {
    if (i % 3 != 1) some.push_back(i);
  }
  const std::vector<PointResult> r = newtop::sweep::evaluate_points(s, some);
  ASSERT_EQ(r.size(), some.size());
  for (std::size_t k = 0; k < some.size(); ++k) {
    expect_same(r[k], newtop::sweep::evaluate_point_safely(s, some[k]), some[k]);
  }
}

// A sweep over the model's numbers (the moments in every order of size, the field's λ, the
// gyrostat, the centre of mass) in one ensemble run, a model per lane: every point's result is the
// bits of its own run.
TEST(SweepEnsemble, PointsOverModelParametersInOneRun) {
  const fs::path base =
      write_file("gyrostat.toml",
                 "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\ncenter_of_mass = [0.3, 0.2, 0.1]\n"
                 "gyrostat = [0.1, -0.2, 0.05]\n[field]\ng = 1.0\nlambda = 0.5\n"
                 "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n"
                 "[integrate]\nt_end = 2.0\nstep = 0.01\nmethod = \"splitting4\"\n");
  const std::string sweep =
      "scenario = \"" + base.string() +
      "\"\nquantities = [\"final_state\", \"drift\"]\n"
      "[[axes]]\nkey = \"body.inertia[0]\"\nvalues = [0.8, 1.2, 1.7, 2.0]\n"
      "[[axes]]\nkey = \"field.lambda\"\nstart = -1.0\nstop = 1.0\ncount = 5\n"
      "[[axes]]\nkey = \"body.gyrostat[2]\"\nvalues = [0.0, 0.05]\n"
      "[[axes]]\nkey = \"body.center_of_mass[2]\"\nvalues = [-0.1, 0.1, 0.4]\n";
  const SweepFile s = newtop::sweep::load_sweep(write_file("params.toml", sweep));
  expect_point_by_point(s);
  expect_points_differ(s, 0, 1, 1);  // their final states are not one state
}

// The same sweep with a tolerance (method taylor) through the Taylor ensemble, a model per lane,
// with two step limits (two runs): every point the bits of its own scalar Taylor run, both
// outcomes present.
TEST(SweepEnsemble, TaylorPointsOverModelParametersAreEvaluatePointsBits) {
  const fs::path base = write_file(
      "gyrostat_taylor.toml",
      "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\ncenter_of_mass = [0.3, 0.2, 0.1]\n"
      "gyrostat = [0.1, -0.2, 0.05]\n[field]\ng = 1.0\nlambda = 0.5\n"
      "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n"
      "[integrate]\nt_end = 6.0\nmethod = \"taylor\"\ntol = 1e-11\nmax_steps = 1000000\n");
  const std::string sweep =
      "scenario = \"" + base.string() +
      "\"\nquantities = [\"final_state\", \"drift\"]\n"
      "[[axes]]\nkey = \"body.inertia[0]\"\nvalues = [0.8, 1.2, 1.7, 2.0]\n"
      "[[axes]]\nkey = \"field.lambda\"\nstart = -1.0\nstop = 1.0\ncount = 5\n"
      "[[axes]]\nkey = \"initial.omega[2]\"\nvalues = [-0.4, 2.5]\n"
      "[[axes]]\nkey = \"integrate.max_steps\"\nvalues = [12, 1000000]\n";
  const SweepFile s = newtop::sweep::load_sweep(write_file("taylor_params.toml", sweep));
  expect_point_by_point(s, 2);
  expect_points_differ(s, 1, 3, 1);  // their final states are not one state
  std::size_t limited = 0;
  for (std::size_t i = 0; i < newtop::sweep::point_count(s); i += 2) {
    limited += newtop::sweep::evaluate_point(s, i).status == "step_limit";
  }
  EXPECT_GT(limited, 0u);
  EXPECT_LT(limited, newtop::sweep::point_count(s) / 2);
}

// Points whose runs all differ (a sweep over the step) run one by one: a block of lanes for one
// point would cost more than its scalar run. The results are the same bits either way.
TEST(SweepEnsemble, PointsAloneInTheirRunRunOneByOne) {
  const SweepFile s = newtop::sweep::load_sweep(
      write_file("steps.toml", heavy_top_sweep("\"final_state\"",
                                               "[[axes]]\nkey = \"integrate.step\"\n"
                                               "values = [1e-3, 2e-3, 4e-3]\n")));
  // 150 points of three steps; then the steps alone.
  expect_point_by_point(s, 3);
  std::vector<std::size_t> alone = {0, 1, 2};
  std::size_t in_ensemble = 1, runs = 1;
  const std::vector<PointResult> r = newtop::sweep::evaluate_points(s, alone, &in_ensemble, &runs);
  EXPECT_EQ(in_ensemble, 0u);
  EXPECT_EQ(runs, 0u);
  for (std::size_t i : alone) expect_same(r[i], newtop::sweep::evaluate_point_safely(s, i), i);
}

// MEGNO and λ_max over initial conditions (the map of examples/sweep_megno.toml, shorter): one
// ensemble tangent run, every point the bits of newtop chaos's run (evaluate_point).
TEST(SweepEnsemble, MegnoMapIsEvaluatePointsBits) {
  const std::string sweep =
      "scenario = \"" + std::string(NEWTOP_SOURCE_DIR) +
      "/examples/section_chaotic.toml\"\nquantities = [\"lyapunov_max\", \"megno\"]\n"
      "[[axes]]\nkey = \"initial.omega[0]\"\nstart = -1.5\nstop = 1.5\ncount = 7\n"
      "[[axes]]\nkey = \"initial.omega[1]\"\nstart = -1.5\nstop = 1.5\ncount = 7\n"
      "[integrate]\nt_end = 40.0\n";
  const SweepFile s = newtop::sweep::load_sweep(write_file("megno.toml", sweep));
  expect_point_by_point(s);
  expect_points_differ(s, 0, 24, 1);  // the map is not flat
}

// The MEGNO map with a tolerance (method taylor): one Taylor ensemble tangent run, every point
// the bits of newtop chaos's scalar Taylor run (evaluate_point).
TEST(SweepEnsemble, TaylorMegnoMapIsEvaluatePointsBits) {
  const std::string sweep =
      "scenario = \"" + std::string(NEWTOP_SOURCE_DIR) +
      "/examples/section_chaotic.toml\"\nquantities = [\"megno\", \"lyapunov_max\"]\n"
      "[[axes]]\nkey = \"initial.omega[0]\"\nstart = -1.5\nstop = 1.5\ncount = 5\n"
      "[[axes]]\nkey = \"initial.omega[1]\"\nstart = -1.5\nstop = 1.5\ncount = 5\n"
      "[integrate]\nt_end = 30.0\nmethod = \"taylor\"\ntol = 1e-10\n";
  const SweepFile s = newtop::sweep::load_sweep(write_file("megno_taylor.toml", sweep));
  expect_point_by_point(s);
  expect_points_differ(s, 0, 12, 0);  // the map is not flat
}

// MEGNO over the model's numbers (A across B, λ of both signs) in one ensemble tangent run, a
// model per lane: every point the bits of its own tangent run.
TEST(SweepEnsemble, MegnoOverModelParametersInOneRun) {
  const std::string sweep =
      "scenario = \"" + std::string(NEWTOP_SOURCE_DIR) +
      "/examples/coulomb.toml\"\nquantities = [\"megno\", \"lyapunov_max\"]\n"
      "[[axes]]\nkey = \"body.inertia[0]\"\nvalues = [0.8, 1.2, 1.6, 1.9]\n"
      "[[axes]]\nkey = \"field.lambda\"\nstart = -1.5\nstop = 1.5\ncount = 5\n"
      "[integrate]\nt_end = 5.0\nmethod = \"splitting4\"\n";
  const SweepFile s = newtop::sweep::load_sweep(write_file("megno_params.toml", sweep));
  expect_point_by_point(s);
  expect_points_differ(s, 0, 1, 0);
}

// A MEGNO map with the spin split of the free body: the ensemble tangent kernels have the axes
// split only, so every point runs alone through the scalar tangent map of the spin split (none in
// the ensemble, every point ok and evaluate_point's bits), and its values are those of the axes
// split within 1e-6 (another map of the same flow over a short run). Six points: enough for a
// group of lanes, had the split been let through.
TEST(SweepEnsemble, MegnoWithTheSpinSplitRunsPointByPoint) {
  std::ifstream in(std::string(NEWTOP_SOURCE_DIR) + "/examples/section_chaotic.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string scenario = text.str();
  const std::size_t at = scenario.find("step = 0.02\n");
  ASSERT_NE(at, std::string::npos);
  scenario.insert(at, "split = \"spin\"\n");
  const std::string spin_path = write_file("spin_scenario.toml", scenario);
  auto sweep_of = [](const std::string& path) {
    return "scenario = \"" + path +
           "\"\nquantities = [\"megno\", \"lyapunov_max\"]\n"
           "[[axes]]\nkey = \"initial.omega[0]\"\nstart = -1.5\nstop = 1.5\ncount = 6\n"
           "[integrate]\nt_end = 20.0\n";
  };
  const SweepFile spin =
      newtop::sweep::load_sweep(write_file("megno_spin.toml", sweep_of(spin_path)));
  const SweepFile axes = newtop::sweep::load_sweep(
      write_file("megno_axes.toml",
                 sweep_of(std::string(NEWTOP_SOURCE_DIR) + "/examples/section_chaotic.toml")));
  std::vector<std::size_t> all(newtop::sweep::point_count(spin));
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  std::size_t in_ensemble = 1, runs = 1;
  const std::vector<PointResult> r = newtop::sweep::evaluate_points(spin, all, &in_ensemble, &runs);
  EXPECT_EQ(in_ensemble, 0u);
  EXPECT_EQ(runs, 0u);
  for (std::size_t i : all) {
    ASSERT_EQ(r[i].status, "ok") << i;
    expect_same(r[i], newtop::sweep::evaluate_point_safely(spin, i), i);
    const PointResult a = newtop::sweep::evaluate_point(axes, i);
    ASSERT_EQ(a.values.size(), r[i].values.size());
    for (std::size_t q = 0; q < a.values.size(); ++q) {
      EXPECT_NEAR(r[i].values[q], a.values[q], 1e-6) << i << " " << q;
      EXPECT_NE(r[i].values[q], a.values[q]) << i << " " << q;  // the spin split ran
    }
  }
}

}  // namespace
}  // namespace test_sweep_ensemble
