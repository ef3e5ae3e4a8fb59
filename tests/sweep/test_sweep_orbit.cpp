// Sweeps over orbit scenarios (docs/sweep.md "Orbit scenarios"): the DeBra–Delp atlas against the
// analytic boundary curves of docs/orbit.md §8 and its frequencies against the model's own
// linearisation, the inertia ratios as keys, trajectory quantities against the relative
// equilibrium and the conservation laws, the synchronous odd family against the located events of
// docs/continuation.md and the small-e series, the same bits on any thread count, and the
// quantities that do not apply refused naming the model.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "newtop/orbit/debra_delp.hpp"
#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_stability.hpp"
#include "newtop/sweep/sweep.hpp"
#include "support/cli.hpp"

namespace test_sweep_orbit {
namespace {

namespace fs = std::filesystem;
using newtop::sweep::SweepFile;

constexpr double kEps = std::numeric_limits<double>::epsilon();

fs::path write_file(const std::string& name, const std::string& text) {
  return newtop::test::write_text(newtop::test::scratch_path("newtop_sweep_orbit", name), text);
}

std::string example(const char* name) { return newtop::test::example_path(name); }

SweepFile load(const std::string& name, const std::string& text) {
  return newtop::sweep::load_sweep(write_file(name, text).string());
}

/// The column `name` of point i.
double column(const SweepFile& s, const newtop::sweep::SweepRun& run, std::size_t i,
              const std::string& name) {
  const auto c = newtop::sweep::quantity_columns(s);
  const auto k = static_cast<std::size_t>(std::find(c.begin(), c.end(), name) - c.begin());
  EXPECT_LT(k, c.size()) << name;
  EXPECT_EQ(run.results[i].status, "ok");
  return run.results[i].values.at(k);
}

/// A neighbour pair whose classes differ must lie on both sides of (or on) one of the analytic
/// boundaries of docs/orbit.md §8: k_R = k_Y (pitch), k_R k_Y = 0 (roll–yaw, through k_R = 0 or
/// k_Y = 0), and 1 + 3k_R + k_R k_Y = 4√(k_R k_Y) where k_R k_Y > 0 (roll–yaw, a Krein collision).
bool straddles(double r1, double y1, double r2, double y2) {
  auto across = [](double a, double b) { return a * b <= 0.0; };
  auto krein = [](double r, double y) { return 1 + 3 * r + r * y - 4 * std::sqrt(r * y); };
  return across(r1 - y1, r2 - y2) || across(r1, r2) || across(y1, y2) ||
         (r1 * y1 > 0 && r2 * y2 > 0 && across(krein(r1, y1), krein(r2, y2)));
}

/// The class of docs/orbit.md §8 off the boundaries: 2 Lagrange (k_R > k_Y > 0), 1 DeBra–Delp
/// (the same conditions with k_R, k_Y < 0), 0 unstable.
double region(double r, double y) {
  const bool stable = r > y && r * y > 0 && 1 + 3 * r + r * y > 4 * std::sqrt(r * y);
  return stable ? (r > 0 ? 2.0 : 1.0) : 0.0;
}

TEST(SweepOrbit, DebraDelpCellsStraddleTheAnalyticBoundaries) {
  const SweepFile s = newtop::sweep::load_sweep(example("sweep_debra_delp.toml"));
  ASSERT_EQ(s.model, newtop::sweep::BaseModel::circular_orbit);
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  const std::vector<double>& kr = s.axes[0].values;
  const std::vector<double>& ky = s.axes[1].values;
  const std::size_t n = kr.size(), m = ky.size();
  auto cls = [&](std::size_t i, std::size_t j) {
    return column(s, run, i * m + j, "stability_class");
  };
  int changes = 0, seen[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t p = i * m + j;
      // The key sets the moments (each within a few ulps, written with 17 digits), whose ratios
      // come back to the value within those ulps over the divisor: k_R = (B − C)/A.
      const newtop::Vec3 I = newtop::inertia_from_ratios(kr[i], ky[j]);
      EXPECT_NEAR(column(s, run, p, "k_R"), kr[i], 8 * kEps * (1 + (I[1] + I[2]) / I[0]));
      EXPECT_NEAR(column(s, run, p, "k_Y"), ky[j], 8 * kEps * (1 + (I[1] + I[0]) / I[2]));
      ++seen[static_cast<int>(cls(i, j))];
      if (column(s, run, p, "boundary") == 0.0) {  // off the curves: the regions of §8
        EXPECT_EQ(cls(i, j), region(kr[i], ky[j])) << kr[i] << ", " << ky[j];
        EXPECT_EQ(cls(i, j), column(s, run, p, "closed_form_class")) << kr[i] << ", " << ky[j];
      }
      if (i + 1 < n && cls(i, j) != cls(i + 1, j)) {
        ++changes;
        EXPECT_TRUE(straddles(kr[i], ky[j], kr[i + 1], ky[j])) << kr[i] << ", " << ky[j];
      }
      if (j + 1 < m && cls(i, j) != cls(i, j + 1)) {
        ++changes;
        EXPECT_TRUE(straddles(kr[i], ky[j], kr[i], ky[j + 1])) << kr[i] << ", " << ky[j];
      }
    }
  }
  EXPECT_GT(changes, 100);  // the boundaries cross the grid
  EXPECT_GT(seen[0], 0);
  EXPECT_GT(seen[1], 0);  // the thin DeBra–Delp sliver is resolved
  EXPECT_GT(seen[2], 0);
}

// The engineer's spacecraft (1200, 1500, 900): the frequencies of the three librations, in units
// of n, are the imaginary parts of the eigenvalues of the model's own 6×6 leaf Jacobian at the
// rest orientation (a second computation: a numerical eigenproblem, not the closed form).
TEST(SweepOrbit, DebraDelpFrequenciesAreTheLinearisationsEigenvalues) {
  const SweepFile s =
      load("freq.toml", "scenario = \"" + example("satellite_700km.toml") +
                            "\"\nquantities = [\"debra_delp\"]\n[[axes]]\nkey = \"orbit.radius\"\n"
                            "values = [7.078137e6]\n");
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  EXPECT_EQ(column(s, run, 0, "stability_class"), 2.0);  // Lagrange: B > A > C
  const newtop::Body body = newtop::Body::from_principal({1200.0, 1500.0, 900.0}, 1.0, {0, 0, 0});
  const newtop::CircularOrbitModel model(body, newtop::CircularOrbit::from_rate(1.0));
  const newtop::OrbitState rest =
      newtop::relative_rest_state(model, newtop::Vec3::UnitZ(), newtop::Vec3::UnitY());
  Eigen::EigenSolver<newtop::OrbitReduced> eig(newtop::reduced_jacobian(model, rest));
  std::vector<double> im;
  for (int k = 0; k < 6; ++k) {
    if (eig.eigenvalues()[k].imag() > 0) im.push_back(eig.eigenvalues()[k].imag());
  }
  ASSERT_EQ(im.size(), 3u);
  std::vector<double> f{column(s, run, 0, "pitch_frequency"),
                        column(s, run, 0, "roll_yaw_frequency1"),
                        column(s, run, 0, "roll_yaw_frequency2")};
  std::sort(im.begin(), im.end());
  std::sort(f.begin(), f.end());
  // The eigenvalues of a 6×6 nonsymmetric matrix of entries ~1 to ~1e-14 (Eigen's QR iteration).
  constexpr double kEigenTolerance = 1e-12;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], im[k], kEigenTolerance);
  EXPECT_NEAR(f[1], std::sqrt(3 * (1200.0 - 900.0) / 1500.0), kEigenTolerance);  // pitch
}

