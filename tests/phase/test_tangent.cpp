// The tangent map of the integrators against central finite differences of the one-step map,
// for each sub-flow and a whole step, in the quadratic, exact (point masses) and multipole fields.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "newtop/exact/model_fields.hpp"
#include "newtop/model/model.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "newtop/phase/one_step.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_tangent {
namespace {

using phase::Tangent;
using test::kEps;

// Central differences of a map Φ: R⁶ → R⁶ at x with the step ε: the columns of (Φ(x + εe_j) −
// Φ(x − εe_j))/(2ε). Their error is ε² |Φ'''|/6 (truncation) plus ε_mach |Φ|/ε (rounding); with
// ε = 1e-5 and the O(1) states and derivatives of these problems (|Φ'''| ≲ 100 over one step) both
// are below 2e-8, the tolerance. A tangent map missing any term is off by O(h) ≥ 1e-3.
constexpr double kFdStep = 1e-5;
constexpr double kFdTolerance = 2e-8;

template <class Map>
Eigen::Matrix<double, 6, 6> central_differences(const State& x, Map&& map) {
  Eigen::Matrix<double, 6, 6> D;
  for (int j = 0; j < 6; ++j) {
    State p = x, q = x;
    (j < 3 ? p.m[j] : p.gamma[j - 3]) += kFdStep;
    (j < 3 ? q.m[j] : q.gamma[j - 3]) -= kFdStep;
    const State a = map(p), b = map(q);
    D.col(j).head<3>() = (a.m - b.m) / (2 * kFdStep);
    D.col(j).tail<3>() = (a.gamma - b.gamma) / (2 * kFdStep);
  }
  return D;
}

/// The map's tangent applied to the identity, and its state.
template <class Step>
Eigen::Matrix<double, 6, 6> tangent_of(const State& x, Step&& step) {
  State y = x;
  Tangent V = Tangent::Identity(6, 6);
  step(y, V);
  return V;
}

struct Models {
  QuadraticModel quadratic = test::generic_model(Vec3(0.1, -0.2, 0.3));
  std::shared_ptr<const MassModel> points = std::make_shared<const MassModel>(PointMasses(
      {1.0, 0.7, 0.5, 0.9},
      {Vec3(0.3, 0.1, -0.2), Vec3(-0.4, 0.2, 0.1), Vec3(0.1, -0.5, 0.3), Vec3(0.0, 0.2, -0.4)}));
  Model exact = Model::exact(points, 2.0, 2.0 * max_radius(*points));
  Model multipole = Model::multipole(points, 4, 2.0, 2.0 * max_radius(*points));
};

const State kX{Vec3(0.6, -1.1, 0.8), Vec3(0.48, -0.6, 0.64)};

template <Field F>
void check_sub_flows(const BasicModel<F>& model, const char* name) {
  for (int a = 0; a < 3; ++a) {
    auto flow = [&](State y, Tangent& V) { phase::axis_flow_tangent(model.body, a, 0.3, y, V); };
    const auto T = tangent_of(kX, [&](State& y, Tangent& V) { flow(y, V); });
    const auto D = central_differences(kX, [&](State y) {
      Tangent W(6, 0);
      phase::axis_flow_tangent(model.body, a, 0.3, y, W);
      return y;
    });
    EXPECT_LE((T - D).cwiseAbs().maxCoeff(), kFdTolerance) << name << " axis " << a;
  }
  // The spin (φ = τ|m| ≈ 0.2 and 1.9: the series and the closed form of f₃) and a rotation by
  // θ = ta m_a + tb (the spin split's), each against differences of its own map.
  for (double tau : {0.12, 1.2}) {
    const auto T =
        tangent_of(kX, [&](State& y, Tangent& V) { phase::spin_flow_tangent(tau, y, V); });
    const auto D = central_differences(kX, [&](State y) {
      Tangent W(6, 0);
      phase::spin_flow_tangent(tau, y, W);
      return y;
    });
    EXPECT_LE((T - D).cwiseAbs().maxCoeff(), kFdTolerance) << name << " spin " << tau;
  }
  for (int a = 0; a < 3; ++a) {
    const auto T = tangent_of(
        kX, [&](State& y, Tangent& V) { phase::axis_flow_tangent(a, 0.4, -0.05, y, V); });
    const auto D = central_differences(kX, [&](State y) {
      Tangent W(6, 0);
      phase::axis_flow_tangent(a, 0.4, -0.05, y, W);
      return y;
    });
    EXPECT_LE((T - D).cwiseAbs().maxCoeff(), kFdTolerance) << name << " rotation " << a;
  }
  const auto T =
      tangent_of(kX, [&](State& y, Tangent& V) { phase::kick_tangent(model, 0.3, y, V); });
  const auto D = central_differences(kX, [&](State y) {
    Tangent W(6, 0);
    phase::kick_tangent(model, 0.3, y, W);
    return y;
  });
  EXPECT_LE((T - D).cwiseAbs().maxCoeff(), kFdTolerance) << name << " kick";
}

template <Field F>
void check_steps(const BasicModel<F>& model, const char* name) {
  for (const char* method : {"splitting2", "splitting4", "splitting6", "splitting8", "rk4",
                             "splitting4 spin", "splitting6 spin"}) {
    const std::string text = method;
    MethodSettings m;
    m.name = text.substr(0, text.find(' '));
    m.step = 0.1;
    if (text.ends_with(" spin")) {
      m.ordering = default_ordering(composition_table(m.name));
      m.ordering->free_body = FreeBodySplit::spin;
    }
    phase::with_tangent_stepper(m, [&](auto& s) {
      if constexpr (phase::TangentFixedStepper<std::decay_t<decltype(s)>, BasicModel<F>>) {
        const auto T = tangent_of(kX, [&](State& y, Tangent& V) { s.step(model, y, V, 0.1); });
        const auto D = central_differences(kX, [&](State y) {
          Tangent W(6, 0);
          s.step(model, y, W, 0.1);
          return y;
        });
        EXPECT_LE((T - D).cwiseAbs().maxCoeff(), kFdTolerance) << name << " " << method;
      }
    });
  }
}

TEST(TangentMap, SubFlowsMatchFiniteDifferences) {
  const Models ms;
  check_sub_flows(ms.quadratic, "quadratic");
  check_sub_flows(exact_model(ms.exact), "exact");
  check_sub_flows(multipole_model(ms.multipole), "multipole");
}

TEST(TangentMap, WholeStepsMatchFiniteDifferences) {
  const Models ms;
  check_steps(ms.quadratic, "quadratic");
  // The spin split above has a gyrostat on C, the axis of largest moment (SpinFlow<true>); here
  // none.
  check_steps(test::generic_model(Vec3(0.1, -0.2, 0.0)), "quadratic, no gyrostat on C");
  check_steps(exact_model(ms.exact), "exact");
  check_steps(multipole_model(ms.multipole), "multipole");
}

// The tangent stepper iterates the same map as the plain stepper: the states agree to the
// rounding of a step (64 ε over the O(1) state after 100 steps; the sub-flows are the same
// formulas in another frame).
TEST(TangentMap, StateIsThePlainSteppersState) {
  const QuadraticModel model = test::generic_model(Vec3(0.1, -0.2, 0.3));
  for (const char* method : {"splitting4", "splitting6", "rk4", "splitting4 spin"}) {
    const std::string text = method;
    MethodSettings m;
    m.name = text.substr(0, text.find(' '));
    m.step = 0.05;
    if (text.ends_with(" spin")) {
      m.ordering = default_ordering(composition_table(m.name));
      m.ordering->free_body = FreeBodySplit::spin;
    }
    State a = kX, b = kX;
    Tangent V = phase::initial_tangent(1);
    with_stepper(m, [&](auto& s) {
      phase::OneStepMap<std::decay_t<decltype(s)>> map(s);
      for (int i = 0; i < 100; ++i) a = map(model, a, 0.05);
    });
    phase::with_tangent_stepper(m, [&](auto& s) {
      if constexpr (phase::TangentFixedStepper<std::decay_t<decltype(s)>, QuadraticModel>) {
        for (int i = 0; i < 100; ++i) s.step(model, b, V, 0.05);
      }
    });
    EXPECT_LE(test::distance(a, b), 1e3 * kEps) << method;
  }
  MethodSettings exact;
  exact.name = "splitting4";
  exact.step = 0.05;
  exact.ordering = default_ordering(composition_table("splitting4"));
  exact.ordering->free_body = FreeBodySplit::exact;
  EXPECT_THROW(phase::with_tangent_stepper(exact, [](auto&) {}), InputError);
}

}  // namespace
}  // namespace test_tangent
}  // namespace newtop
