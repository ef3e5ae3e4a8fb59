// The Lyapunov families of the Euler–Poisson equations (docs/continuation.md §4c): the period
// tends to the linear one, each orbit closes under an independent integration (Fehlberg 7(8)),
// and the energy is constant along it and the family's parameter.

#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>

#include "newtop/analysis/lyapunov_family.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop {
namespace test_lyapunov_family {
namespace {

constexpr double kPi = std::numbers::pi;
// The independent integration: Fehlberg 7(8) at 1e-13 (absolute and relative) over one period of
// ~10 time units, ~10² steps: its global error ~1e-12, the shooting's (Bulirsch–Stoer at 1e-12)
// similar, magnified by at most the multipliers' growth (≤ 2 on the stable stretches): 1e-9.
constexpr double kClosed = 1e-9;
// The energy along the orbit: both integrators conserve it to their error (~1e-12).
constexpr double kEnergy = 1e-10;

QuadraticModel model() {
  return {Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.1, 0, 0)),
          QuadraticField{1.0, 1.0}};
}

TEST(ContinuationLyapunov, FamilyStartsAtTheLinearPeriodAndEachOrbitCloses) {
  // γ = e_x at rest is a minimum of V (a stable equilibrium): its two normal modes ±iω.
  const QuadraticModel m = model();
  const Eigen::Vector2d w = normal_frequencies(m, Vec3::UnitX());
  const double h_eq = energy(m, State{Vec3::Zero(), Vec3::UnitX()});
  for (const int mode : {0, 1}) {
    const double linear = 2 * kPi / w[mode];
    const Family f = lyapunov_family(m, Vec3::UnitX(), mode, 1e-4, 0.1);
    ASSERT_EQ(f.end, "range") << mode;
    // The period's limit as the energy (∝ amplitude²) → 0, linear in the energy: extrapolated
    // from the first two points to 0, the linear period within 1e-6 (the quadratic term:
    // T″ p0² ~ 1e-7 at p0 = 1e-4 here).
    const FamilyPoint &a = f.points[0], &b = f.points[1];
    const double t0 = a.period - a.parameter * (b.period - a.period) / (b.parameter - a.parameter);
    EXPECT_NEAR(t0, linear, 1e-6 * linear) << mode;
    EXPECT_GT(f.points.back().period, linear);  // softening: the period grows with the energy
    namespace ode = boost::numeric::odeint;
    using S = std::array<double, 6>;
    double worst = 0.0, drift = 0.0;
    for (std::size_t i = 0; i < f.points.size(); i += 5) {
      const FamilyPoint& p = f.points[i];
      S x{p.values[0], p.values[1], p.values[2], p.values[3], p.values[4], p.values[5]};
      auto h = [&m](const S& y) {
        return energy(m, State{Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5])});
      };
      const double h0 = h(x);
      EXPECT_NEAR(h0 - h_eq, p.parameter, kEnergy);  // the family's parameter is its energy
      auto f6 = [&m](const S& y, S& d, double) {
        const State r = rhs(m, State{Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5])});
        d = {r.m[0], r.m[1], r.m[2], r.gamma[0], r.gamma[1], r.gamma[2]};
      };
      double dh = 0.0;
      ode::integrate_adaptive(ode::make_controlled<ode::runge_kutta_fehlberg78<S>>(1e-13, 1e-13),
                              f6, x, 0.0, p.period, p.period / 100,
                              [&](const S& y, double) { dh = std::max(dh, std::abs(h(y) - h0)); });
      double closed = 0.0;
      for (int k = 0; k < 6; ++k) closed = std::max(closed, std::abs(x[k] - p.values[k]));
      EXPECT_LE(closed, kClosed) << "mode " << mode << " p = " << p.parameter;
      EXPECT_LE(dh, kEnergy);
      worst = std::max(worst, closed);
      drift = std::max(drift, dh);
    }
    std::printf(
        "mode %d: %zu points, linear period %.12f, extrapolated %.12f, max |x(T) − x0| "
        "%.2e, max energy change %.2e\n",
        mode, f.points.size(), linear, t0, worst, drift);
  }
}

}  // namespace
}  // namespace test_lyapunov_family
}  // namespace newtop
