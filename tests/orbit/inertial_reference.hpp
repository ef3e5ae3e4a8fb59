#pragma once
// An independent simulation of a satellite in inertial space, sharing no code with the orbit
// model: the centre of mass moves under −μ r/|r|³ (Newton, not Kepler's closed forms), the
// attitude matrix R (body → inertial) under Ṙ = R [ω]×, and the inertial angular momentum L under
// the gravity-gradient torque, L̇ = R τ with τ = 3μ/|r|³ ρ̂ × Iρ̂, ρ̂ = Rᵀ r/|r| (body axes).
// Integrated by Fehlberg 7(8) at a tolerance near round-off.

#include <array>
#include <cmath>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint/integrate/integrate_adaptive.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "newtop/core/types.hpp"

namespace newtop::test {

/// Inertial configuration: position and velocity of the centre of mass, attitude, and the
/// angular momentum about the centre of mass, all in inertial axes.
struct InertialSatellite {
  Vec3 r, v;
  Mat3 R;  // body → inertial
  Vec3 L;  // R (Iω + k)
};

struct InertialProblem {
  double mu;
  Vec3 inertia;   // A, B, C
  Vec3 gyrostat;  // k, body axes
};

inline InertialSatellite inertial_flow(const InertialProblem& p, const InertialSatellite& x0,
                                       double T, double tol = 1e-14) {
  using Y = std::array<double, 18>;
  auto pack = [](const InertialSatellite& s) {
    Y y;
    for (int i = 0; i < 3; ++i) {
      y[i] = s.r[i];
      y[3 + i] = s.v[i];
      y[15 + i] = s.L[i];
      for (int j = 0; j < 3; ++j) y[6 + 3 * i + j] = s.R(i, j);
    }
    return y;
  };
  auto unpack = [](const Y& y) {
    InertialSatellite s;
    for (int i = 0; i < 3; ++i) {
      s.r[i] = y[i];
      s.v[i] = y[3 + i];
      s.L[i] = y[15 + i];
      for (int j = 0; j < 3; ++j) s.R(i, j) = y[6 + 3 * i + j];
    }
    return s;
  };
  auto f = [&](const Y& y, Y& dy, double) {
    const InertialSatellite s = unpack(y);
    const double rn = s.r.norm();
    const Vec3 rho = s.R.transpose() * s.r / rn;
    const Vec3 tau = 3.0 * p.mu / (rn * rn * rn) * rho.cross(p.inertia.cwiseProduct(rho));
    const Vec3 w = (s.R.transpose() * s.L - p.gyrostat).cwiseQuotient(p.inertia);
    Mat3 W;
    W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    InertialSatellite d;
    d.r = s.v;
    d.v = -p.mu * s.r / (rn * rn * rn);
    d.R = s.R * W;
    d.L = s.R * tau;
    dy = pack(d);
  };
  namespace odeint = boost::numeric::odeint;
  Y y = pack(x0);
  odeint::integrate_adaptive(odeint::make_controlled(tol, tol, odeint::runge_kutta_fehlberg78<Y>()),
                             f, y, 0.0, T, T / 1000);
  return unpack(y);
}

}  // namespace newtop::test
