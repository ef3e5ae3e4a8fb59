// Scenario files: a valid file round-trips into the model; every class of bad input gives one line
// naming the key, what was expected and what was found.

#include <gtest/gtest.h>

#include <string>

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::io {
namespace test_scenario {
namespace {

const std::string kValid = R"(
[body]
inertia = [1.0, 1.5, 2.2]
mass = 2.0
center_of_mass = [0.1, 0.0, 0.3]
[field]
g = 1.0
R = 6.0
[initial]
omega = [0.5, 1.1, -0.4]
gamma = [0.48, -0.6, 0.64]
[integrate]
t_end = 10.0
step = 0.01
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

// Parses text and returns the error message (empty if it parsed).
std::string error_of(const std::string& text) {
  try {
    parse_scenario(text, "s.toml");
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message must be one line: " << msg;
    return msg;
  }
  return "";
}

void expect_error(const std::string& text, std::initializer_list<const char*> parts) {
  const std::string msg = error_of(text);
  ASSERT_FALSE(msg.empty()) << "accepted bad input";
  for (const char* p : parts) EXPECT_NE(msg.find(p), std::string::npos) << msg << " lacks " << p;
}

IntegrateOverrides with_method(const char* name) {
  IntegrateOverrides o;
  o.method = name;
  return o;
}

IntegrateOverrides with_tol(double tol) {
  IntegrateOverrides o;
  o.tol = tol;
  return o;
}

TEST(Scenario, ValidFileBuildsTheModel) {
  const Scenario s = parse_scenario(kValid, "s.toml");
  EXPECT_EQ(s.model.body().inertia(), Vec3(1.0, 1.5, 2.2));
  EXPECT_DOUBLE_EQ(s.model.quadratic().field.lambda_, 0.5);
  EXPECT_EQ(omega(s.model.body(), s.initial), Vec3(0.5, 1.1, -0.4));
  EXPECT_EQ(*s.integrate.t_end, 10.0);
  const MethodSettings m = resolve_method(s, {});
  EXPECT_EQ(m.name, kDefaultFixedMethod);
  EXPECT_EQ(m.step, 0.01);
  EXPECT_EQ(resolve_method(s, with_tol(1e-9)).name, kDefaultQuadraticAdaptiveMethod);
  EXPECT_EQ(resolve_method(s, with_method("rk4")).step, 0.01);
  EXPECT_THROW(resolve_method(s, with_method("dopri5")), InputError);  // no tolerance anywhere
}

TEST(Scenario, UnknownKeyIsNamedWithItsPosition) {
  expect_error(replace(kValid, "mass = 2.0", "mas = 2.0"),
               {"s.toml:4:", "unknown key 'mas' in [body] — did you mean 'mass'?"});
  expect_error(kValid + "[outptu]\nfile = \"x.csv\"\n",
               {"unknown section [outptu] — did you mean [output]?"});
}

TEST(Scenario, WrongTypeAndLength) {
  expect_error(replace(kValid, "mass = 2.0", "mass = \"heavy\""),
               {"[body] mass", "expected a number", "found the string \"heavy\""});
  expect_error(replace(kValid, "inertia = [1.0, 1.5, 2.2]", "inertia = [1.0, 1.5]"),
               {"[body] inertia", "expected an array of 3 numbers", "found an array of 2"});
  expect_error(replace(kValid, "omega = [0.5, 1.1, -0.4]", "omega = [0.5, true, -0.4]"),
               {"[initial] omega", "element 2"});
}

TEST(Scenario, NonPhysicalInertia) {
  expect_error(replace(kValid, "inertia = [1.0, 1.5, 2.2]", "inertia = [1.0, 2.0, 4.5]"),
               {"[body] inertia", "A + B >= C fails: 1 + 2 < 4.5"});
  expect_error(replace(kValid, "inertia = [1.0, 1.5, 2.2]", "inertia = [1.0, -1.5, 2.2]"),
               {"[body] inertia", "positive", "B = -1.5"});
}

TEST(Scenario, NonFiniteNumbers) {
  expect_error(replace(kValid, "g = 1.0", "g = nan"), {"[field] g", "finite", "nan"});
  expect_error(replace(kValid, "gamma = [0.48, -0.6, 0.64]", "gamma = [inf, 0.0, 0.0]"),
               {"[initial] gamma", "finite"});
}

TEST(Scenario, GammaMustBeUnitUnlessNormalized) {
  const std::string off = replace(kValid, "gamma = [0.48, -0.6, 0.64]", "gamma = [0.6, 0.8, 0.01]");
  expect_error(off, {"[initial] gamma", "unit vector", "normalize = true"});
  const Scenario s =
      parse_scenario(replace(off, "[initial]", "[initial]\nnormalize = true"), "s.toml");
  EXPECT_NEAR(s.initial.gamma.norm(), 1.0, 1e-15);
}

TEST(Scenario, MalformedTomlAndMissingSections) {
  expect_error("[body\ninertia = [1, 1, 1]\n", {"s.toml:1:", "malformed TOML"});
  expect_error(replace(kValid, "[initial]", "[initial_state]"),
               {"unknown section [initial_state]", "[initial]"});
  expect_error(
      replace(kValid, "[initial]\nomega = [0.5, 1.1, -0.4]\ngamma = [0.48, -0.6, 0.64]\n", ""),
      {"missing section [initial]"});
  expect_error(replace(kValid, "R = 6.0", "lambda = 0.5\nR = 6.0"),
               {"[field] R: conflicts with lambda", "(g, lambda), (g, R) or (mu, R)"});
}

TEST(Scenario, UnreadableFile) {
  try {
    load_scenario("/nonexistent/dir/none.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/nonexistent/dir/none.toml: scenario file: cannot read it: no such file");
  }
}

TEST(Scenario, UnknownMethod) {
  expect_error(replace(kValid, "step = 0.01", "step = 0.01\nmethod = \"euler\""),
               {"[integrate] method", "euler", "splitting6"});
}

TEST(Scenario, SplitOfTheFreeBodySetsTheOrdering) {
  // Absent: the method's default ordering (no override).
  EXPECT_FALSE(resolve_method(parse_scenario(kValid, "s.toml"), {}).ordering.has_value());
  const std::string spin = replace(kValid, "step = 0.01", "step = 0.01\nsplit = \"spin\"");
  const Scenario s = parse_scenario(spin, "s.toml");
  const MethodSettings m = resolve_method(s, {});
  ASSERT_TRUE(m.ordering.has_value());
  EXPECT_EQ(m.ordering->free_body, FreeBodySplit::spin);
  // The rest of the ordering is the method's default.
  const SplitOrdering d = default_ordering(composition_table(m.name));
  EXPECT_EQ(m.ordering->kick_outside, d.kick_outside);
  EXPECT_EQ(m.ordering->axes, d.axes);
  // The command line wins; the file's split is dropped for a method that is not a splitting.
  IntegrateOverrides axes;
  axes.split = "axes";
  EXPECT_EQ(resolve_method(s, axes).ordering->free_body, FreeBodySplit::axes);
  EXPECT_FALSE(resolve_method(s, with_tol(1e-9)).ordering.has_value());
  IntegrateOverrides bad = with_tol(1e-9);
  bad.split = "spin";
  EXPECT_THROW(resolve_method(s, bad), InputError);
  // The exact free-body flow: only without a gyrostat.
  IntegrateOverrides exact;
  exact.split = "exact";
  EXPECT_EQ(resolve_method(s, exact).ordering->free_body, FreeBodySplit::exact);
  const Scenario k =
      parse_scenario(replace(spin, "center_of_mass = [0.1, 0.0, 0.3]",
                             "center_of_mass = [0.1, 0.0, 0.3]\ngyrostat = [0.0, 0.1, 0.0]"),
                     "s.toml");
  try {
    resolve_method(k, exact);
    ADD_FAILURE() << "exact split with a gyrostat accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("split: the exact free-body flow needs"),
              std::string::npos)
        << e.what();
  }
}

TEST(Scenario, BadSplitIsNamed) {
  expect_error(replace(kValid, "step = 0.01", "step = 0.01\nsplit = \"rotations\""),
               {"split", "expected \"axes\", \"spin\" or \"exact\"", "rotations"});
  expect_error(replace(kValid, "step = 0.01", "tol = 1e-9\nsplit = \"spin\""),
               {"split", "found tol"});
  expect_error(replace(kValid, "step = 0.01", "method = \"rkf78\"\ntol = 1e-9\nsplit = \"spin\""),
               {"split", "applies to the splitting methods", "rkf78"});
  expect_error(replace(kValid, "step = 0.01", "step = 0.01\nsplit = 3"), {"split"});
}

TEST(Scenario, FullTensorRotatesTheInitialVectors) {
  // A tensor diagonal up to a swap of x and y needs no rotation but must keep the moments.
  const std::string t =
      replace(kValid, "inertia = [1.0, 1.5, 2.2]",
              "inertia_tensor = [[1.25, 0.25, 0.0], [0.25, 1.25, 0.0], [0.0, 0.0, 2.2]]");
  const Scenario s = parse_scenario(t, "s.toml");
  EXPECT_NEAR(s.model.body().A(), 1.0, 1e-14);
  EXPECT_NEAR(s.model.body().B(), 1.5, 1e-14);
  // ω in the body frame is Pᵀ ω_user: its norm and its product with γ are frame-invariant.
  EXPECT_NEAR(omega(s.model.body(), s.initial).norm(), Vec3(0.5, 1.1, -0.4).norm(), 1e-14);
  EXPECT_NEAR(omega(s.model.body(), s.initial).dot(s.initial.gamma),
              Vec3(0.5, 1.1, -0.4).dot(Vec3(0.48, -0.6, 0.64)), 1e-14);
}

}  // namespace
}  // namespace test_scenario
}  // namespace newtop::io
