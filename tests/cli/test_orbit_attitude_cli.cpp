// Orbit runs through the engine's sampled output and the attitude relative to LVLH: rows exactly
// at the output times, the q0..q3 and roll/pitch/yaw columns against an attitude built here from
// γ and n at every row, and the engineer's 700 km example (issue: pitch period, planar motion).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace test_orbit_attitude_cli {
namespace {

using newtop::test::CliResult;
using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// A CSV as named columns of numbers.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  std::size_t col(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  Vec3 vec(std::size_t row, const std::string& first) const {
    const std::size_t c = col(first);
    return {rows[row][c], rows[row][c + 1], rows[row][c + 2]};
  }
};

Table read_csv(const std::string& text) {
  Table t;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::istringstream h(line);
  for (std::string f; std::getline(h, f, ',');) t.names.push_back(f);
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream r(line);
    for (std::string f; std::getline(r, f, ',');) row.push_back(std::stod(f));
    t.rows.push_back(row);
  }
  return t;
}

CliResult run(const std::string& args) {
  return newtop::test::run_newtop(args, newtop::test::Stderr::separate);
}

std::string scratch(const std::string& name) {
  return newtop::test::scratch_path("newtop_orbit_attitude", name).string();
}

Table simulate(const std::string& example, const std::string& args, const std::string& csv) {
  const std::string path = scratch(csv);
  const CliResult r =
      run("simulate " + newtop::test::example_path(example) + " " + args + " --out " + path);
  EXPECT_EQ(r.code, 0) << r.err;
  return read_csv(newtop::test::read_text(path));
}

// Frame rotations written out here, independently of the library: R1, R2, R3 (Schaub & Junkins'
// M_i, the components in the turned frame).
Mat3 frame_rotation(int axis, double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 m;
  if (axis == 0) m << 1, 0, 0, 0, c, s, 0, -s, c;
  if (axis == 1) m << c, 0, -s, 0, 1, 0, s, 0, c;
  if (axis == 2) m << c, s, 0, -s, c, 0, 0, 0, 1;
  return m;
}

/// C(body←LVLH) from γ and n: columns x_L = n × γ (along-track), y_L = −n, z_L = −γ (nadir).
Mat3 lvlh_from_gamma_normal(const Vec3& gamma, const Vec3& n) {
  Mat3 C;
  C.col(0) = n.cross(gamma);
  C.col(1) = -n;
  C.col(2) = -gamma;
  return C;
}

/// The direction cosine matrix of Euler parameters (q0; q) (Schaub & Junkins eq. 3.97).
Mat3 dcm_of_euler_parameters(double q0, const Vec3& q) {
  Mat3 qx;
  qx << 0, -q[2], q[1], q[2], 0, -q[0], -q[1], q[0], 0;
  return (q0 * q0 - q.dot(q)) * Mat3::Identity() + 2 * q * q.transpose() - 2 * q0 * qx;
}

// Attitudes from columns that round-trip (shortest form) agree with one built from the rounded γ
// and n to a few ulps of the matrix entries (≤ 1): 1e-13 leaves room for the extraction. On top
// of it, C built from γ and n is a rotation only to the row's Casimir error δ (|γ|, |n| and γ·n
// off by δ): the quaternion of the nearest rotation differs from it by at most ~2δ (4δ allowed),
// and the outer angles, atan2 of entries of size |cos θ| (3-2-1) or |sin θ| (3-1-3) off by δ + ε,
// by 4(δ + ε)/|cos θ| (or /|sin θ|) — near gimbal lock (examples/orbit_leo_lagrange.toml pitches
// at 88.5°, cos θ = 0.027) that is the larger term.
constexpr double kAttitudeTolerance = 1e-13;
constexpr double kCasimirFactor = 4.0;
constexpr double kEps = 2.220446049250313e-16;

