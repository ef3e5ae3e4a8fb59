// Orbit scenarios ([orbit]): valid files build the orbit and the state (inertial or relative to the
// orbital frame); every bad input is one line naming the key.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "newtop/io/orbit_scenario.hpp"

namespace newtop::io {
namespace test_orbit_scenario {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

const std::string kCircular = R"(
[body]
inertia = [1.0, 1.6, 2.1]
[orbit]
kind = "circular"
mu = 4.0
radius = 2.0
[initial]
omega = [0.1, 0.2, 0.3]
gamma = [1.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
[integrate]
t_end = 10.0
step = 0.01
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

void expect_error(const std::string& text, std::initializer_list<const char*> parts) {
  SCOPED_TRACE(*parts.begin());
  try {
    parse_orbit_scenario(text, "o.toml");
    ADD_FAILURE() << "accepted bad input";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    for (const char* p : parts) EXPECT_NE(msg.find(p), std::string::npos) << msg << " lacks " << p;
  }
}

TEST(OrbitScenario, CircularFromMuAndRadius) {
  ASSERT_TRUE(is_orbit_scenario_text(kCircular));
  const OrbitScenario s = parse_orbit_scenario(kCircular, "o.toml");
  ASSERT_TRUE(s.circular());
  const auto& c = std::get<CircularOrbit>(s.orbit);
  EXPECT_NEAR(c.rate, std::sqrt(4.0 / 8.0), 2 * kEps);                // ω0 = √(μ/R³)
  EXPECT_NEAR(c.lambda_, 3 * 0.5, 4 * kEps);                          // λ = 3ω0²
  EXPECT_LT((s.initial.m - Vec3(0.1, 0.32, 0.63)).norm(), 4 * kEps);  // m = Iω
  EXPECT_EQ(s.initial.normal, Vec3::UnitZ());
  EXPECT_EQ(*s.integrate.step, 0.01);
}

TEST(OrbitScenario, RateFormAndEllipse) {
  const std::string rate = replace(kCircular, "mu = 4.0\nradius = 2.0", "rate = 0.3");
  EXPECT_EQ(std::get<CircularOrbit>(parse_orbit_scenario(rate, "o.toml").orbit).rate, 0.3);
  const std::string ell =
      replace(kCircular, "kind = \"circular\"\nmu = 4.0\nradius = 2.0",
              "kind = \"elliptic\"\nmu = 1.0\nsemi_major_axis = 1.0\neccentricity = 0.3\n"
              "true_anomaly = 0.5");
  const OrbitScenario s = parse_orbit_scenario(ell, "o.toml");
  const auto& e = std::get<EllipticOrbit>(s.orbit);
  EXPECT_EQ(e.eccentricity, 0.3);
  EXPECT_EQ(e.true_anomaly0, 0.5);
  EXPECT_EQ(s.rate_at_start(), anomaly_rate(e, 0.5));
}

// 3-2-1 angles (yaw ψ about e_n): the body x axis is e_r turned by ψ about e_n, so in body
// components γ = e_r = (cos ψ, −sin ψ, 0) and n = (0, 0, 1); at rest in the orbital frame
// ω = ω0 n. A quaternion of the same rotation gives the same state.
TEST(OrbitScenario, RelativeAttitudeByEulerAnglesAndQuaternion) {
  const double psi = 0.3, w0 = std::sqrt(0.5);
  const std::string base = replace(kCircular,
                                   "omega = [0.1, 0.2, 0.3]\ngamma = [1.0, 0.0, 0.0]\n"
                                   "normal = [0.0, 0.0, 1.0]",
                                   "euler_321 = [0.3, 0.0, 0.0]");
  const OrbitScenario s = parse_orbit_scenario(base, "o.toml");
  EXPECT_LT((s.initial.gamma - Vec3(std::cos(psi), -std::sin(psi), 0)).norm(), 4 * kEps);
  EXPECT_LT((s.initial.normal - Vec3::UnitZ()).norm(), 4 * kEps);
  EXPECT_LT((s.initial.m - 2.1 * w0 * Vec3::UnitZ()).norm(), 8 * kEps);
  const std::string q = replace(base, "euler_321 = [0.3, 0.0, 0.0]",
                                "quaternion = [" + format_number(std::cos(psi / 2)) +
                                    ", 0.0, 0.0, " + format_number(std::sin(psi / 2)) + "]");
  const OrbitScenario sq = parse_orbit_scenario(q, "o.toml");
  EXPECT_LT((sq.initial.gamma - s.initial.gamma).norm(), 4 * kEps);
  // A relative angular velocity is added to ω0 n.
  const std::string wr = replace(base, "euler_321 = [0.3, 0.0, 0.0]",
                                 "euler_321 = [0.3, 0.0, 0.0]\nomega_relative = [0.1, 0.0, 0.0]");
  const OrbitScenario sw = parse_orbit_scenario(wr, "o.toml");
  EXPECT_LT((relative_omega(sw.body, sw.initial, w0) - Vec3(0.1, 0, 0)).norm(), 8 * kEps);
}

TEST(OrbitScenario, BadInputIsOneLineNamingTheKey) {
  expect_error(kCircular + "[field]\ng = 1.0\nR = 2.0\n", {"field", "no [field]"});
  expect_error(replace(kCircular, "inertia = [1.0, 1.6, 2.1]",
                       "inertia = [1.0, 1.6, 2.1]\ncenter_of_mass = [0.1, 0.0, 0.0]"),
               {"center_of_mass", "[0, 0, 0]"});
  expect_error(replace(kCircular, "radius = 2.0", "radius = 2.0\nrate = 0.3"), {"rate", "either"});
  expect_error(replace(kCircular, "kind = \"circular\"", "kind = \"parabolic\""),
               {"kind", "parabolic"});
  expect_error(replace(kCircular, "radius = 2.0", "radius = -2.0"), {"radius", "> 0"});
  expect_error(replace(kCircular, "radius = 2.0", "radius = 2.0\nradiu = 2.0"), {"radiu"});
  const std::string ell = replace(kCircular, "kind = \"circular\"\nmu = 4.0\nradius = 2.0",
                                  "kind = \"elliptic\"\nmu = 1.0\nsemi_major_axis = 1.0\n"
                                  "eccentricity = 1.0");
  expect_error(ell, {"eccentricity", "e < 1", "found 1"});
  expect_error(replace(kCircular, "normal = [0.0, 0.0, 1.0]", "normal = [0.6, 0.0, 0.8]"),
               {"normal", "orthogonal"});
  expect_error(replace(kCircular, "normal = [0.0, 0.0, 1.0]", "normal = [0.0, 0.0, 2.0]"),
               {"normal", "unit"});
  expect_error(replace(kCircular, "normal = [0.0, 0.0, 1.0]\n", ""), {"normal", "missing"});
  const std::string rel = replace(kCircular,
                                  "omega = [0.1, 0.2, 0.3]\ngamma = [1.0, 0.0, 0.0]\n"
                                  "normal = [0.0, 0.0, 1.0]",
                                  "quaternion = [1.0, 0.1, 0.0, 0.0]");
  expect_error(rel, {"quaternion", "unit"});
  EXPECT_NO_THROW(parse_orbit_scenario(
      replace(rel, "[1.0, 0.1, 0.0, 0.0]", "[1.0, 0.1, 0.0, 0.0]\nnormalize = true"), "o.toml"));
  expect_error(replace(rel, "[1.0, 0.1, 0.0, 0.0]", "[1.0, 0.0, 0.0]"), {"quaternion", "4"});
  expect_error(replace(rel, "quaternion = [1.0, 0.1, 0.0, 0.0]",
                       "quaternion = [1.0, 0.0, 0.0, 0.0]\ngamma = [1.0, 0.0, 0.0]"),
               {"exactly one"});
}

}  // namespace
}  // namespace test_orbit_scenario
}  // namespace newtop::io
