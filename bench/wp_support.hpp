#pragma once
// Work–precision support: the regimes, the long-double reference, Boost.Odeint peers driven
// directly on std::array with a hand-written right-hand side (the fastest way to use odeint), and
// CPU time.

#include <array>
#include <boost/numeric/odeint/integrate/integrate_adaptive.hpp>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include "newtop/integrate/methods.hpp"
#include "newtop/newtop.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "newtop/phase/section_run.hpp"

namespace wp {

using namespace newtop;
namespace ode = boost::numeric::odeint;

/// CPU time of the process (all threads; the runs are single-threaded).
inline double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Regime {
  std::string name;         // a, b3, b5, c
  std::string description;  // for the table heading
  QuadraticModel model;
  State x0;
  double T;      // span
  double h_max;  // largest step tried by the fixed-step methods
};

/// The Euler–Poisson right-hand side of the quadratic field written out by hand, in any scalar:
/// ṁ = m × ω + γ × (b + λ Iγ), γ̇ = γ × ω, ω = (m − k)/I, b = M g r0.
template <class Real>
struct QuadraticRhs {
  std::array<Real, 3> inv_i, k, b, li;  // 1/I, k, M g r0, λ I

  explicit QuadraticRhs(const QuadraticModel& m) {
    for (int i = 0; i < 3; ++i) {
      inv_i[i] = Real(1) / Real(m.body.inertia()[i]);
      k[i] = Real(m.body.gyrostat()[i]);
      b[i] = Real(m.body.mass()) * Real(m.field.g) * Real(m.body.center_of_mass()[i]);
      li[i] = Real(m.field.lambda_) * Real(m.body.inertia()[i]);
    }
  }
  void operator()(const std::array<Real, 6>& y, std::array<Real, 6>& d, Real) const {
    const Real w0 = (y[0] - k[0]) * inv_i[0], w1 = (y[1] - k[1]) * inv_i[1],
               w2 = (y[2] - k[2]) * inv_i[2];
    const Real g0 = b[0] + li[0] * y[3], g1 = b[1] + li[1] * y[4], g2 = b[2] + li[2] * y[5];
    d[0] = y[1] * w2 - y[2] * w1 + y[4] * g2 - y[5] * g1;
    d[1] = y[2] * w0 - y[0] * w2 + y[5] * g0 - y[3] * g2;
    d[2] = y[0] * w1 - y[1] * w0 + y[3] * g1 - y[4] * g0;
    d[3] = y[4] * w2 - y[5] * w1;
    d[4] = y[5] * w0 - y[3] * w2;
    d[5] = y[3] * w1 - y[4] * w0;
  }
};

using LState = std::array<long double, 6>;

/// The reference: Fehlberg 7(8) in long double at tolerance tol (1e-19 by the issue).
inline LState reference(const Regime& r, long double tol) {
  LState y{r.x0.m[0], r.x0.m[1], r.x0.m[2], r.x0.gamma[0], r.x0.gamma[1], r.x0.gamma[2]};
  using Stepper = ode::runge_kutta_fehlberg78<LState, long double, LState, long double>;
  ode::integrate_adaptive(ode::make_controlled(tol, tol, Stepper()),
                          QuadraticRhs<long double>(r.model), y, 0.0L,
                          static_cast<long double>(r.T), 1e-3L);
  return y;
}

/// |Δm| + |Δγ| against the reference, the difference taken in long double.
inline double state_error(const State& x, const LState& ref) {
  long double dm = 0, dg = 0;
  for (int i = 0; i < 3; ++i) {
    dm += (x.m[i] - ref[i]) * (x.m[i] - ref[i]);
    dg += (x.gamma[i] - ref[i + 3]) * (x.gamma[i] - ref[i + 3]);
  }
  return static_cast<double>(std::sqrt(dm) + std::sqrt(dg));
}

/// An odeint controlled stepper run by integrate_adaptive on the hand-written right-hand side;
/// obs(x) after every accepted step when Observe.
template <class Stepper, bool Observe, class Obs>
State odeint_run(const Regime& r, double tol, std::int64_t& steps, Obs&& obs) {
  OdeState y = to_ode(r.x0);
  const QuadraticRhs<double> rhs(r.model);
  auto observer = [&](const OdeState& s, double) {
    if constexpr (Observe) obs(from_ode(s));
  };
  steps = static_cast<std::int64_t>(ode::integrate_adaptive(
      ode::make_controlled(tol, tol, Stepper()), rhs, y, 0.0, r.T, 1e-3, observer));
  return from_ode(y);
}

// --- regimes -------------------------------------------------------------------------------------

inline Regime generic() {
  QuadraticModel m{
      Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1), Vec3(0.1, -0.2, 0.05)),
      QuadraticField::coulomb(1.0, 0.5)};
  const State x0 = state_from_omega(m.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
  return {"a",
          "(a) generic: A, B, C = 1, 1.5, 2.2; r0 = (0.3, 0.2, 0.1); k = (0.1, -0.2, 0.05); "
          "g = 1, lambda = 0.5; T = 40 (about 3 Lyapunov times)",
          m,
          x0,
          40.0,
          0.5};
}

// A spinning satellite (fixed point at the centre of mass: r0 = 0, k = 0) about its largest axis
// at Ω = 1 with a nutation of 0.1 rad, in a gravity gradient λ = ratio Ω².
inline Regime fast_spin(double ratio, std::string name) {
  QuadraticModel m{Body::from_principal(Vec3(1.0, 1.2, 1.5), 1.0, Vec3::Zero()),
                   QuadraticField::coulomb(0.0, ratio)};
  const Vec3 w = Vec3(0.08, -0.06, 1.0).normalized();
  const State x0 = state_from_omega(m.body, w, Vec3(0.3, -0.5, 0.8).normalized());
  char d[200];
  std::snprintf(
      d, sizeof d,
      "(b) fast spin: A, B, C = 1, 1.2, 1.5; r0 = 0, k = 0; |omega| = 1 about the largest "
      "axis, nutation 0.1 rad; lambda/Omega^2 = %g; T = 1e4 (unit 1/Omega)",
      ratio);
  return {std::move(name), d, m, x0, 1e4, 2.0};
}

// Libration about the stable equilibrium γ = e_x (least moment) of a gravity gradient λ = 1
// (time unit 1/√λ), amplitude about 0.2 rad.
inline Regime libration() {
  QuadraticModel m{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                   QuadraticField::coulomb(0.0, 1.0)};
  const State x0 =
      state_from_omega(m.body, Vec3(0.05, -0.1, 0.12), Vec3(1.0, 0.15, -0.1).normalized());
  return {"c",
          "(c) slow libration: A, B, C = 1, 1.5, 2.2; r0 = 0, k = 0; lambda = 1; about "
          "gamma = e_x, amplitude ~0.2 rad; T = 1e4 (unit 1/sqrt(lambda))",
          m,
          x0,
          1e4,
          2.0};
}

}  // namespace wp
