// The fixed point stability_of_equilibrium / stability_of_state could not analyse: a
// StabilityChoiceError whose reason and fields (the number of equilibria, every orientation, the
// failed polish) let the command line word it for its options, the library's message in what().

#include <gtest/gtest.h>

#include <string>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability_report.hpp"

namespace newtop {
namespace test_choice_test {
namespace {

using Reason = StabilityChoiceError::Reason;

template <class F>
StabilityChoiceError choice_error(F&& f) {
  try {
    f();
  } catch (const StabilityChoiceError& e) {
    return e;
  }
  ADD_FAILURE() << "no StabilityChoiceError";
  return StabilityChoiceError(Reason::no_equilibrium, "");
}

Model coulomb() {
  return Model(Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.1, 0.05, 0.2)),
               QuadraticField::coulomb(1.0, 0.7));
}

TEST(StabilityChoice, EquilibriumOutOfRangeGivesTheCount) {
  const Model model = coulomb();
  const int count = static_cast<int>(find_equilibria(model).equilibria.size());
  ASSERT_GT(count, 0);
  for (int k : {0, count + 1}) {
    const StabilityChoiceError e = choice_error([&] { stability_of_equilibrium(model, k); });
    EXPECT_EQ(e.reason, Reason::equilibrium_index) << k;
    EXPECT_EQ(e.count, count) << k;
    EXPECT_EQ(std::string(e.what()), "equilibrium: expected 1 to " + std::to_string(count) +
                                         " (the equilibria of find_equilibria), found " +
                                         std::to_string(k));
  }
  EXPECT_NO_THROW(stability_of_equilibrium(model, count));
}

TEST(StabilityChoice, FreeBodyHasNoIsolatedEquilibrium) {
  const Model free(Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()), QuadraticField{});
  const StabilityChoiceError e = choice_error([&] { stability_of_equilibrium(free, 1); });
  EXPECT_EQ(e.reason, Reason::no_equilibrium);
  EXPECT_TRUE(e.every_orientation);
}

TEST(StabilityChoice, StateFarFromAFixedPointCarriesItsPolish) {
  const Model model = coulomb();
  const State x = state_from_omega(model.body(), Vec3(0.3, -0.2, 0.9), Vec3(0.0, 0.6, 0.8));
  const StabilityChoiceError e = choice_error([&] { stability_of_state(model, x); });
  EXPECT_EQ(e.reason, Reason::not_fixed_point);
  EXPECT_FALSE(e.polish.converged);
  EXPECT_GT(e.polish.residual_given, 0.0);
  EXPECT_NE(std::string(e.what()).find(polish_failure(e.polish)), std::string::npos);
}

}  // namespace
}  // namespace test_choice_test
}  // namespace newtop
