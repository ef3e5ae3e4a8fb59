// newtop continue: the JSON and CSV against the library, and bad input (one line, exit 2, no
// file written).

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "newtop/analysis/lyapunov_family.hpp"
#include "newtop/analysis/rest_family.hpp"
#include "newtop/orbit/orbit_families.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_continue_cli {
namespace {

const std::string kSynchronous = " continue " + test::example_path("continue_synchronous.toml");

TEST(ContinueCli, JsonAndCsvAreTheLibrarysFamily) {
  const std::string csv = test::scratch_path("continue_cli", "family.csv").string();
  const auto r = test::run_newtop(kSynchronous +
                                      " --family resonance --parameter orbit.eccentricity"
                                      " --range 0:0.6 --json --out " +
                                      csv,
                                  test::Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const Family f = resonance_family(eccentricity_path(0.9), 0.0, 0.6, resonance(1, 1), 0.0, 0.0);
  EXPECT_EQ(j["family"], "resonance");
  EXPECT_EQ(j["parameter"], "orbit.eccentricity");
  EXPECT_EQ(j["end"], f.end);
  ASSERT_EQ(j["points"].size(), f.points.size());
  ASSERT_EQ(j["events"].size(), f.events.size());
  for (std::size_t i = 0; i < f.events.size(); ++i) {
    EXPECT_EQ(j["events"][i]["type"], to_string(f.events[i].type));
    EXPECT_DOUBLE_EQ(j["events"][i]["value"].get<double>(), f.events[i].value);
    EXPECT_DOUBLE_EQ(j["events"][i]["solution"]["dtheta0"].get<double>(),
                     f.events[i].point.values[1]);
    EXPECT_EQ(j["events"][i]["multipliers"].size(), 2u);
  }
  const auto& last = j["points"].back();
  EXPECT_DOUBLE_EQ(last["parameter"].get<double>(), f.points.back().parameter);
  EXPECT_EQ(last["stability"], f.points.back().stability);
  std::istringstream in(test::read_text(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "parameter,theta0,dtheta0,period,multiplier1_re,multiplier1_im,multiplier2_re,"
            "multiplier2_im,stability");
  std::size_t rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, f.points.size());
}

TEST(ContinueCli, AMomentAsTheParameterIsTheInertiaPath) {
  // body.inertia[1] = B with A = 0.1, C = 1: k = B − 0.1, so B from 0.9 to 1.0 is k from 0.8 to
  // 0.9 at e = 0 (the scenario's): the same family as the path in k.
  const auto r = test::run_newtop(kSynchronous +
                                  " --family resonance --parameter body.inertia[1] --range 0.9:1.0"
                                  " --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const Family f = resonance_family(inertia_path(Vec3(0.1, 1.0, 1.0), 1, 0.0), 0.9, 1.0,
                                    resonance(1, 1), 0.0, 0.0);
  ASSERT_EQ(j["points"].size(), f.points.size());
  EXPECT_DOUBLE_EQ(j["points"].back()["values"]["dtheta0"].get<double>(),
                   f.points.back().values[1]);
}

TEST(ContinueCli, SecondKeyGivesTheEventsCurves) {
  // The fold of k = 0.9 continued in A (k = 1 − A) from 0.1 to 0.05: the curve's end is the
  // library's.
  const auto r =
      test::run_newtop(kSynchronous +
                       " --family resonance --parameter orbit.eccentricity --range "
                       "0.3:0.6 --second body.inertia[0] --second-range 0.05:0.1 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["boundaries"].size(), j["events"].size());
  const Family f = resonance_family(eccentricity_path(0.9), 0.3, 0.6, resonance(1, 1), 0.0, 0.0);
  const auto& fold = j["boundaries"].back();
  ASSERT_EQ(fold["type"], "fold");
  const Family curve =
      resonance_boundary(pitch_plane_path(Vec3(0.1, 1.0, 1.0), 0.0, kEccentricityKey, 0),
                         f.events.back(), 0.1, 0.05, resonance(1, 1), 0.0);
  EXPECT_EQ(fold["points"].size(), curve.points.size());
  EXPECT_DOUBLE_EQ(fold["points"][0]["second"].get<double>(), 0.05);  // ordered along C:D
  EXPECT_DOUBLE_EQ(fold["points"][0]["parameter"].get<double>(), curve.points.back().values[2]);
}

TEST(ContinueCli, SwitchContinuesTheBranchFromEachFlip) {
  // k = 0.9, e from 0.25 to 0.35: the two flips (0.2755, 0.3287), each with its period-doubled
  // branch, the library's; the CSV's rows are the family's (branch 0) and the branches'.
  const std::string csv = test::scratch_path("continue_cli", "switch.csv").string();
  const auto r = test::run_newtop(kSynchronous +
                                      " --family resonance --parameter orbit.eccentricity"
                                      " --range 0.25:0.35 --switch --json --out " +
                                      csv,
                                  test::Stderr::separate);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const PitchPath path = eccentricity_path(0.9);
  const Family f = resonance_family(path, 0.25, 0.35, resonance(1, 1), 0.0, 0.0);
  ASSERT_EQ(f.events.size(), 2u);
  ASSERT_EQ(j["branches"].size(), 2u);
  std::size_t rows = f.points.size();
  for (std::size_t i = 0; i < 2; ++i) {
    const Family b = resonance_branch(path, f.events[i], 0.25, 0.35, resonance(1, 1), 0.0);
    const auto& jb = j["branches"][i];
    EXPECT_EQ(jb["event"], i);
    EXPECT_EQ(jb["type"], "flip");
    EXPECT_EQ(jb["end"], b.end);
    ASSERT_EQ(jb["points"].size(), b.points.size());
    EXPECT_EQ(jb["events"].size(), b.events.size());
    EXPECT_DOUBLE_EQ(jb["points"].back()["values"]["dtheta0"].get<double>(),
                     b.points.back().values[1]);
    EXPECT_DOUBLE_EQ(jb["points"][0]["period"].get<double>(), 4 * std::numbers::pi);
    rows += b.points.size();
  }
  std::istringstream in(test::read_text(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("branch,parameter,theta0,dtheta0,period,", 0), 0u) << line;
  std::size_t n = 0;
  while (std::getline(in, line)) ++n;
  EXPECT_EQ(n, rows);
}

TEST(ContinueCli, EquilibriumAtRestOfAFixedPointScenario) {
  const auto r = test::run_newtop(" continue " + test::example_path("continue_rest.toml") +
                                  " --family equilibrium --parameter body.center_of_mass[0]"
                                  " --range 0.1:2 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const QuadraticModel m{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.1, 0, 0)),
                         QuadraticField{1.0, 1.0}};
  const Family f =
      rest_family(quadratic_path(m, "body.center_of_mass[0]"), Vec3::UnitX(), 0.1, 2.0);
  ASSERT_EQ(j["points"].size(), f.points.size());
  ASSERT_EQ(j["events"].size(), f.events.size());
  for (std::size_t i = 0; i < f.events.size(); ++i) {
    EXPECT_EQ(j["events"][i]["type"], to_string(f.events[i].type));
    EXPECT_DOUBLE_EQ(j["events"][i]["value"].get<double>(), f.events[i].value);
    EXPECT_DOUBLE_EQ(j["events"][i]["solution"]["kappa"].get<double>(),
                     f.events[i].point.values[3]);
  }
  EXPECT_EQ(j["points"][0]["multipliers"].size(), 4u);
  EXPECT_EQ(j["points"][0]["stability"], "minimum");
}

TEST(ContinueCli, PeriodicIsTheLyapunovFamilyOfTheEquilibrium) {
  const auto r = test::run_newtop(" continue " + test::example_path("continue_rest.toml") +
                                  " --family periodic --parameter energy --range 1e-4:0.3"
                                  " --mode 2 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const QuadraticModel m{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.1, 0, 0)),
                         QuadraticField{1.0, 1.0}};
  const Family f = lyapunov_family(m, Vec3::UnitX(), 1, 1e-4, 0.3);
  ASSERT_EQ(j["points"].size(), f.points.size());
  ASSERT_EQ(j["events"].size(), f.events.size());
  EXPECT_EQ(j["points"][0]["multipliers"].size(), 6u);
  EXPECT_DOUBLE_EQ(j["points"].back()["period"].get<double>(), f.points.back().period);
  EXPECT_DOUBLE_EQ(j["points"].back()["values"]["m_z"].get<double>(), f.points.back().values[2]);
}

TEST(ContinueCli, BadInputIsOneLineAndWritesNothing) {
  const std::string csv = test::scratch_path("continue_cli", "bad.csv").string();
  const std::string res = " --family resonance --parameter orbit.eccentricity";
  const std::string beletsky = " continue " + test::example_path("stability_beletsky.toml");
  const std::string rest =
      " continue " + test::example_path("continue_rest.toml") + " --family equilibrium";
  const std::string periodic = " continue " + test::example_path("continue_rest.toml") +
                               " --family periodic --parameter energy";
  for (const std::string& args : {
           kSynchronous + res + " --range 0.2:0.2",
           kSynchronous + res + " --range 0:x",
           kSynchronous + res + " --range 0:nan",
           kSynchronous + res + " --range 0:1.2",             // e ≥ 1
           kSynchronous + res + " --range 0:0.5 --line 0.3",  // not a reversibility line
           kSynchronous + res + " --range 0:0.5 --resonance 1:0",
           kSynchronous + res + " --range 0:0.5 --second body.inertia[1]",
           kSynchronous + res + " --range 0:0.5 --second orbit.eccentricity --second-range 0:1",
           kSynchronous + res + " --range 0:0.5 --second body.inertia[0] --second-range 0.2:0.3",
           kSynchronous + res + " --range 0:0.5 --second body.inertia[0] --second-range 0.05:3",
           kSynchronous + res + " --range 0:0.5 --second stability.omega --second-range 0:1",
           kSynchronous + " --family resonance --parameter orbit.semi_major_axis --range 1:2",
           kSynchronous + " --family resonance --parameter body.inertia[0] --range 0.1:3",
           kSynchronous + " --family bogus --parameter orbit.eccentricity --range 0:0.5",
           beletsky + " --family periodic --parameter stability.omega --range 0.1:3",
           beletsky + " --family periodic --parameter energy --range 0.1:3",  // not at rest
           rest + " --parameter energy --range 0.1:0.2",  // periodic's key for equilibrium
           periodic + " --range 0:0.2",                   // energies above the equilibrium's
           periodic + " --range 0.1:0.2 --mode 3",
           periodic + " --range 0.1:0.2 --mode 0",
           periodic + " --range 0.1:0.2 --mode x",
           periodic + " --range 0.1:0.2 --switch",
           rest + " --parameter field.g --range 1:2 --mode 2",
           beletsky + " --family rotation --parameter stability.omega --range 0.1:3 --line 0",
           beletsky +
               " --family rotation --parameter stability.omega --range 0.1:3 --resonance 1:1",
           beletsky + " --family rotation --parameter body.inertia[0] --range 0.1:3",
           beletsky + " --family rotation --parameter stability.omega --range 0.1:3 --second "
                      "body.inertia[0] --second-range 0.9:1.1",
           beletsky + " --family equilibrium --parameter body.inertia[0] --range 0.9:1.1",
           beletsky + " --family rotation --parameter stability.omega --range 0.1:3 --switch",
           rest + " --parameter field.bogus --range 1:2",
           rest + " --parameter body.inertia[0] --range 1:5",  // no body at 5
           rest + " --parameter field.g --range 1:inf",
           rest + " --parameter field.g --range 1:2 --line 0",
           beletsky + " --family equilibrium --parameter field.g --range 1:2",  // not at rest
           kSynchronous + res +
               " --range 0:0.5 --switch --second body.inertia[0] --second-range 0.05:0.5",
       }) {
    const auto r = test::run_newtop(args + " --out " + csv, test::Stderr::separate);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(csv)) << args;
  }
}

}  // namespace
}  // namespace test_continue_cli
}  // namespace newtop
