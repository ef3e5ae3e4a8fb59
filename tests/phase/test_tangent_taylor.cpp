// Taylor's tangent map: the coefficients of the variational equations against the Jacobian of the
// right-hand side and its derivative along the flow, the same bits on every instruction set, the
// map over a run against central differences of Taylor's own flow and against Dormand–Prince
// 8(5,3)'s variational equations, and the fields it refuses.

#include <gtest/gtest.h>

#include <memory>

#include "newtop/exact/model_fields.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "newtop/phase/tangent_taylor.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_tangent_taylor {
namespace {

using phase::Tangent;
using test::kEps;

Eigen::Matrix<double, 6, 1> column(const detail::TaylorTangentSeries& ts, int c, int n) {
  const auto& m = ts.m[static_cast<std::size_t>(c)][static_cast<std::size_t>(n)];
  const auto& g = ts.gamma[static_cast<std::size_t>(c)][static_cast<std::size_t>(n)];
  Eigen::Matrix<double, 6, 1> v;
  v << m[0], m[1], m[2], g[0], g[1], g[2];
  return v;
}

State moved(const State& x, const State& f, double d) {
  return {x.m + d * f.m, x.gamma + d * f.gamma};
}

// δx^[1] = J(x) δx to the rounding of J's products (|J| |δx| ≲ 10 here: 16 ε of that), and
// δx^[2] = ½ d/dt (J(x(t)) δx(t)) = ½ (J(x + d f) (δx + d J δx) − J(x − d f) (δx − d J δx))/(2d)
// + O(d²): with d = 1e-5 the truncation (≲ 1e-9) and the rounding (ε |J δx| / d ≈ 1e-10) stay
// under kSecondOrder = 1e-8; every column of the identity (all of J).
constexpr double kSecondOrder = 1e-8;

TEST(TaylorTangentSeries, FirstTwoCoefficientsAreTheJacobianAndItsDerivative) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const State x = test::generic_state(m);
  const detail::TaylorModel p(m);
  detail::TaylorSeries s;
  detail::taylor_expand(p, x, nullptr, 8, s);
  const Tangent V = Tangent::Identity(6, 6);
  detail::TaylorTangentSeries ts;
  detail::taylor_expand_tangent(p, s, V, ts);
  const Eigen::Matrix<double, 6, 6> J = phase::rhs_jacobian(m, x);
  constexpr double d = 1e-5;
  const State f = rhs(m, x);
  const Eigen::Matrix<double, 6, 6> Ju = phase::rhs_jacobian(m, moved(x, f, d));
  const Eigen::Matrix<double, 6, 6> Jd = phase::rhs_jacobian(m, moved(x, f, -d));
  for (int c = 0; c < 6; ++c) {
    const Eigen::Matrix<double, 6, 1> v = V.col(c), Jv = J * v;
    EXPECT_LT((column(ts, c, 1) - Jv).cwiseAbs().maxCoeff(), 16 * kEps * 10.0) << c;
    const Eigen::Matrix<double, 6, 1> second = 0.25 * (Ju * (v + d * Jv) - Jd * (v - d * Jv)) / d;
    EXPECT_LT((column(ts, c, 2) - second).cwiseAbs().maxCoeff(), kSecondOrder) << c;
  }
}

TEST(TaylorTangentSeries, SameBitsOnEveryInstructionSet) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const detail::TaylorModel p(m);
  detail::TaylorSeries s;
  detail::taylor_expand(p, test::generic_state(m), nullptr, 24, s);
  Tangent V = Tangent::Identity(6, 6);
  V.col(2) = Eigen::Matrix<double, 6, 1>(0.3, -0.1, 0.7, 0.2, -0.5, 0.4);
  detail::TaylorTangentSeries a, b;
  detail::taylor_expand_tangent(p, s, V, a, false);
  detail::taylor_expand_tangent(p, s, V, b, true);
  for (int c = 0; c < 6; ++c) {
    for (int n = 0; n <= 24; ++n) EXPECT_EQ(column(a, c, n), column(b, c, n)) << c << " " << n;
  }
}