TEST(SweepOrbit, RatioKeysSetTheMomentsKeepingThePitchMoment) {
  const SweepFile s = load("ratios.toml", "scenario = \"" + example("satellite_700km.toml") +
                                              "\"\nquantities = [\"debra_delp\"]\n[[axes]]\n"
                                              "key = \"body.k_R\"\nvalues = [0.3, -0.05]\n");
  for (std::size_t i = 0; i < 2; ++i) {
    const newtop::Vec3 I = newtop::sweep::orbit_point_scenario(s, i).body.inertia();
    EXPECT_EQ(I[1], 1500.0);
    EXPECT_NEAR((I[1] - I[2]) / I[0], s.axes[0].values[i], 8 * kEps);
    EXPECT_NEAR((I[1] - I[0]) / I[2], (1500.0 - 1200.0) / 900.0, 8 * kEps);  // k_Y kept
  }
}

// At rest in LVLH (pitch 0) the satellite stays at its relative equilibrium: after 6000 s its
// inertial angular velocity is still ω0 n = −ω0 e_y with ω0 = √(μ/R³) (a closed form), and the
// Jacobi integral and the Casimirs drift only by round-off (splitting6 keeps them).
TEST(SweepOrbit, FinalStateAndDriftOnACircularOrbit) {
  const SweepFile s =
      load("traj.toml", "scenario = \"" + example("satellite_700km.toml") +
                            "\"\nquantities = [\"final_state\", \"drift\"]\n[integrate]\n"
                            "t_end = 6000.0\n[[axes]]\nkey = \"orbit.radius\"\nvalues = [7.0e6, "
                            "8.0e6]\n[[axes]]\nkey = \"initial.roll_pitch_yaw[1]\"\n"
                            "values = [0.0, 0.1]\n");
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  // 600 steps: 64 ε √N for the Casimirs; the Jacobi integral (|H| ~ ω0² B ~ 2e-3) the same
  // relative to the moments' scale B ω0² (splitting6 at ω0 h ≈ 0.01: (ω0 h)⁶ ~ 1e-12 relative,
  // bounded, no drift).
  constexpr double kCasimirTolerance = 64 * kEps * 25;
  for (std::size_t i = 0; i < 4; ++i) {
    const double radius = s.axes[0].values[i / 2];
    const double w0 = std::sqrt(3.986004418e14 / (radius * radius * radius));
    EXPECT_EQ(column(s, run, i, "t"), 6000.0);
    EXPECT_LE(column(s, run, i, "drift_geometric"), kCasimirTolerance);
    EXPECT_LE(column(s, run, i, "drift_normal_normal"), kCasimirTolerance);
    EXPECT_LE(column(s, run, i, "drift_gamma_normal"), kCasimirTolerance);
    EXPECT_LE(column(s, run, i, "drift_jacobi"), 1e-12 * 1500.0 * w0 * w0);
    if (i % 2 == 0) {  // at rest in LVLH
      EXPECT_NEAR(column(s, run, i, "q"), -w0, 1e-12 * w0);
      EXPECT_NEAR(column(s, run, i, "normal2"), -1.0, 1e-12);
      EXPECT_NEAR(column(s, run, i, "gamma3"), -1.0, 1e-12);
    }
  }
}

