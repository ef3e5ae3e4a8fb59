// `newtop simulate` with an attitude in [initial]: final.quaternion in the JSON, q0..q3 (and the
// Euler angles asked for) in the CSV, and the fixed direction e = R γ constant along the rows.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "newtop/model/attitude.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_attitude_cli {
namespace {

namespace fs = std::filesystem;

constexpr double kEps = std::numeric_limits<double>::epsilon();

test::CliResult run(const std::string& args) {
  return test::run_newtop(args, test::Stderr::separate);
}

fs::path scratch(const std::string& name) { return newtop::test::scratch_path("newtop_att", name); }

fs::path scenario(const std::string& attitude, const std::string& integrate) {
  const fs::path p = scratch("attitude.toml");
  std::ofstream(p) << "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\n"
                      "center_of_mass = [0.1, 0.0, 0.3]\n[field]\ng = 1\nlambda = 3\n"
                      "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n"
                   << attitude << "[integrate]\nt_end = 5.0\n"
                   << integrate;
  return p;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return static_cast<int>(i);
    }
    return -1;
  }
};

Csv read_csv(const fs::path& p) {
  std::ifstream in(p);
  Csv c;
  std::string line, cell;
  std::getline(in, line);
  std::stringstream h(line);
  while (std::getline(h, cell, ',')) c.header.push_back(cell);
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::vector<double> row;
    while (std::getline(s, cell, ',')) row.push_back(std::stod(cell));
    c.rows.push_back(row);
  }
  return c;
}

TEST(AttitudeCli, JsonAndCsvCarryTheAttitude) {
  for (const std::string integrate : {"step = 0.01\n", "tol = 1e-10\n"}) {
    const fs::path toml = scenario("euler_321 = [0.7, -0.4, 2.1]\n", integrate);
    const fs::path csv = scratch("attitude.csv");
    const test::CliResult r =
        run("simulate " + toml.string() + " --json --euler 313 --out " + csv.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["final"]["quaternion"].size(), 4u);
    const Csv c = read_csv(csv);
    const int q0 = c.column("q0"), g1 = c.column("gamma1"), a0 = c.column("euler313_phi");
    ASSERT_GE(q0, 0);
    ASSERT_GE(a0, 0);
    EXPECT_EQ(c.column("q3"), q0 + 3);
    EXPECT_EQ(c.column("euler313_psi"), a0 + 2);
    ASSERT_GT(c.rows.size(), 10u);
    // The fixed direction from the first row, against every row: γ = Rᵀ e to the run's accuracy
    // (round-off for the splitting, the tolerance times the steps for rkf78), far below the 1e-6
    // that would show an attitude turning about the wrong axis for a single step.
    auto row_state = [&](const std::vector<double>& row) {
      OrientedState x;
      x.gamma = Vec3(row[g1], row[g1 + 1], row[g1 + 2]);
      x.q = Quaternion(row[q0], row[q0 + 1], row[q0 + 2], row[q0 + 3]);
      return x;
    };
    const Vec3 e = inertial_direction(row_state(c.rows.front()));
    double worst = 0.0, worst_euler = 0.0;
    for (const auto& row : c.rows) {
      const OrientedState x = row_state(row);
      worst = std::max(worst, (x.gamma - x.q.conjugate() * e).norm());
      const Quaternion from_angles = from_euler_313(Vec3(row[a0], row[a0 + 1], row[a0 + 2]));
      worst_euler = std::max(worst_euler, rotation_distance(from_angles, x.q));
    }
    EXPECT_LE(worst, 1e-6) << integrate;
    EXPECT_LE(worst_euler, 64 * kEps) << integrate;
    // The last row is the final state of the JSON.
    const auto& last = c.rows.back();
    for (int i = 0; i < 4; ++i) EXPECT_EQ(last[q0 + i], j["final"]["quaternion"][i].get<double>());
    EXPECT_LE(j["attitude"]["max_renormalization"].get<double>(), 1e-9);
  }
}

TEST(AttitudeCli, WithoutAnAttitudeNothingChanges) {
  const fs::path toml = scenario("", "step = 0.01\n");
  const fs::path csv = scratch("plain.csv");
  const test::CliResult r = run("simulate " + toml.string() + " --json --out " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["final"].contains("quaternion"));
  EXPECT_FALSE(j.contains("attitude"));
  EXPECT_EQ(read_csv(csv).column("q0"), -1);
  const test::CliResult e = run("simulate " + toml.string() + " --euler 321");
  EXPECT_EQ(e.code, 2);
  EXPECT_EQ(e.err,
            "newtop: error: --euler: expected a scenario with an attitude ([initial] "
            "quaternion, rotation_matrix, euler_321 or euler_313), found none in " +
                toml.string() + "\n");
  EXPECT_EQ(e.out, "");
}

}  // namespace
}  // namespace test_attitude_cli
}  // namespace newtop
