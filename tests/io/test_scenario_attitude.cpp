// The attitude keys of [initial] (docs/scenario.md): quaternion = [w, x, y, z] (scalar first, body
// → inertial), rotation_matrix (3×3, row-major, orthonormal to 1e-6), euler_321 = [ψ, θ, φ] and
// euler_313 = [φ, θ, ψ] (radians). Each form of one rotation gives the same attitude; at most one
// may be given; a quaternion within 1e-6 of unit norm is normalised, one further off is refused
// unless normalize = true.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "newtop/io/scenario.hpp"
#include "reject.hpp"

namespace newtop::io {
namespace test_scenario_attitude {
namespace {

using newtop::io::test::expect_rejected;

constexpr double kEps = std::numeric_limits<double>::epsilon();

const std::string kHead =
    "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\ncenter_of_mass = [0.1, 0.0, 0.3]\n"
    "[field]\ng = 1\nlambda = 3\n"
    "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n";
const std::string kTail = "[integrate]\nt_end = 1.0\nstep = 0.01\n";

Scenario with_initial(const std::string& keys, const std::string& head = kHead) {
  return parse_scenario(head + keys + kTail, "s.toml");
}

// One rotation in every form: R = R_z(0.7) R_y(−0.4) R_x(2.1) (3-2-1), written out as a matrix,
// as its quaternion and as its 3-1-3 angles, each computed here independently of the reader.
TEST(ScenarioAttitude, EveryFormGivesTheSameAttitude) {
  const Quaternion q = from_euler_321(Vec3(0.7, -0.4, 2.1));
  const Mat3 R = q.toRotationMatrix();
  const Vec3 a313 = euler_313(q);
  char buf[512];
  std::snprintf(buf, sizeof buf, "quaternion = [%.17g, %.17g, %.17g, %.17g]\n", q.w(), q.x(), q.y(),
                q.z());
  const std::string by_quaternion = buf;
  std::snprintf(buf, sizeof buf,
                "rotation_matrix = [[%.17g, %.17g, %.17g], [%.17g, %.17g, %.17g], [%.17g, %.17g, "
                "%.17g]]\n",
                R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
  const std::string by_matrix = buf;
  std::snprintf(buf, sizeof buf, "euler_313 = [%.17g, %.17g, %.17g]\n", a313[0], a313[1], a313[2]);
  const std::string by_313 = buf;
  for (const std::string& keys :
       {by_quaternion, by_matrix, by_313, std::string("euler_321 = [0.7, -0.4, 2.1]\n")}) {
    const Scenario s = with_initial(keys);
    ASSERT_TRUE(s.attitude.has_value()) << keys;
    EXPECT_LE(rotation_distance(*s.attitude, q), 8 * kEps) << keys;
    EXPECT_LE(std::abs(s.attitude->norm() - 1.0), 2 * kEps) << keys;
  }
  EXPECT_FALSE(with_initial("").attitude.has_value());
}

// With a full inertia tensor the state is held in the principal axes P; the attitude read is that
// of the file's frame and is stored for the principal axes (R P), so that the fixed direction
// e = R γ is the same computed either way.
TEST(ScenarioAttitude, PrincipalAxesKeepTheInertialDirection) {
  const std::string head =
      "[body]\ninertia_tensor = [[2.0, 0.3, 0.1], [0.3, 1.5, -0.2], [0.1, -0.2, 1.2]]\n"
      "[field]\ng = 1\nlambda = 3\n"
      "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n";
  const Scenario s = with_initial("euler_321 = [0.7, -0.4, 2.1]\n", head);
  ASSERT_TRUE(s.attitude.has_value());
  const Vec3 e_file = from_euler_321(Vec3(0.7, -0.4, 2.1)) * Vec3(0.48, -0.6, 0.64);
  const Vec3 e_run = inertial_direction(with_attitude(s.initial, *s.attitude));
  EXPECT_LE((e_file - e_run).norm(), 16 * kEps);
  EXPECT_GT((s.initial.gamma - Vec3(0.48, -0.6, 0.64)).norm(), 1e-3);  // the frames do differ
}

TEST(ScenarioAttitude, NearlyUnitQuaternionIsNormalised) {
  const Scenario s = with_initial("quaternion = [1.0000005, 0, 0, 0]\n");
  EXPECT_EQ(s.attitude->coeffs(), Quaternion::Identity().coeffs());
  const Scenario n = with_initial("quaternion = [2, 0, 0, 0]\nnormalize = true\n");
  EXPECT_EQ(n.attitude->coeffs(), Quaternion::Identity().coeffs());
}

TEST(ScenarioAttitude, BadInput) {
  expect_rejected("q_norm", kHead + "quaternion = [1.1, 0, 0, 0]\n" + kTail,
                  ":11:14: [initial] quaternion: expected a unit quaternion (|q| = 1 to 1e-06), "
                  "found |q| = 1.1; add normalize = true to [initial] to rescale it");
  expect_rejected("q_zero", kHead + "quaternion = [0, 0, 0, 0]\n" + kTail,
                  ":11:14: [initial] quaternion: expected a unit quaternion, found [0, 0, 0, 0]");
  expect_rejected(
      "q_length", kHead + "quaternion = [1, 0, 0]\n" + kTail,
      ":11:14: [initial] quaternion: expected an array of 4 numbers, found an array of 3");
  expect_rejected("two_keys",
                  kHead + "quaternion = [1, 0, 0, 0]\neuler_321 = [0.1, 0.2, 0.3]\n" + kTail,
                  ":12:13: [initial] euler_321: expected one attitude key (quaternion, "
                  "rotation_matrix, euler_321 or euler_313), found quaternion and euler_321");
  expect_rejected("matrix_skew",
                  kHead + "rotation_matrix = [[1, 0.01, 0], [0, 1, 0], [0, 0, 1]]\n" + kTail,
                  ":11:19: [initial] rotation_matrix: expected a rotation matrix (max |R^T R - I| "
                  "<= 1e-06), found max |R^T R - I| = 0.01");
  expect_rejected("matrix_reflection",
                  kHead + "rotation_matrix = [[1, 0, 0], [0, 1, 0], [0, 0, -1]]\n" + kTail,
                  ":11:19: [initial] rotation_matrix: expected a rotation matrix (det R = +1), "
                  "found det R = -1 (a reflection)");
  expect_rejected(
      "euler_length", kHead + "euler_313 = [0.1, 0.2]\n" + kTail,
      ":11:13: [initial] euler_313: expected an array of 3 numbers, found an array of 2");
  expect_rejected("euler_text", kHead + "euler_321 = [0.1, \"x\", 0.3]\n" + kTail,
                  ":11:19: [initial] euler_321: element 2: expected a number, found the string "
                  "\"x\"");
}

}  // namespace
}  // namespace test_scenario_attitude
}  // namespace newtop::io