// The same sweep with Taylor's method (docs/orbit.md §5): at rest in LVLH the closed form again,
// and a tilted start where Fehlberg 7(8) at 1e-13 ends (both runs' errors ~1e-11 relative over
// a few hundred steps: 1e-9 of the moments' scale).
TEST(SweepOrbit, FinalStateWithTaylorOnACircularOrbit) {
  auto sweep = [&](const char* method) {
    return newtop::sweep::run_sweep(
        load(std::string(method) + ".toml",
             "scenario = \"" + example("satellite_700km.toml") +
                 "\"\nquantities = [\"final_state\"]\n[integrate]\nt_end = 6000.0\nmethod = \"" +
                 method +
                 "\"\ntol = 1e-13\n[[axes]]\nkey = \"initial.roll_pitch_yaw[1]\"\n"
                 "values = [0.0, 0.1]\n"),
        {});
  };
  const SweepFile s = load("axes.toml", "scenario = \"" + example("satellite_700km.toml") +
                                            "\"\nquantities = [\"final_state\"]\n[[axes]]\n"
                                            "key = \"initial.roll_pitch_yaw[1]\"\n"
                                            "values = [0.0, 0.1]\n");
  const newtop::sweep::SweepRun taylor = sweep("taylor"), rkf78 = sweep("rkf78");
  const double w0 = std::sqrt(3.986004418e14 / std::pow(7.078137e6, 3));
  ASSERT_EQ(taylor.results[0].status, "ok");
  EXPECT_NEAR(column(s, taylor, 0, "q"), -w0, 1e-12 * w0);
  for (const char* c : {"p", "q", "r", "gamma1", "gamma2", "gamma3", "normal1", "normal3"}) {
    const double scale = c[0] == 'p' || c[0] == 'q' || c[0] == 'r' ? w0 : 1.0;
    EXPECT_NEAR(column(s, taylor, 1, c), column(s, rkf78, 1, c), 1e-9 * scale) << c;
  }
}