void expect_attitude_matches_gamma_and_normal(const Table& t, int euler) {
  ASSERT_GT(t.rows.size(), 10u);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const Mat3 C = lvlh_from_gamma_normal(t.vec(i, "gamma1"), t.vec(i, "normal1"));
    const double tol = kAttitudeTolerance + kCasimirFactor * t.rows[i][t.col("casimir_error")];
    const double q0 = t.rows[i][t.col("q0")];
    EXPECT_GE(q0, 0.0);
    const Mat3 Cq = dcm_of_euler_parameters(q0, t.vec(i, "q1"));
    ASSERT_LT((Cq - C).cwiseAbs().maxCoeff(), tol) << "row " << i;
    const double delta = t.rows[i][t.col("casimir_error")] + kEps;
    if (euler == 321) {
      const Vec3 a = t.vec(i, "roll");
      const Mat3 Ce = frame_rotation(0, a[0]) * frame_rotation(1, a[1]) * frame_rotation(2, a[2]);
      const double angles = tol + kCasimirFactor * delta / std::abs(std::cos(a[1]));
      ASSERT_LT((Ce - C).cwiseAbs().maxCoeff(), angles) << "row " << i;
    } else {
      const Vec3 a = t.vec(i, "euler313_phi");
      const Mat3 Ce = frame_rotation(2, a[2]) * frame_rotation(0, a[1]) * frame_rotation(2, a[0]);
      const double angles = tol + kCasimirFactor * delta / std::abs(std::sin(a[1]));
      ASSERT_LT((Ce - C).cwiseAbs().maxCoeff(), angles) << "row " << i;
    }
  }
}

// A general (tumbling, 3-2-1 off every axis) orbit run: both angle sets and the quaternion are
// the attitude of γ and n at every row, on the circular and on the elliptic orbit.
TEST(OrbitAttitudeCli, ColumnsAreTheAttitudeOfGammaAndNormalAtEveryRow) {
  expect_attitude_matches_gamma_and_normal(
      simulate("orbit_leo_lagrange.toml", "--t-end 20000 --euler 321", "leo321.csv"), 321);
  expect_attitude_matches_gamma_and_normal(
      simulate("orbit_leo_lagrange.toml", "--t-end 20000 --euler 313", "leo313.csv"), 313);
  expect_attitude_matches_gamma_and_normal(
      simulate("orbit_elliptic_pitch.toml", "--t-end 20 --euler 321 --method rkf78 --tol 1e-10",
               "ell321.csv"),
      321);
  const Table q = simulate("orbit_leo_lagrange.toml", "--t-end 200 --attitude", "leoq.csv");
  EXPECT_EQ(q.names.back(), "q3");
}

// Output times are rows exactly at t0 + k D, whatever the method (fixed steps land on them, the
// adaptive methods read the dense output), on both orbits; --times gives exactly the list.
TEST(OrbitAttitudeCli, RowsAreExactlyAtTheOutputTimes) {
  struct Case {
    const char* example;
    std::string args;
    double dt;
    std::size_t rows;
  };
  const Case cases[] = {
      {"orbit_leo_lagrange.toml", "--t-end 6000 --dt-out 600", 600, 11},
      {"orbit_leo_lagrange.toml", "--t-end 6000 --dt-out 600 --method rkf78 --tol 1e-10", 600, 11},
      {"orbit_leo_lagrange.toml", "--t-end 6000 --dt-out 600 --method dopri5 --tol 1e-10", 600, 11},
      {"orbit_elliptic_pitch.toml", "--t-end 5 --dt-out 0.5", 0.5, 11},
      {"orbit_elliptic_pitch.toml", "--t-end 5 --dt-out 0.5 --method rkf78 --tol 1e-10", 0.5, 11},
  };
  int n = 0;
  for (const Case& c : cases) {
    const Table t = simulate(c.example, c.args, "rows" + std::to_string(n++) + ".csv");
    ASSERT_EQ(t.rows.size(), c.rows) << c.args;
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
      EXPECT_EQ(t.rows[k][0], c.dt * static_cast<double>(k)) << c.example << " " << c.args;
    }
  }
  const Table l = simulate("orbit_elliptic_pitch.toml", "--times 0.25,1,3.5", "list.csv");
  ASSERT_EQ(l.rows.size(), 3u);
  EXPECT_EQ(l.rows[0][0], 0.25);
  EXPECT_EQ(l.rows[1][0], 1.0);
  EXPECT_EQ(l.rows[2][0], 3.5);
}

// The same sampled state whatever the method: rkf78's dense output at t = 3000 against
// splitting8 landing on it (both far below 1e-9 of the state, which is of order 1).
TEST(OrbitAttitudeCli, DenseOutputAgreesWithFixedStepsLandingOnTheTime) {
  const Table a = simulate("orbit_leo_lagrange.toml",
                           "--t-end 3000 --times 1234.5 --method rkf78 --tol 1e-13", "dense.csv");
  const Table b = simulate("orbit_leo_lagrange.toml",
                           "--t-end 3000 --times 1234.5 --method splitting8 --step 5", "land.csv");
  ASSERT_EQ(a.rows.size(), 1u);
  ASSERT_EQ(b.rows.size(), 1u);
  EXPECT_LT((a.vec(0, "gamma1") - b.vec(0, "gamma1")).norm(), 1e-9);
  EXPECT_LT((a.vec(0, "omega1") - b.vec(0, "omega1")).norm(), 1e-12);  // ω ~ 1e-3 rad/s
}

