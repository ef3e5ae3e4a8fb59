// The library's checks of a state (newtop/model/state_checks.hpp): every compiled entry point
// refuses a non-unit γ or a non-finite number with the scenario reader's words, so that C++,
// Python and the command line refuse the same input alike.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "newtop/integrate/run.hpp"
#include "newtop/model/state_checks.hpp"
#include "newtop/phase/chaos.hpp"
#include "newtop/phase/section.hpp"

namespace newtop {
namespace test_state_checks {
namespace {

const Model& model() {
  static const Model m(Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.1, 0.05, 0.2)),
                       QuadraticField::coulomb(1.0, 0.7));
  return m;
}

/// The message f throws as InputError ("" when it returns).
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kTwice =
    "gamma: expected a unit vector (|gamma| = 1 to 1e-12), found |gamma| = 2";

TEST(StateChecks, RunMethodRefusesANonUnitGamma) {
  const State x{Vec3(0.1, 0.2, 0.3), 2 * Vec3(0, 0.6, 0.8)};
  EXPECT_EQ(refusal([&] { run_method({"splitting6", 0.01}, model(), x, 0, 1); }), kTwice);
  EXPECT_EQ(refusal([&] { run_method({"dop853", 0.0, 1e-10, 1e-10}, model(), x, 0, 1); }), kTwice);
  EXPECT_EQ(refusal([&] {
              run_method_sampled({"splitting6", 0.01}, model(), x, 0, 1,
                                 OutputTimes::list({0.5}, 0, 1), {}, {});
            }),
            kTwice);
  EXPECT_EQ(
      refusal([&] {
        run_method({"splitting6", 0.01}, model(), with_attitude(x, Quaternion::Identity()), 0, 1);
      }),
      kTwice);
}

TEST(StateChecks, ChaosAndSectionRefuseANonUnitGamma) {
  const State x{Vec3(0.1, 0.2, 0.3), Vec3(0, 0.6, 0.9)};  // |γ| = 1.0816…
  const std::string chaos = refusal([&] {
    phase::chaos(model(), x, {.method = {"splitting6", 0.01}, .t_end = 1});
  });
  EXPECT_EQ(
      chaos.rfind("gamma: expected a unit vector (|gamma| = 1 to 1e-12), found |gamma| = 1.08", 0),
      0u)
      << chaos;
  std::vector<phase::Crossing> out;
  phase::IntegralsDrift drift;
  const phase::SurfaceFunction g(phase::parse_surface("gamma3 = 0"), model().body());
  EXPECT_EQ(
      refusal([&] {
        phase::section_orbit({"splitting6", 0.01}, model(), g, {}, 0, x, 0, 1, {}, out, drift);
      }),
      chaos);
}

TEST(StateChecks, NonFiniteNumbersAndZeroGammaAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refusal([&] {
              validate(State{Vec3(nan, 0, 0), Vec3::UnitZ()});
            }),
            "m: expected finite numbers, found [nan, 0, 0]");
  EXPECT_EQ(refusal([&] { check_unit_gamma(Vec3(0, std::numeric_limits<double>::infinity(), 0)); }),
            "gamma: expected finite numbers, found [0, inf, 0]");
  EXPECT_EQ(refusal([&] { check_unit_gamma(Vec3::Zero()); }),
            "gamma: expected a unit vector, found [0, 0, 0]");
  EXPECT_EQ(refusal([&] { normalized_gamma(Vec3::Zero()); }),
            "gamma: expected a unit vector, found [0, 0, 0]");
}

TEST(StateChecks, AUnitGammaToTheToleranceIsAccepted) {
  // 15 significant digits (what a file holds) pass; the norm is exactly 1 after normalized_gamma.
  EXPECT_EQ(refusal([] { check_unit_gamma(Vec3(0, 0.6, 0.800000000000001)); }), "");
  EXPECT_EQ(refusal([] { check_unit_gamma(Vec3(0, 0.6, 0.80001)); }).substr(0, 24),
            "gamma: expected a unit v");
  const Vec3 g = normalized_gamma(Vec3(0, 3e300, 4e300));  // no overflow
  EXPECT_EQ(g, Vec3(0, 0.6, 0.8).normalized());
  EXPECT_NEAR(g.norm(), 1.0, 1e-16);
  EXPECT_EQ(gamma_norm(Vec3(0, 3e-300, 4e-300)), 5e-300);
}

}  // namespace
}  // namespace test_state_checks
}  // namespace newtop
