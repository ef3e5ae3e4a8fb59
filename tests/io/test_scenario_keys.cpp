// Keys of a scenario file, each form exactly as documented (docs/scenario.md): conflicting keys
// are refused naming both, a misspelt key or section is named with the closest allowed name before
// anything else is checked, and `kind` is optional where the keys say which model it is. Each bad
// input is checked with its exact bytes through the library and the program.

#include <gtest/gtest.h>

#include <string>

#include "newtop/exact/mass_models.hpp"
#include "newtop/io/scenario.hpp"
#include "reject.hpp"

namespace newtop::io {
namespace test_scenario_keys {
namespace {

using test::expect_rejected;

const std::string kBody =
    "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\ncenter_of_mass = [0.1, 0.0, 0.3]\n";
const std::string kInitial =
    "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n"
    "[integrate]\nt_end = 1.0\nstep = 0.01\n";

std::string with_field(const std::string& field) { return kBody + "[field]\n" + field + kInitial; }

TEST(ScenarioKeys, BrunFieldRefusesG) {
  expect_rejected("brun_g", with_field("kind = \"brun\"\nN = 0.8\ng = 5\n"),
                  ":8:5: [field] g: conflicts with kind = \"brun\" (which takes N, plane_offset)");
}

TEST(ScenarioKeys, UniformFieldRefusesLambda) {
  expect_rejected("uniform_lambda", with_field("kind = \"uniform\"\ng = 9.81\nlambda = 3\n"),
                  ":8:10: [field] lambda: conflicts with kind = \"uniform\" (which takes g)");
}

TEST(ScenarioKeys, BrunFieldRefusesR) {
  expect_rejected("brun_R", with_field("kind = \"brun\"\nN = 0.8\nR = 5\n"),
                  ":8:5: [field] R: conflicts with kind = \"brun\" (which takes N, plane_offset)");
}

TEST(ScenarioKeys, NewtonianFieldRefusesNegativeGAndLambda) {
  expect_rejected("newtonian_g", with_field("kind = \"newtonian\"\ng = -1\nlambda = 3\n"),
                  ":7:5: [field] g: kind = \"newtonian\" needs g >= 0 (an attracting centre), "
                  "found g = -1; kind = \"coulomb\" allows either sign");
  expect_rejected("newtonian_lambda", with_field("kind = \"newtonian\"\ng = 1\nlambda = -3\n"),
                  ":8:10: [field] lambda: kind = \"newtonian\" needs lambda >= 0, found lambda = "
                  "-3; kind = \"coulomb\" allows either sign");
  expect_rejected("newtonian_g_R", with_field("kind = \"newtonian\"\ng = -1\nR = 3\n"),
                  ":7:5: [field] g: kind = \"newtonian\" needs g >= 0 (an attracting centre), "
                  "found g = -1; kind = \"coulomb\" allows either sign");
  // The same numbers as a Coulomb centre are a valid field.
  EXPECT_NO_THROW(
      parse_scenario(with_field("kind = \"coulomb\"\ng = -1\nlambda = -3\n"), "s.toml"));
}

// g multiplies r0 only (V = M g r0·γ + ½ λ γ·Iγ): with r0 = 0 it cannot matter, and lambda alone
// is the field with g = 0, the same model as g = 0 written out; with r0 ≠ 0 g is still required.
TEST(ScenarioKeys, LambdaAloneWhereGCannotMatter) {
  const std::string body0 =
      "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\ncenter_of_mass = [0.0, 0.0, 0.0]\n";
  const Scenario alone = parse_scenario(body0 + "[field]\nlambda = 3\n" + kInitial, "s.toml");
  const Scenario written =
      parse_scenario(body0 + "[field]\ng = 0\nlambda = 3\n" + kInitial, "s.toml");
  EXPECT_EQ(alone.model.quadratic().field.g, 0.0);
  EXPECT_EQ(alone.model.quadratic().field.lambda_, 3.0);
  EXPECT_EQ(alone.model.quadratic().field.g, written.model.quadratic().field.g);
  EXPECT_EQ(alone.model.quadratic().field.lambda_, written.model.quadratic().field.lambda_);
  expect_rejected("lambda_without_g", with_field("lambda = 3\n"),
                  ":5:1: [field] g: missing: lambda needs g (where the centre of mass r0 is not "
                  "0)");
}

TEST(ScenarioKeys, StepAndTolTogether) {
  expect_rejected("step_tol", with_field("g = 1\nlambda = 3\n") + "tol = 1e-9\n",
                  ":14:7: [integrate] tol: conflicts with step: give step (fixed-step methods) or "
                  "tol (adaptive methods)");
}

// The rest of the audit: every key that one form of a section would ignore.
TEST(ScenarioKeys, EveryIgnoredKeyIsAConflict) {
  expect_rejected("brun_N_and_g", with_field("N = 0.8\ng = 1\nlambda = 3\n"),
                  ":7:5: [field] g: conflicts with N (Brun's field, kind = \"brun\") (which takes "
                  "N, plane_offset)");
  expect_rejected("exact_order",
                  "[mass_model]\nsemi_axes = [1.0, 2.0, 3.0]\nmass = 1.0\n[field]\n"
                  "kind = \"exact\"\nmu = 1\nR = 10\norder = 3\n" +
                      kInitial,
                  ":8:9: [field] order: conflicts with kind = \"exact\" (which takes mu, R)");
  expect_rejected("g_lambda_R", with_field("g = 1\nlambda = 3\nR = 2\n"),
                  ":8:5: [field] R: conflicts with lambda: give (g, lambda), (g, R) or (mu, R)");
  expect_rejected("g_mu", with_field("g = 1\nmu = 3\nR = 2\n"),
                  ":7:6: [field] mu: conflicts with g: give (g, lambda), (g, R) or (mu, R)");
  expect_rejected("rk4_tol",
                  kBody +
                      "[field]\ng = 1\nlambda = 3\n[initial]\nomega = [0.5, 1.1, -0.4]\n"
                      "gamma = [0.48, -0.6, 0.64]\n[integrate]\nmethod = \"rk4\"\ntol = 1e-9\n",
                  ":13:7: [integrate] tol: conflicts with method = \"rk4\", which takes a step "
                  "(step)");
  expect_rejected("dopri5_step",
                  kBody +
                      "[field]\ng = 1\nlambda = 3\n[initial]\nomega = [0.5, 1.1, -0.4]\n"
                      "gamma = [0.48, -0.6, 0.64]\n[integrate]\nmethod = \"dopri5\"\nstep = 0.1\n",
                  ":13:8: [integrate] step: conflicts with method = \"dopri5\", which takes a "
                  "tolerance (tol)");
  expect_rejected(
      "ellipsoid_dimensions",
      "[mass_model]\nkind = \"ellipsoid\"\nsemi_axes = [1.0, 2.0, 3.0]\n"
      "dimensions = [1.0, 1.0, 1.0]\nmass = 1.0\n[field]\nmu = 1\nR = 10\n" +
          kInitial,
      ":4:14: [mass_model] dimensions: conflicts with kind = \"ellipsoid\" (which takes "
      "semi_axes, density, mass, center)");
  expect_rejected("points_and_semi_axes",
                  "[mass_model]\npoints = [[1, 1, 0, 0], [1, -1, 0, 0]]\n"
                  "semi_axes = [1.0, 2.0, 3.0]\n[field]\nmu = 1\nR = 10\n" +
                      kInitial,
                  ":3:13: [mass_model] semi_axes: conflicts with points (kind = \"points\") (which "
                  "takes points, file)");
  expect_rejected("density_and_mass",
                  "[mass_model]\nkind = \"box\"\ndimensions = [1.0, 2.0, 3.0]\ndensity = 2.0\n"
                  "mass = 12.0\n[field]\nmu = 1\nR = 10\n" +
                      kInitial,
                  ":5:8: [mass_model] mass: conflicts with density: give one of them");
  expect_rejected("inertia_and_tensor",
                  "[body]\ninertia = [1.0, 1.5, 2.2]\n"
                  "inertia_tensor = [[1, 0, 0], [0, 1.5, 0], [0, 0, 2.2]]\n[field]\ng = 1\n"
                  "lambda = 3\n" +
                      kInitial,
                  ":3:18: [body] inertia_tensor: conflicts with inertia: give one of them");
}

TEST(ScenarioKeys, MisspeltKeyIsNamedBeforeWhatItDisplaced) {
  expect_rejected("inertai",
                  "[body]\ninertai = [1.0, 1.5, 2.2]\n[field]\ng = 1\nlambda = 3\n" + kInitial,
                  ":2:1: unknown key 'inertai' in [body] — did you mean 'inertia'?");
  expect_rejected("feild", kBody + "[feild]\ng = 1\nlambda = 3\n" + kInitial,
                  ":5:2: unknown section [feild] — did you mean [field]?");
  // A typo in a later section is still reported before an error of an earlier one.
  expect_rejected("typo_after_conflict",
                  with_field("kind = \"brun\"\nN = 1\ng = 1\n") + "max_step = 10\n",
                  ":15:1: unknown key 'max_step' in [integrate] — did you mean 'max_steps'?");
  expect_rejected("far_from_any", kBody + "[field]\ng = 1\nlambda = 3\nzeta = 1\n" + kInitial,
                  ":8:1: unknown key 'zeta' in [field] (expected one of kind, g, lambda, mu, R, "
                  "N, plane_offset, order)");
}

TEST(ScenarioKeys, NoStepNoToleranceNoMethod) {
  const std::string text = kBody +
                           "[field]\ng = 1\nlambda = 3\n[initial]\nomega = [0.5, 1.1, -0.4]\n"
                           "gamma = [0.48, -0.6, 0.64]\n[integrate]\nt_end = 1.0\n";
  const std::string tail =
      ": [integrate]: a step or a tolerance is needed: give --step (fixed step, splitting6) or "
      "--tol (adaptive, taylor), or step or tol in [integrate]";
  try {
    resolve_method(parse_scenario(text, "s.toml"), {});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "s.toml" + tail);
  }
  const std::string path = test::write_file("no_step.toml", text);
  const auto r = newtop::test::run_newtop("simulate " + path, newtop::test::Stderr::separate);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "newtop: error: " + path + tail + "\n");
  // A method named without what it needs keeps the method's own message.
  IntegrateOverrides o;
  o.method = "dopri5";
  try {
    resolve_method(parse_scenario(text, "s.toml"), o);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.toml: tol: method dopri5 is adaptive and needs a tolerance: give --tol or "
              "[integrate] tol");
  }
}

