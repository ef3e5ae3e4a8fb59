// Planar pitch motion on an elliptic orbit: the full (m, γ, n) model restricted to n = e_z, γ in
// the body xy plane, against Beletsky's scalar equation (docs/orbit.md §4) integrated separately.

#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>

#include "orbit_problems.hpp"

namespace newtop {
namespace test_beletsky {
namespace {

// Both sides integrated by Fehlberg 7(8) at 1e-13 over Δν = 12 (two orbits): each is accurate to
// ~1e-11 in θ; 1e-9 leaves room while any error of the equation (a sign, a factor) is O(e) ≥ 1e-2.
constexpr double kSameMotion = 1e-9;

/// θ″ = [2e sin ν (θ′ + 1) − 3 ((B − A)/C) sin θ cos θ] / (1 + e cos ν).
double beletsky_theta(double e, double k, double theta0, double dtheta0, double nu0, double nu1) {
  using namespace boost::numeric::odeint;
  std::array<double, 2> x{theta0, dtheta0};
  auto f = [&](const std::array<double, 2>& y, std::array<double, 2>& d, double nu) {
    d[0] = y[1];
    d[1] = (2 * e * std::sin(nu) * (y[1] + 1) - 3 * k * std::sin(y[0]) * std::cos(y[0])) /
           (1 + e * std::cos(nu));
  };
  integrate_adaptive(make_controlled<runge_kutta_fehlberg78<std::array<double, 2>>>(1e-13, 1e-13),
                     f, x, nu0, nu1, 1e-3);
  return x[0];
}

TEST(Beletsky, PlanarRestrictionIsBeletskysEquation) {
  const Vec3 I(1.0, 1.6, 2.1);  // A, B in the plane, C about the orbit normal
  const Body body = Body::from_principal(I, 1.0, Vec3::Zero());
  for (const double e : {0.0, 0.1, 0.3}) {
    const EllipticOrbit orbit = EllipticOrbit::from_mean_motion(1.0, e, 0.4);
    const EllipticOrbitModel model(body, orbit);
    const double theta0 = 0.3, dtheta0 = -0.2;
    // θ from the radius to the body x axis about n: γ = (cos θ, −sin θ, 0), ω_z = ν̇ (1 + θ′).
    const double wz = anomaly_rate(orbit, 0.4) * (1 + dtheta0);
    const OrbitState x0{I.z() * wz * Vec3::UnitZ(), Vec3(std::cos(theta0), -std::sin(theta0), 0),
                        Vec3::UnitZ()};
    const OrbitState x1 = test::reference(model, x0, 0.4, 12.4, 1e-13);
    EXPECT_LT(std::abs(x1.normal.z() - 1.0), kSameMotion);  // the motion stays planar
    const double theta_full = std::atan2(-x1.gamma.y(), x1.gamma.x());
    const double theta_scalar =
        beletsky_theta(e, (I.y() - I.x()) / I.z(), theta0, dtheta0, 0.4, 12.4);
    EXPECT_NEAR(std::remainder(theta_full - theta_scalar, 2 * std::numbers::pi), 0.0, kSameMotion)
        << e;
  }
}

}  // namespace
}  // namespace test_beletsky
}  // namespace newtop