// The engineer's satellite (examples/satellite_700km.toml): rows at 0, 10, 20, …, roll and yaw
// zero, and the pitch period that of the linearised pitch equation.
TEST(OrbitAttitudeCli, SatelliteExamplePitchLibration) {
  const Table t = simulate("satellite_700km.toml", "--dt-out 10 --euler 321", "p.csv");
  ASSERT_EQ(t.rows.size(), 4001u);
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    ASSERT_EQ(t.rows[k][0], 10.0 * static_cast<double>(k));
  }
  const std::size_t roll = t.col("roll"), pitch = t.col("pitch"), yaw = t.col("yaw");
  EXPECT_NEAR(t.rows[0][pitch], 5 * std::numbers::pi / 180, 1e-15);
  // The bound: a pure pitch start stays planar (it is exact here: n stays along body y).
  constexpr double kPlanar = 1e-12;
  for (const auto& r : t.rows) {
    ASSERT_LE(std::abs(r[roll]), kPlanar);
    ASSERT_LE(std::abs(r[yaw]), kPlanar);
  }
  // The axes of the example, derived from the first row: the pitch axis is the body axis along
  // the orbit normal, roll along-track (n × γ), yaw along the radius.
  const Vec3 inertia(1200, 1500, 900);
  const Vec3 g = t.vec(0, "gamma1"), n = t.vec(0, "normal1");
  Eigen::Index ip, ir, iy;
  n.cwiseAbs().maxCoeff(&ip);
  n.cross(g).cwiseAbs().maxCoeff(&ir);
  g.cwiseAbs().maxCoeff(&iy);
  const double A = inertia[ir], B = inertia[ip], C = inertia[iy];
  EXPECT_EQ(B, 1500.0);
  const double mu = 3.986004418e14, R = 7.078137e6;
  const double rate = std::sqrt(mu / (R * R * R));
  const double linear = 2 * std::numbers::pi / (rate * std::sqrt(3 * (A - C) / B));
  // Upward zero crossings of the pitch, by linear interpolation between rows (10 s apart: the
  // interpolation error of a crossing is below (10 s)² |θ''| / |θ'| ~ 1e-2 s, 1e-6 of a period).
  std::vector<double> up;
  for (std::size_t k = 1; k < t.rows.size(); ++k) {
    const double a = t.rows[k - 1][pitch], b = t.rows[k][pitch];
    if (a < 0 && b >= 0) up.push_back(t.rows[k - 1][0] + 10 * a / (a - b));
  }
  ASSERT_GE(up.size(), 4u);
  const double period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
  // The 0.3 %: the 5° amplitude lengthens the period by (2θ0)²/16 = 0.19 % (the pitch
  // equation is a pendulum in 2θ), the method's error at ω h = 0.008 is far below.
  EXPECT_NEAR(period / linear, 1.0, 0.003) << period << " vs " << linear;
  EXPECT_GT(period / linear, 1.0);  // the amplitude correction has its sign
}

