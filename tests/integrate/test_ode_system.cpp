// The quadratic field's right-hand side as the Runge–Kutta methods evaluate it (OdeSystem with its
// per-model numbers formed once) against the generic rhs(model, x) of docs/model.md §4, the second
// method.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "newtop/integrate/runge_kutta.hpp"
#include "support/ensemble.hpp"

namespace newtop {
namespace test_ode_system {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Each component is a sum of four products of order |m||ω| or |γ||∂V/∂γ|; the two forms differ by
// the rounding of 1/I (ω: 2 ulps instead of 1) and of λI (one more rounding), a few ε of the size
// of the terms. Bound: 16 ε of the largest term's scale.
constexpr double kUlps = 16.0;

TEST(OdeSystem, QuadraticFieldAgreesWithTheGenericRightHandSide) {
  const auto models = test::random_models(40, true, 20261125);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const QuadraticModel& model : models) {
    const OdeSystem<QuadraticField, OrientedOdeState> fast{&model};
    for (int trial = 0; trial < 5; ++trial) {
      OrientedState x;
      static_cast<State&>(x) = test::random_start(model.body, 3.0, rng);
      double q4[4];
      for (double& c : q4) c = u(rng);
      x.q = Quaternion(q4[0], q4[1], q4[2], q4[3]).normalized();
      const State d = rhs(model, static_cast<const State&>(x));
      const Vec3 w = omega(model.body, x);
      const Quaternion dq = attitude_rate(x.q, w);
      OrientedOdeState y = to_ode(x), dy{};
      fast(y, dy, 0.0);
      const Vec3 grad = grad_gamma(model, x.gamma);
      const double scale = x.m.norm() * w.norm() + x.gamma.norm() * grad.norm();
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(dy[i], d.m[i], kUlps * kEps * scale);
        EXPECT_NEAR(dy[3 + i], d.gamma[i], kUlps * kEps * x.gamma.norm() * w.norm());
      }
      const double qs = x.q.norm() * w.norm();
      EXPECT_NEAR(dy[6], dq.w(), kUlps * kEps * qs);
      EXPECT_NEAR(dy[7], dq.x(), kUlps * kEps * qs);
      EXPECT_NEAR(dy[8], dq.y(), kUlps * kEps * qs);
      EXPECT_NEAR(dy[9], dq.z(), kUlps * kEps * qs);

      // The six-number system is the same numbers.
      const OdeSystem<QuadraticField> six{&model};
      OdeState y6 = to_ode(static_cast<const State&>(x)), d6{};
      six(y6, d6, 0.0);
      for (int i = 0; i < 6; ++i) EXPECT_EQ(d6[i], dy[i]);
    }
  }
}

}  // namespace
}  // namespace test_ode_system
}  // namespace newtop
