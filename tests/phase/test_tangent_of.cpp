// tangent_of(stepper): newtop's steppers get their exact tangent maps; any other fixed-step
// stepper is wrapped in FiniteDifferenceTangent, whose tangent vectors and chaos indicators agree
// with the exact map of the same method.

#include <gtest/gtest.h>

#include <memory>
#include <type_traits>

#include "newtop/exact/model_fields.hpp"
#include "newtop/model/model.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_tangent_of {
namespace {

using phase::Tangent;

// newtop's own steppers map to their exact tangent steppers.
static_assert(
    std::is_same_v<phase::TangentOf<SplittingStepper>::type, phase::TangentSplittingStepper>);
static_assert(std::is_same_v<phase::TangentOf<Rk4Stepper>::type, phase::TangentRk4Stepper>);
static_assert(std::is_same_v<phase::TangentOf<Dopri5Stepper>::type, phase::TangentDopri5Stepper>);
static_assert(
    std::is_same_v<phase::TangentOf<Fehlberg78Stepper>::type, phase::TangentFehlberg78Stepper>);

/// A stepper of one's own, unknown to newtop: the same splitting method behind another type, so
/// that tangent_of() wraps it in finite differences and the exact map of the method is known.
struct OwnStepper {
  SplittingStepper inner;
  int order() const { return inner.order(); }
  template <Field F>
  void step(const BasicModel<F>& model, State& x, double h) {
    inner.step(model, x, h);
  }
};
static_assert(
    std::is_same_v<phase::TangentOf<OwnStepper>::type, phase::FiniteDifferenceTangent<OwnStepper>>);

// The central difference of one step has a relative error of about δ² |Φ'''| + ε/δ ≈ 1e-10 with
// δ = ε^(1/3) (FiniteDifferenceTangent::kFiniteDifferenceStep) on these O(1) states. Over N = 200
// steps the errors add (at most N · 1e-10 relative to |V|, |V| ≤ e^(λ T) ≈ 20 here): 1e-6 bounds
// them with room; a forward difference (error ≈ δ ≈ 6e-6 per step) exceeds it.
constexpr double kFdAgreement = 1e-6;

// The tangent steppers carry the state by the same formulas as the plain steppers, in another
// order of operations: the states part by round-off, at most about 4ε per stage of each step (20
// stages for splitting8), over `steps` steps. Another method would part by O(h^p) ≫ this.
double round_off(int steps) { return steps * 20 * 4 * test::kEps; }

template <Field F>
void compare_with_exact(const BasicModel<F>& model, const char* name) {
  for (const char* method : {"splitting2", "splitting6"}) {
    const SplittingStepper plain(composition_table(method));
    auto fd = phase::tangent_of(OwnStepper{plain});
    auto exact = phase::tangent_of(plain);
    State x = test::generic_state(test::generic_model()), y = x;
    Tangent U = Tangent::Identity(6, 6), V = U;
    for (int n = 0; n < 200; ++n) {
      fd.step(model, x, U, 0.02);
      exact.step(model, y, V, 0.02);
    }
    EXPECT_LE((x.m - y.m).cwiseAbs().maxCoeff(), round_off(200) * x.m.norm()) << name << method;
    EXPECT_LE((x.gamma - y.gamma).cwiseAbs().maxCoeff(), round_off(200)) << name << method;
    const double scale = V.cwiseAbs().maxCoeff();
    EXPECT_LE((U - V).cwiseAbs().maxCoeff(), kFdAgreement * scale) << name << " " << method;
    EXPECT_GT(scale, 1.5) << name;  // the vectors moved: the comparison is not of identities
  }
}

TEST(TangentOf, FiniteDifferencesAgreeWithTheExactMapInEveryField) {
  const QuadraticModel quadratic = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const auto points = std::make_shared<const MassModel>(PointMasses(
      {1.0, 0.7, 0.5, 0.9},
      {Vec3(0.3, 0.1, -0.2), Vec3(-0.4, 0.2, 0.1), Vec3(0.1, -0.5, 0.3), Vec3(0.0, 0.2, -0.4)}));
  compare_with_exact(quadratic, "quadratic");
  visit_model(Model::exact(points, 2.0, 2.0 * max_radius(*points)),
              [](const auto& m) { compare_with_exact(m, "exact"); });
}

TEST(TangentOf, ChaosIndicatorsOfAWrappedStepperAgreeWithTheExactMap) {
  // λ_max and ⟨Y⟩ of a chaotic generic body (docs/chaos.md) from the same method's exact tangent
  // map and from finite differences of a stepper of one's own: the indicators are smooth
  // functions of the tangent vectors, so they agree to the vectors' kFdAgreement.
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  const double h = 0.02, T = 100.0;
  auto indicators = [&](auto& stepper) {
    phase::ChaosIndicators ind(0.0, 1);
    phase::integrate_tangent(stepper, model, x0, phase::initial_tangent(1), 0.0, T,
                             IntegrateOptions{.step = h},
                             [&](double t, const State&, Tangent& V) { ind(t, V); });
    return ind.sample();
  };
  const SplittingStepper plain(composition_table("splitting4"));
  auto exact = phase::tangent_of(plain);
  auto fd = phase::tangent_of(OwnStepper{plain});
  const phase::ChaosSample a = indicators(exact), b = indicators(fd);
  EXPECT_GT(a.lyapunov_max, 0.01);  // chaotic: a positive exponent to compare
  EXPECT_NEAR(b.lyapunov_max, a.lyapunov_max, kFdAgreement);
  EXPECT_NEAR(b.megno, a.megno, kFdAgreement * a.megno);
}

TEST(TangentOf, TheNamedTangentStepperIteratesTheSameMethod) {
  // with_tangent_stepper(settings) is tangent_of(the stepper with_stepper(settings) makes): the
  // state it carries is the plain method's, to round-off.
  const QuadraticModel model = test::generic_model();
  for (const char* name : {"splitting2", "splitting8", "rk4"}) {
    MethodSettings m;
    m.name = name;
    m.step = 0.05;
    State x = test::generic_state(model), y = x;
    phase::with_tangent_stepper(m, [&](auto& s) {
      if constexpr (phase::TangentFixedStepper<std::decay_t<decltype(s)>, QuadraticModel>) {
        Tangent V = phase::initial_tangent(1);
        for (int n = 0; n < 100; ++n) s.step(model, x, V, 0.05);
      }
    });
    with_stepper(m, [&](auto& s) {
      if constexpr (FixedStepper<std::decay_t<decltype(s)>, QuadraticModel, State>) {
        for (int n = 0; n < 100; ++n) s.step(model, y, 0.05);
      }
    });
    EXPECT_NE(x.m, test::generic_state(model).m) << name;
    EXPECT_LE((x.m - y.m).cwiseAbs().maxCoeff(), round_off(100) * x.m.norm()) << name;
    EXPECT_LE((x.gamma - y.gamma).cwiseAbs().maxCoeff(), round_off(100)) << name;
  }
}

}  // namespace
}  // namespace test_tangent_of
}  // namespace newtop