TEST(SweepOrbit, FinalStateOnAnEllipseIsAtTheTimeAsked) {
  const SweepFile s = load("ell.toml", "scenario = \"" + example("orbit_elliptic_pitch.toml") +
                                           "\"\nquantities = [\"final_state\", \"drift\"]\n"
                                           "[integrate]\nt_end = 3.0\n[[axes]]\n"
                                           "key = \"orbit.eccentricity\"\nvalues = [0.0, 0.3]\n");
  const auto cols = newtop::sweep::quantity_columns(s);
  EXPECT_EQ(std::count(cols.begin(), cols.end(), "drift_jacobi"), 0);  // not an integral there
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(column(s, run, i, "t"), 3.0);
}

// The odd synchronous family of k = 0.9 (A = 0.1, B = C = 1): period doubling between the flips
// at e = 0.275543 and 0.328662 and no member past the fold at e = 0.373743 (docs/continuation.md,
// located there against bisection and Newton's method to 1e-10); the grid agrees on both sides
// of each, 2e-3 away.
TEST(SweepOrbit, SynchronousOddAgreesWithTheFamilysEvents) {
  const SweepFile s = load(
      "sync.toml", "scenario = \"" + example("continue_synchronous.toml") +
                       "\"\nquantities = [\"synchronous_odd\"]\n[[axes]]\n"
                       "key = \"orbit.eccentricity\"\n"
                       "values = [0.273543, 0.277543, 0.326662, 0.330662, 0.371743, 0.375743]\n");
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  const double stable[] = {1, 0, 0, 1, 1};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(column(s, run, i, "odd_found"), 1.0) << i;
    EXPECT_EQ(column(s, run, i, "odd_stable"), stable[i]) << i;
    EXPECT_NEAR(column(s, run, i, "k"), 0.9, 4 * kEps);
  }
  EXPECT_EQ(column(s, run, 5, "odd_found"), 0.0);
  EXPECT_TRUE(std::isnan(column(s, run, 5, "odd_stable")));
}

// Small e: the odd synchronous solution is θ = 2e sin ν/(3k − 1) + O(e²) (docs/orbit.md §9), so
// θ′(0) = 2e/(3k − 1) + O(e²); at k = 0.2 (A = 0.8) the rest is c e² with c ≈ 5 (measured 5.3 at
// e = 0.01): below 8 e², and quartered as e halves (4 ± 0.4: the O(e³) part, about 4 % of it at
// e = 0.005, raises the ratio).
TEST(SweepOrbit, SynchronousOddFollowsTheSmallEccentricitySeries) {
  const SweepFile s = load("series.toml", "scenario = \"" + example("continue_synchronous.toml") +
                                              "\"\nquantities = [\"synchronous_odd\"]\n[[axes]]\n"
                                              "key = \"body.inertia[0]\"\nvalues = [0.8]\n"
                                              "[[axes]]\nkey = \"orbit.eccentricity\"\n"
                                              "values = [0.0025, 0.005]\n");
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  double error[2];
  for (std::size_t i = 0; i < 2; ++i) {
    const double e = s.axes[1].values[i];
    error[i] = column(s, run, i, "odd_dtheta0") - 2 * e / (3 * 0.2 - 1);
    EXPECT_LT(std::abs(error[i]), 8 * e * e);
  }
  EXPECT_NEAR(error[1] / error[0], 4.0, 0.4);
}

