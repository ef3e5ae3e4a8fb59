// newtop libration: the pitch state read from the full (m, γ, n) model, the command's JSON and
// CSV against the library, and its bad input (one line, exit 2, nothing written).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "newtop/orbit/libration_report.hpp"
#include "newtop/orbit/spin_orbit.hpp"
#include "orbit_problems.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_libration_cli {
namespace {

TEST(LibrationCli, PitchStateFollowsTheFullModel) {
  // A planar state of the full model, carried by the full equations, read back as (θ, θ′), equals
  // Beletsky's equation carried from the state read at the start (both Fehlberg 7(8), ~1e-11).
  const Vec3 I(0.314, 0.474, 0.542);
  const Body body = Body::from_principal(I, 1.0, Vec3::Zero());
  const EllipticOrbit orbit = EllipticOrbit::from_mean_motion(1.0, 0.2, 0.7);
  const EllipticOrbitModel model(body, orbit);
  const double theta = -0.4, wz = 1.3;
  const OrbitState x0{I.z() * wz * Vec3::UnitZ(), Vec3(std::cos(theta), -std::sin(theta), 0),
                      Vec3::UnitZ()};
  const Vec2 p0 = pitch_state(body, orbit, x0, 0.7, 1e-12);
  EXPECT_NEAR(p0[0], theta, 1e-15);
  EXPECT_NEAR(p0[1], wz / anomaly_rate(orbit, 0.7) - 1, 1e-15);
  const OrbitState x1 = test::reference(model, x0, 0.7, 7.0, 1e-13);
  const Vec2 p1 = pitch_state(body, orbit, x1, 7.0, 1e-9);
  const Vec2 expected = pitch_advance(pitch_problem(body, orbit), p0, 0.7, 7.0);
  EXPECT_NEAR(std::remainder(p1[0] - expected[0], 2 * std::numbers::pi), 0.0, 1e-9);
  EXPECT_NEAR(p1[1], expected[1], 1e-9);
  OrbitState tilted = x0;
  tilted.m.x() = 0.1;
  EXPECT_THROW(pitch_state(body, orbit, tilted, 0.7, 1e-9), InputError);
}

TEST(LibrationCli, JsonAndCsvAgreeWithTheLibrary) {
  const std::string csv = test::scratch_path("newtop_libration", "libration.csv").string();
  const auto r = test::run_newtop("libration " + test::example_path("orbit_spin_orbit.toml") +
                                      " --resonances 1:1,3:2 --spin 3.4:3.6:2 --iterates 30 --json"
                                      " --out " +
                                      csv,
                                  test::Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const PitchProblem p = pitch_problem(0.1, (0.474 - 0.314) / 0.542);
  EXPECT_DOUBLE_EQ(j["k"].get<double>(), p.k);
  ASSERT_EQ(j["resonances"].size(), 2u);
  EXPECT_EQ(j["resonances"][1]["resonance"], "3:2");
  EXPECT_EQ(j["resonances"][1]["half_turns"], 1);
  const auto lib = periodic_solutions(p, resonance(1, 1));
  ASSERT_EQ(j["resonances"][0]["solutions"].size(), lib.size());
  EXPECT_DOUBLE_EQ(j["resonances"][0]["solutions"][0]["dtheta0"].get<double>(), lib[0].dtheta0);
  ASSERT_EQ(j["starts"].size(), 3u);  // the scenario's start and the two --spin starts
  EXPECT_DOUBLE_EQ(j["starts"][0]["theta0"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["starts"][0]["dtheta0"].get<double>(), 0.0);  // at rest in the orbital frame
  EXPECT_NEAR(j["starts"][2]["spin0"].get<double>(), 3.6, 1e-14);
  const SectionOrbit o = periapsis_section(p, 0.0, dtheta_from_spin(0.1, 3.6), 30);
  EXPECT_DOUBLE_EQ(j["starts"][2]["lyapunov"].get<double>(), o.lyapunov);
  std::ifstream in(csv);
  std::string line, last;
  int rows = 0;
  std::getline(in, line);
  EXPECT_EQ(line, "start,orbit,theta,dtheta,spin,lyapunov,chaotic");
  while (std::getline(in, line)) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, 90);
  EXPECT_EQ(last.substr(0, 5), "2,30,");
  EXPECT_NEAR(std::stod(last.substr(5)), o.points.back()[0], 1e-15);
  std::filesystem::remove(csv);
}

// --asymmetric adds each resonance's asymmetric solutions (2-D shooting) and leaves the symmetric
// list as it was; every solution says whether it is symmetric.
TEST(LibrationCli, AsymmetricSolutionsAreAddedBesideTheSymmetricOnes) {
  const auto r = test::run_newtop("libration " + test::example_path("libration_asymmetric.toml") +
                                      " --resonances 1:2 --asymmetric --iterates 2 --json",
                                  test::Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& res = j["resonances"][0];
  const PitchProblem p = pitch_problem(0.1, j["k"].get<double>());
  ASSERT_EQ(res["solutions"].size(), periodic_solutions(p, resonance(1, 2)).size());
  for (const auto& s : res["solutions"]) EXPECT_EQ(s["symmetric"], true);
  ASSERT_GE(res["asymmetric_solutions"].size(), 1u);
  for (const auto& s : res["asymmetric_solutions"]) {
    EXPECT_EQ(s["symmetric"], false);
    EXPECT_GT(s["symmetry_distance"].get<double>(), 0.1);
    EXPECT_LT(s["residual"].get<double>(), 1e-10);
    EXPECT_NEAR(std::abs(s["theta0"].get<double>()), 1.459145, 1e-6);
  }
  const auto plain =
      test::run_newtop("libration " + test::example_path("libration_asymmetric.toml") +
                           " --resonances 1:2 --iterates 2 --json",
                       test::Stderr::separate);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out)["resonances"][0].contains("asymmetric_solutions"));
}

// A circular Kepler orbit is the ellipse e = 0 (ν counted from the start): the same resonances,
// solutions and section, number for number, as the scenario written with kind = "elliptic".
TEST(LibrationCli, CircularOrbitIsTheEllipseOfEccentricityZero) {
  const auto dir = test::scratch_dir("newtop_libration");
  const std::string body = "[body]\ninertia = [0.314, 0.474, 0.542]\n";
  const std::string initial = "[initial]\neuler_321 = [0.3, 0.0, 0.0]\n";
  const std::string circular = (dir / "circular.toml").string();
  const std::string elliptic = (dir / "elliptic.toml").string();
  std::ofstream(circular) << body << "[orbit]\nkind = \"circular\"\nrate = 1.0\n" << initial;
  std::ofstream(elliptic) << body
                          << "[orbit]\nkind = \"elliptic\"\nmu = 1.0\nsemi_major_axis = 1.0\n"
                             "eccentricity = 0.0\n"
                          << initial;
  const std::string args = " --resonances 1:1,2:1 --iterates 20 --json";
  const auto c = test::run_newtop("libration " + circular + args, test::Stderr::separate);
  const auto e = test::run_newtop("libration " + elliptic + args, test::Stderr::separate);
  ASSERT_EQ(c.code, 0) << c.err;
  ASSERT_EQ(e.code, 0) << e.err;
  auto jc = nlohmann::json::parse(c.out), je = nlohmann::json::parse(e.out);
  ASSERT_EQ(jc["resonances"][0]["solutions"].size(), je["resonances"][0]["solutions"].size());
  EXPECT_GE(jc["resonances"][0]["solutions"].size(), 1u);
  jc.erase("scenario");
  je.erase("scenario");
  EXPECT_EQ(jc, je);
  std::filesystem::remove(circular);
  std::filesystem::remove(elliptic);
}

TEST(LibrationCli, BadInputIsOneLineAndExitTwo) {
  const std::string ex = test::example_path("orbit_spin_orbit.toml");
  for (const std::string& args :
       {ex + " --resonances 3-2", ex + " --resonances 1:0", ex + " --spin 2:1:5",
        ex + " --spin 1:2", ex + " --iterates 0", test::example_path("orbit_leo_lagrange.toml")}) {
    const auto r = test::run_newtop("libration " + args, test::Stderr::separate);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(LibrationReport, ChainsTheResonancesAndTheSectionOfThePitchProblem) {
  // The report of a planar start at periapsis (ν0 = 0) is the pitch problem's own pieces: each
  // resonance's periodic solutions and the section of the start and of each spin start, bit for
  // bit; bad input (iterates, a forced circular orbit) is refused before any work.
  const Vec3 I(0.314, 0.474, 0.542);
  const Body body = Body::from_principal(I, 1.0, Vec3::Zero());
  const EllipticOrbit orbit = EllipticOrbit::from_mean_motion(1.0, 0.1, 0.0);
  const double theta = 0.3, wz = 1.1;
  const OrbitState x0{I.z() * wz * Vec3::UnitZ(), Vec3(std::cos(theta), -std::sin(theta), 0),
                      Vec3::UnitZ()};
  LibrationRequest request;
  request.resonances = {resonance(1, 1), resonance(3, 2)};
  request.spin = SpinStarts{1.0, 2.0, 2};
  request.iterates = 20;
  const LibrationReport r = libration_report(body, orbit, x0, request);
  const PitchProblem problem = pitch_problem(body, orbit);
  EXPECT_EQ(r.eccentricity, 0.1);
  EXPECT_EQ(r.k, problem.k);
  ASSERT_EQ(r.resonances.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto direct = periodic_solutions(problem, request.resonances[i]);
    ASSERT_EQ(r.resonances[i].solutions.size(), direct.size());
    for (std::size_t k = 0; k < direct.size(); ++k) {
      EXPECT_EQ(r.resonances[i].solutions[k].dtheta0, direct[k].dtheta0);
    }
    EXPECT_FALSE(r.resonances[i].asymmetric_solutions);
  }
  ASSERT_EQ(r.starts.size(), 3u);
  const Vec2 p0 = pitch_state(body, orbit, x0, 0.0, 1e-9);
  EXPECT_EQ(r.starts[0].lyapunov, periapsis_section(problem, p0[0], p0[1], 20).lyapunov);
  const SectionOrbit s2 = periapsis_section(problem, 0.0, dtheta_from_spin(0.1, 2.0), 20);
  EXPECT_EQ(r.starts[2].lyapunov, s2.lyapunov);
  EXPECT_EQ(r.starts[2].points, s2.points);
  int chaotic = 0;
  for (const SectionOrbit& s : r.starts) chaotic += s.chaotic;
  EXPECT_EQ(r.chaotic_starts, chaotic);
  request.iterates = 0;
  EXPECT_THROW(libration_report(body, orbit, x0, request), InputError);
  request.iterates = 20;
  const CircularOrbit forced{1.0, 2.0};
  EXPECT_THROW(libration_report(body, forced, x0, request), InputError);
}

}  // namespace
}  // namespace test_libration_cli
}  // namespace newtop
