// io::scenario_text: the scenario of a model built in code, read back by parse_scenario into the
// same model (the quadratic field's body in its principal axes bit for bit; a mass model's
// gyrostat in the user's frame, taken into the principal axes once), a polyhedron refused.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "newtop/exact/exact_field.hpp"
#include "newtop/exact/mass_models.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/io/scenario_text.hpp"

namespace newtop {
namespace test_scenario_text {
namespace {

// Round-off of P Pᵀ k against k (three products and sums of numbers of order |k|): 8 ε |k|.
constexpr double kRotationRoundOff = 8 * 2.220446049250313e-16;

std::shared_ptr<const MassModel> skew_points() {
  return std::make_shared<const MassModel>(PointMasses(
      {1.0, 0.8, 0.5}, {Vec3(0.4, 0.3, 0.0), Vec3(-0.2, 0.5, 0.3), Vec3(0.1, -0.4, 0.6)}));
}

TEST(ScenarioText, QuadraticBodyOfATensorReadsBackBitForBit) {
  Mat3 J;
  J << 1.2, 0.1, -0.05, 0.1, 1.5, 0.2, -0.05, 0.2, 2.1;
  const Body body = Body::from_tensor(J, 1.0, Vec3(0.1, 0.05, 0.2), Vec3(0.05, -0.1, 0.2));
  const Model model(body, QuadraticField::coulomb(1.0, 0.7));
  const State x0 = state_from_omega(body, Vec3(0.3, -0.2, 0.9), Vec3(0.0, 0.6, 0.8));
  const io::Scenario sc = io::parse_scenario(io::scenario_text(model, x0), "<text>");
  const Body& b = sc.model.body();
  EXPECT_EQ(b.inertia(), body.inertia());
  EXPECT_EQ(b.center_of_mass(), body.center_of_mass());
  EXPECT_EQ(b.gyrostat(), body.gyrostat());
  EXPECT_EQ(sc.model.quadratic().field.lambda_, 0.7);
  EXPECT_EQ(sc.initial.gamma, x0.gamma);
}

// The gyrostat of [body] beside a mass model is in the user's frame, as Model::exact takes it:
// the model read back has the gyrostat of the model built (to the round-off of P Pᵀ), and the
// same body as its state's (one rotation, not two).
TEST(ScenarioText, GyrostatBesideAMassModelIsRotatedOnce) {
  const Vec3 k(0.05, -0.1, 0.2);
  const Model model = Model::exact(skew_points(), 5.0, 20.0, k);
  ASSERT_FALSE(model.body().principal_axes().isIdentity(0.0));
  const State x0 = state_from_omega(model.body(), Vec3(0.3, -0.2, 0.9), Vec3(0.0, 0.6, 0.8));
  const io::Scenario sc = io::parse_scenario(io::scenario_text(model, x0), "<text>");
  EXPECT_TRUE(sc.model.body().gyrostat().isApprox(model.body().gyrostat(), kRotationRoundOff))
      << sc.model.body().gyrostat().transpose() << " vs " << model.body().gyrostat().transpose();
  EXPECT_EQ(sc.model.body().inertia(), model.body().inertia());
}

TEST(ScenarioText, PolyhedronBuiltInCodeIsRefused) {
  const Model model = Model::exact(
      std::make_shared<const MassModel>(make_box(Vec3(1.0, 0.8, 0.5), 1.0)), 5.0, 20.0);
  const State x0 = state_from_omega(model.body(), Vec3(0.3, -0.2, 0.9), Vec3(0.0, 0.6, 0.8));
  try {
    io::scenario_text(model, x0);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("base: expected a model with a scenario text, found the "
                                          "field of a polyhedron built in code",
                                          0),
              0u)
        << e.what();
  }
}

}  // namespace
}  // namespace test_scenario_text
}  // namespace newtop