TEST(ScenarioKeys, UnknownSubcommandAndOptionNameTheClosest) {
  const auto r = newtop::test::run_newtop("simulat x.toml", newtop::test::Stderr::separate);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "newtop: error: unknown subcommand 'simulat' — did you mean 'simulate'?\n");
  const std::string path = test::write_file("valid.toml", with_field("g = 1\nlambda = 3\n"));
  const auto o =
      newtop::test::run_newtop("simulate " + path + " --tend 5", newtop::test::Stderr::separate);
  EXPECT_EQ(o.code, 2);
  EXPECT_EQ(o.err,
            "newtop: error: unknown option '--tend' for newtop simulate — did you mean "
            "'--t-end'?\n");
}

// The documented form of point masses: a points key says which model it is.
TEST(ScenarioKeys, PointsWithoutKindArePointMasses) {
  const std::string text =
      "[mass_model]\npoints = [[1, 1, 0, 0], [1, -1, 0, 0], [2, 0, 1, 0], [2, 0, -1, 0], "
      "[3, 0, 0, 1], [3, 0, 0, -1]]\n[field]\nmu = 1.0\nR = 10.0\n" +
      kInitial;
  const Scenario s = parse_scenario(text, "s.toml");
  ASSERT_TRUE(s.model.mass_model());
  ASSERT_TRUE(std::holds_alternative<PointMasses>(*s.model.mass_model()));
  // M = Σm = 12; A = Σ m (y² + z²) = 2·2 + 3·2 = 10, B = 1·2 + 3·2 = 8, C = 1·2 + 2·2 = 6, exact
  // in binary; the tensor is diagonal, so the axes are kept.
  EXPECT_EQ(s.model.body().mass(), 12.0);
  EXPECT_EQ(s.model.body().inertia(), Vec3(10.0, 8.0, 6.0));
  // The other kinds follow from their own keys too.
  EXPECT_NO_THROW(
      parse_scenario("[mass_model]\nsemi_axes = [1.0, 2.0, 3.0]\nmass = 1.0\n"
                     "[field]\nmu = 1.0\nR = 10.0\n" +
                         kInitial,
                     "s.toml"));
  EXPECT_NO_THROW(
      parse_scenario("[mass_model]\ndimensions = [1.0, 2.0, 3.0]\ndensity = 1.0\n"
                     "[field]\nmu = 1.0\nR = 10.0\n" +
                         kInitial,
                     "s.toml"));
  expect_rejected("mass_model_no_kind",
                  "[mass_model]\nfile = \"m.csv\"\n[field]\nmu = 1.0\nR = 10.0\n" + kInitial,
                  ":1:1: [mass_model] kind: missing: give kind = \"points\", \"polyhedron\", "
                  "\"ellipsoid\" or \"box\" (a file alone may hold point masses or a mesh)");
}

}  // namespace
}  // namespace test_scenario_keys
}  // namespace newtop::io