// Runs (x, V) from t = 0 to T with the tangent stepper, V unrenormalised.
template <class S>
Tangent tangent_over(S& stepper, const QuadraticModel& m, const State& x0, double T) {
  Tangent V;
  phase::integrate_tangent_adaptive(stepper, m, x0, Tangent::Identity(6, 6), 0.0, T, {},
                                    [&](double, const State&, Tangent& W) { V = W; });
  return V;
}

// Over T = 5 on the generic (chaotic) body, the map against central differences of Taylor's own
// flow at tolerance 1e-15 with δ = 1e-6: their truncation δ² |Φ'''| and rounding ε |Φ| / δ ≈ 1e-10
// (|Φ| ≈ 1) stay under kFiniteDifference = 1e-8, relative to |V| (≈ 10).
constexpr double kFiniteDifference = 1e-8;

TEST(TangentTaylor, AgreesWithCentralDifferencesOfTheFlow) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const State x0 = test::generic_state(m);
  constexpr double T = 5.0, delta = 1e-6;
  phase::TangentTaylorStepper stepper(1e-14, 1e-14);
  const Tangent V = tangent_over(stepper, m, x0, T);
  const double scale = V.cwiseAbs().maxCoeff();
  for (int c = 0; c < 6; ++c) {
    auto flow = [&](double sign) {
      Eigen::Matrix<double, 6, 1> y;
      y << x0.m, x0.gamma;
      y(c) += sign * delta;
      TaylorStepper s(1e-15, 1e-15);
      const State x = integrate(s, m, State{y.head<3>(), y.tail<3>()}, 0.0, T, {}).state;
      y << x.m, x.gamma;
      return y;
    };
    const Eigen::Matrix<double, 6, 1> fd = (flow(1.0) - flow(-1.0)) / (2 * delta);
    EXPECT_LT((V.col(c) - fd).cwiseAbs().maxCoeff(), kFiniteDifference * scale) << c;
  }
}

// The same map from Dormand–Prince 8(5,3)'s variational equations (a second method) at tolerance
// 1e-14: each takes ~100 steps of local error ≲ 1e-14 |V|, grown by at most e^(λ T) ≈ 2 over T = 5
// (λ ≈ 0.15): kSecondMethod = 1e-11 relative to |V|.
constexpr double kSecondMethod = 1e-11;

TEST(TangentTaylor, AgreesWithDop853sVariationalEquations) {
  const QuadraticModel m = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const State x0 = test::generic_state(m);
  phase::TangentTaylorStepper taylor(1e-14, 1e-14);
  phase::TangentDop853Stepper dop853(1e-14, 1e-14);
  const Tangent a = tangent_over(taylor, m, x0, 5.0), b = tangent_over(dop853, m, x0, 5.0);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), kSecondMethod * b.cwiseAbs().maxCoeff());
}

TEST(TangentTaylor, OtherFieldsAreRefused) {
  const auto masses = std::make_shared<const MassModel>(PointMasses(
      {1.0, 0.7, 0.5}, {Vec3(0.3, 0.1, -0.2), Vec3(-0.4, 0.2, 0.1), Vec3(0.1, -0.5, 0.3)}));
  const BasicModel<ExactField> exact = exact_model(Model::exact(masses, 1.0, 5.0));
  const State x0 = state_from_omega(exact.body, Vec3(0.1, 0.2, 0.3), Vec3(0.0, 0.6, 0.8));
  phase::TangentTaylorStepper s(1e-10, 1e-10);
  State x = x0;
  Tangent V = Tangent::Identity(6, 1);
  double t = 0.0, dt = 0.1;
  EXPECT_THROW(s.try_step(exact, x, V, t, dt), InputError);
  EXPECT_THROW(s.initial_step(exact, x, 0.0, 1.0), InputError);
}

}  // namespace
}  // namespace test_tangent_taylor
}  // namespace newtop