// The scenario's roll_pitch_yaw gives back the same angles in the first row.
TEST(OrbitAttitudeCli, InitialRollPitchYawIsTheFirstRow) {
  const std::string path = scratch("rpy.toml");
  newtop::test::write_text(path,
                           "[body]\ninertia = [1200.0, 1500.0, 900.0]\n[orbit]\nkind = "
                           "\"circular\"\nrate = 1.0\n[initial]\nroll_pitch_yaw = [0.1, -0.2, "
                           "0.3]\n[integrate]\nstep = 0.01\nt_end = 0.1\n");
  const std::string csv = scratch("rpy.csv");
  const CliResult r = run("simulate " + path + " --euler 321 --out " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const Table t = read_csv(newtop::test::read_text(csv));
  EXPECT_LT((t.vec(0, "roll") - Vec3(0.1, -0.2, 0.3)).norm(), 1e-15);
}

// The equilibria list: numbered from 1, each with its LVLH quaternion and roll/pitch/yaw, which
// are the attitude of its γ and n; `stability --equilibrium K` analyses the K-th of them.
TEST(OrbitAttitudeCli, EquilibriaAreNumberedWithTheirLvlhAttitude) {
  const std::string ex = newtop::test::example_path("satellite_700km.toml");
  const CliResult r = run("equilibria " + ex + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["count"], 24);
  int k = 0;
  bool identity = false;  // the Lagrange orientation of the example: body axes along LVLH
  for (const auto& e : j["equilibria"]) {
    EXPECT_EQ(e["number"], ++k);
    const auto g = e["gamma"].get<std::vector<double>>(),
               n = e["normal"].get<std::vector<double>>();
    const Mat3 C = lvlh_from_gamma_normal(Vec3(g[0], g[1], g[2]), Vec3(n[0], n[1], n[2]));
    const auto q = e["lvlh_quaternion"].get<std::vector<double>>();
    const auto a = e["roll_pitch_yaw"].get<std::vector<double>>();
    EXPECT_LT((dcm_of_euler_parameters(q[0], Vec3(q[1], q[2], q[3])) - C).cwiseAbs().maxCoeff(),
              kAttitudeTolerance);
    const Mat3 Ce = frame_rotation(0, a[0]) * frame_rotation(1, a[1]) * frame_rotation(2, a[2]);
    EXPECT_LT((Ce - C).cwiseAbs().maxCoeff(), kAttitudeTolerance);
    if ((C - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-12) {
      identity = true;
      EXPECT_EQ(e["verdict"], "lyapunov");  // B > A > C: the Lagrange region
      const CliResult s =
          run("stability " + ex + " --equilibrium " + std::to_string(k) + " --json");
      ASSERT_EQ(s.code, 0) << s.err;
      EXPECT_EQ(nlohmann::json::parse(s.out)["verdict"], "lyapunov");
    }
  }
  EXPECT_TRUE(identity);
  const CliResult bad = run("stability " + ex + " --equilibrium 25");
  EXPECT_EQ(bad.code, 2);
}

// The summary names the orbital period and the linear modes: DeBra–Delp's pitch 0.7746 and
// roll–yaw 0.5285, 1.545 (in units of the orbit's rate) for (A, B, C) = (1200, 1500, 900):
// k_P = 0.2 (pitch √(3 k_P)), k_R = 1/2, k_Y = 1/3 (σ² + (8/3)σ + 2/3 = 0).
TEST(OrbitAttitudeCli, SummaryNamesPeriodModesAndUnits) {
  const CliResult r =
      run("integrals " + newtop::test::example_path("satellite_700km.toml") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto o = nlohmann::json::parse(r.out)["model"]["orbit"];
  const double rate = o["rate"].get<double>();
  EXPECT_NEAR(o["period"].get<double>(), 2 * std::numbers::pi / rate, 1e-9);
  const auto& m = o["libration_modes"];
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0]["mode"], "pitch");
  EXPECT_NEAR(m[0]["frequency"].get<double>() / rate, std::sqrt(0.6), 1e-12);
  const double b = 8.0 / 3.0, c = 2.0 / 3.0, d = std::sqrt(b * b - 4 * c);
  EXPECT_NEAR(m[1]["frequency"].get<double>() / rate, std::sqrt((b - d) / 2), 1e-12);
  EXPECT_NEAR(m[2]["frequency"].get<double>() / rate, std::sqrt((b + d) / 2), 1e-12);
  EXPECT_NE(nlohmann::json::parse(r.out)["model"]["units"].get<std::string>().find("SI"),
            std::string::npos);
}

// A radius in km with Earth's μ in m³/s²: one warning line, exit 0; --quiet silences it.
TEST(OrbitAttitudeCli, UnitMixIsOneWarningLine) {
  const std::string path = scratch("km.toml");
  newtop::test::write_text(path,
                           "[body]\ninertia = [1200.0, 1500.0, 900.0]\n[orbit]\nkind = "
                           "\"circular\"\nmu = 3.986004418e14\nradius = 7078.137\n[initial]\n"
                           "roll_pitch_yaw = [0.0, 0.0, 0.0]\n");
  const CliResult r = run("integrals " + path);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("newtop: warning: "), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;  // rate and radius
  const CliResult q = run("--quiet integrals " + path);
  EXPECT_EQ(q.code, 0);
  EXPECT_EQ(q.err, "");
  const CliResult ok = run("integrals " + newtop::test::example_path("satellite_700km.toml"));
  EXPECT_EQ(ok.err, "");
}

// libration with the pitch axis along body y (the example's): the axes are relabelled, k is
// (A − C)/B = 0.2 in the example's roll/pitch/yaw moments.
TEST(OrbitAttitudeCli, LibrationTakesAnyBodyAxisAlongTheNormal) {
  const CliResult r = run("libration " + newtop::test::example_path("satellite_700km.toml") +
                          " --resonances 1:1 --iterates 2 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["k"].get<double>(), 0.2, 1e-15);
}

}  // namespace
}  // namespace test_orbit_attitude_cli