TEST(SweepOrbit, SameBitsOnAnyThreadCount) {
  const SweepFile s = load("threads.toml", "scenario = \"" + example("continue_synchronous.toml") +
                                               "\"\nquantities = [\"synchronous_odd\", "
                                               "\"final_state\"]\n[integrate]\nt_end = 1.0\n"
                                               "[[axes]]\nkey = \"orbit.eccentricity\"\n"
                                               "start = 0.0\nstop = 0.4\ncount = 9\n");
  newtop::sweep::RunOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = newtop::sweep::run_sweep(s, one), b = newtop::sweep::run_sweep(s, two);
  for (std::size_t i = 0; i < a.results.size(); ++i) {
    ASSERT_EQ(a.results[i].values.size(), b.results[i].values.size());
    for (std::size_t k = 0; k < a.results[i].values.size(); ++k) {
      const double x = a.results[i].values[k], y = b.results[i].values[k];
      EXPECT_TRUE(std::memcmp(&x, &y, sizeof x) == 0) << i << ", " << k;
    }
  }
}

// megno and lyapunov_max on an orbit are newtop chaos's indicators of the point (orbit_chaos, the
// orbit's variational equations with the sweep's embedded pair): the same bits as a direct call on
// the point's scenario; a 0.1 rad pitch libration about the stable LVLH rest orientation is
// regular (MEGNO well below the ~λt/2 of a chaotic run); a splitting is refused naming `method`.
TEST(SweepOrbit, MegnoAndLyapunovAreThoseOfTheOrbitsTangentRun) {
  const std::string base = "scenario = \"" + example("satellite_700km.toml") +
                           "\"\nquantities = [\"megno\", \"lyapunov_max\"]\n[integrate]\n"
                           "t_end = 20000.0\n";
  const SweepFile s = load("chaos.toml", base +
                                             "method = \"rkf78\"\ntol = 1e-10\n[[axes]]\n"
                                             "key = \"initial.roll_pitch_yaw[1]\"\n"
                                             "values = [0.0, 0.1]\n");
  const newtop::sweep::SweepRun run = newtop::sweep::run_sweep(s, {});
  for (std::size_t i = 0; i < 2; ++i) {
    const auto sc = newtop::sweep::orbit_point_scenario(s, i);
    newtop::OrbitChaosSettings c;
    c.method = newtop::MethodSettings("rkf78", 0.0, 1e-10, 1e-10);
    c.t0 = sc.integrate.t0;
    c.t1 = 20000.0;
    const auto direct = newtop::orbit_chaos(
        newtop::CircularOrbitModel(sc.body, std::get<newtop::CircularOrbit>(sc.orbit)), sc.initial,
        c);
    const double megno = column(s, run, i, "megno"), lyap = column(s, run, i, "lyapunov_max");
    EXPECT_EQ(std::memcmp(&megno, &direct.indicators.megno, sizeof megno), 0) << i;
    EXPECT_EQ(std::memcmp(&lyap, &direct.indicators.lyapunov_max, sizeof lyap), 0) << i;
    // Regular: MEGNO tends to 2 (docs/chaos.md); 4 leaves room for the slow approach at ~3 pitch
    // periods per 20000 s while a chaotic run grows without bound.
    EXPECT_LT(megno, 4.0) << i;
  }
  try {
    load("chaos_split.toml", base + "method = \"splitting6\"\nstep = 10.0\n");
    ADD_FAILURE() << "a splitting was accepted for megno on an orbit";
  } catch (const newtop::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("method"), std::string::npos) << e.what();
  }
}

TEST(SweepOrbit, QuantitiesThatDoNotApplyAreRefusedNamingTheModel) {
  const struct {
    const char* scenario;
    const char* quantity;
    const char* model;
  } cases[] = {
      {"satellite_700km.toml", "stability", "circular orbit"},
      {"satellite_700km.toml", "equilibria", "circular orbit"},
      {"satellite_700km.toml", "synchronous_odd", "circular orbit"},
      {"orbit_elliptic_pitch.toml", "debra_delp", "elliptic orbit"},
      {"heavy_top.toml", "debra_delp", "fixed point"},
      {"heavy_top.toml", "synchronous_odd", "fixed point"},
  };
  for (const auto& c : cases) {
    const std::string text =
        "scenario = \"" + example(c.scenario) + "\"\nquantities = [\"" + c.quantity + "\"]\n";
    try {
      load("refused.toml", text);
      ADD_FAILURE() << c.quantity << " on " << c.scenario << " was accepted";
    } catch (const newtop::InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(std::string("'") + c.quantity + "' does not apply to the " + c.model),
                std::string::npos)
          << what;
    }
  }
}

}  // namespace
}  // namespace test_sweep_orbit
