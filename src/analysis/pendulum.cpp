#include "newtop/analysis/pendulum.hpp"

#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "newtop/analysis/analytic_quadrature.hpp"

namespace newtop {
namespace {

// p, q, γ3 below this (in units of |ω| and 1) count as zero: values written to 15 digits.
constexpr double kPlaneTolerance = 1e-12;
// Scan step when bracketing the turning points: far finer than the π/2 between extrema of V.
constexpr int kScanPoints = 720;
constexpr int kPendulumNewtonIterations = 60;

double dpotential(const Pendulum& p, double phi) {
  return -p.mgx * std::sin(phi) - p.mgy * std::cos(phi) +
         0.5 * p.lambda_ * (p.B - p.A) * std::sin(2 * phi);
}

/// The turning point nearest φ0 in direction dir (±1): first zero of h − V(φ).
double turning_point(const Pendulum& p, double dir) {
  auto g = [&](double phi) { return p.h - pendulum_potential(p, phi); };
  const double step = 2 * std::numbers::pi / kScanPoints;
  double a = p.phi0;
  for (int i = 1; i <= kScanPoints; ++i) {
    const double b = p.phi0 + dir * step * i;
    if (g(b) < 0) {
      std::uintmax_t iters = 200;
      const auto r = boost::math::tools::toms748_solve(
          g, std::min(a, b), std::max(a, b), boost::math::tools::eps_tolerance<double>(), iters);
      return 0.5 * (r.first + r.second);
    }
    a = b;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

/// φ(α) and dt/dα along the unfolded angle of the quadrature solution.
std::array<double, 2> unfolded(const Pendulum& p, double alpha) {
  if (p.kind == PendulumKind::rotation) {
    const double phi = p.phi0 + p.sense * alpha;
    return {phi, 1.0 / std::sqrt(2 * (p.h - pendulum_potential(p, phi)) / p.C)};
  }
  // φ = c − d cos α written from the nearer turning point φt, and h − V(φ) = V(φt) − V(φ) by
  // product formulas: no cancellation near the turning points, where both sides vanish as α².
  const bool near_low = std::cos(alpha) >= 0;
  const double phit = near_low ? p.c - p.d : p.c + p.d;
  const double half = std::sin(0.5 * alpha), half_c = std::cos(0.5 * alpha);
  const double delta = near_low ? 2 * p.d * half * half : -2 * p.d * half_c * half_c;
  const double phi = phit + delta, sigma = phit + 0.5 * delta;
  const double g = 2 * std::sin(0.5 * delta) * (p.mgx * std::sin(sigma) + p.mgy * std::cos(sigma)) +
                   0.5 * p.lambda_ * (p.A - p.B) * std::sin(2 * sigma) * std::sin(delta);
  const double s = std::abs(std::sin(alpha));
  if (s == 0.0 || g <= 0.0) {  // at a turning point: the limit √(C d / |V′(φ)|)
    return {phi, std::sqrt(p.C * p.d / std::abs(dpotential(p, phi)))};
  }
  return {phi, p.d * s / std::sqrt(2 * g / p.C)};
}

void setup_closed_form(Pendulum& p) {
  const double kappa = p.lambda_ * (p.B - p.A) / p.C;
  if (kappa == 0.0) {
    p.kind = p.r0 == 0.0 ? PendulumKind::equilibrium : PendulumKind::rotation;
    p.period = p.r0 == 0.0 ? std::numeric_limits<double>::infinity()
                           : 2 * std::numbers::pi / std::abs(p.r0);
    return;
  }
  p.omega0 = std::sqrt(std::abs(kappa));
  p.theta0 =
      std::remainder(2 * p.phi0 - (kappa > 0 ? 0.0 : std::numbers::pi), 2 * std::numbers::pi);
  const double s = std::sin(0.5 * p.theta0);
  const double k2 = (p.r0 * p.r0 + p.omega0 * p.omega0 * s * s) / (p.omega0 * p.omega0);
  p.sense = p.r0 < 0 ? -1.0 : 1.0;
  if (k2 == 0.0) {
    p.kind = PendulumKind::equilibrium;
    p.period = std::numeric_limits<double>::infinity();
  } else if (k2 < 1.0) {
    p.kind = PendulumKind::libration;
    p.modulus = std::sqrt(k2);
    const double am = std::atan2(s / p.modulus, p.r0 / (p.modulus * p.omega0));
    p.u0 = boost::math::ellint_1(p.modulus, am);
    p.period = 4 * boost::math::ellint_1(p.modulus) / p.omega0;
    const double half = std::asin(p.modulus);  // θ/2 at the turning points
    p.turning_points = {p.phi0 + (-2 * half - p.theta0) / 2, p.phi0 + (2 * half - p.theta0) / 2};
  } else {
    p.kind = PendulumKind::rotation;
    p.modulus = 1.0 / std::sqrt(k2);
    p.u0 = boost::math::ellint_1(p.modulus, p.sense * 0.5 * p.theta0);
    p.period = 4 * boost::math::ellint_1(p.modulus) * p.modulus / p.omega0;
  }
}

void setup_quadrature(Pendulum& p) {
  // The highest V on the circle: sampled, then the best sample refined by Brent's method.
  double vmax = -std::numeric_limits<double>::infinity(), at = 0;
  for (int i = 0; i < kScanPoints; ++i) {
    const double phi = 2 * std::numbers::pi * i / kScanPoints;
    if (pendulum_potential(p, phi) > vmax) vmax = pendulum_potential(p, phi), at = phi;
  }
  const double step = 2 * std::numbers::pi / kScanPoints;
  const auto best = boost::math::tools::brent_find_minima(
      [&](double phi) { return -pendulum_potential(p, phi); }, at - step, at + step, 52);
  vmax = std::max(vmax, -best.second);
  p.sense = p.r0 < 0 ? -1.0 : 1.0;
  if (p.h > vmax) {
    p.kind = PendulumKind::rotation;
    p.alpha0 = 0.0;
  } else {
    const double lo = turning_point(p, -1.0), hi = turning_point(p, 1.0);
    p.turning_points = {lo, hi};
    if (!(hi - lo > 0)) {
      p.kind = PendulumKind::equilibrium;
      p.period = std::numeric_limits<double>::infinity();
      return;
    }
    p.kind = PendulumKind::libration;
    p.c = 0.5 * (lo + hi);
    p.d = 0.5 * (hi - lo);
    p.alpha0 = std::acos(std::clamp((p.c - p.phi0) / p.d, -1.0, 1.0));
    if (p.r0 < 0) p.alpha0 = 2 * std::numbers::pi - p.alpha0;
  }
  p.period =
      integrate_one_period([&](double a) { return unfolded(p, a)[1]; }, 2 * std::numbers::pi);
}

std::array<double, 2> closed_form_angle(const Pendulum& p, double t) {
  if (p.kind == PendulumKind::equilibrium) return {p.phi0, 0.0};
  if (p.omega0 == 0.0) return {p.phi0 + p.r0 * t, p.r0};
  double cn = 0, dn = 0;
  if (p.kind == PendulumKind::libration) {
    const double sn = boost::math::jacobi_elliptic(p.modulus, p.omega0 * t + p.u0, &cn, &dn);
    const double theta = 2 * std::atan2(p.modulus * sn, dn);
    return {p.phi0 + 0.5 * (theta - p.theta0), p.modulus * p.omega0 * cn};
  }
  const double v = p.omega0 * t / p.modulus + p.u0;
  const double K = boost::math::ellint_1(p.modulus);
  const double n = std::round(v / (2 * K));
  const double sn = boost::math::jacobi_elliptic(p.modulus, v - 2 * K * n, &cn, &dn);
  const double am = std::atan2(sn, cn) + n * std::numbers::pi;
  return {p.phi0 + p.sense * am - 0.5 * p.theta0, p.sense * p.omega0 / p.modulus * dn};
}

std::array<double, 2> quadrature_angle(const Pendulum& p, double t) {
  if (p.kind == PendulumKind::equilibrium) return {p.phi0, 0.0};
  auto G = [&](double a) { return unfolded(p, a)[1]; };
  const double turns = std::floor(t / p.period);
  const double rest = t - turns * p.period;
  // Solve ∫_{α0}^{α0+x} G = rest for x ∈ [0, 2π] by safeguarded Newton.
  double x = 2 * std::numbers::pi * rest / p.period, lo = 0.0, hi = 2 * std::numbers::pi;
  for (int it = 0; it < kPendulumNewtonIterations; ++it) {
    const double f = integrate_interval(G, p.alpha0, p.alpha0 + x) - rest;
    if (f > 0)
      hi = x;
    else
      lo = x;
    double next = x - f / G(p.alpha0 + x);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - x) <= 4 * std::numeric_limits<double>::epsilon() * (1 + x);
    x = next;
    if (done) break;
  }
  const double alpha = p.alpha0 + x + 2 * std::numbers::pi * turns;
  const auto [phi, dt] = unfolded(p, alpha);
  if (p.kind == PendulumKind::rotation) return {phi, p.sense / dt};
  return {phi, p.d * std::sin(alpha) / dt};
}

}  // namespace

std::string to_string(PendulumKind k) {
  switch (k) {
    case PendulumKind::libration:
      return "libration";
    case PendulumKind::rotation:
      return "rotation";
    case PendulumKind::equilibrium:
      return "equilibrium";
  }
  return "equilibrium";
}

double pendulum_potential(const Pendulum& p, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return p.mgx * c - p.mgy * s + 0.5 * p.lambda_ * (p.A * c * c + p.B * s * s);
}

bool pendulum_holds(const QuadraticModel& model, const State& x0, std::string* why) {
  const Body& b = model.body;
  const Vec3 w = omega(b, x0);
  auto fail = [&](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  const double length = std::sqrt(b.inertia().maxCoeff() / std::max(b.mass(), 1e-300));
  if (model.field.g != 0.0 && std::abs(b.center_of_mass().z()) > kPlaneTolerance * length) {
    return fail("the centre of mass is not in the principal plane z0 = 0");
  }
  if (b.gyrostat().x() != 0.0 || b.gyrostat().y() != 0.0) return fail("k1 or k2 is not zero");
  const double wn = std::max(w.norm(), std::numeric_limits<double>::min());
  if (std::abs(w.x()) > kPlaneTolerance * wn || std::abs(w.y()) > kPlaneTolerance * wn ||
      std::abs(x0.gamma.z()) > kPlaneTolerance) {
    return fail("the initial state is not a plane motion (p = q = gamma3 = 0)");
  }
  return true;
}

Pendulum pendulum(const QuadraticModel& model, const State& x0) {
  std::string why;
  if (!pendulum_holds(model, x0, &why)) throw InputError("initial: plane pendulum motion: " + why);
  const Body& b = model.body;
  Pendulum p;
  p.C = b.C();
  p.k3 = b.gyrostat().z();
  p.A = b.A();
  p.B = b.B();
  p.lambda_ = model.field.lambda_;
  p.mgx = b.mass() * model.field.g * b.center_of_mass().x();
  p.mgy = b.mass() * model.field.g * b.center_of_mass().y();
  p.phi0 = std::atan2(-x0.gamma.y(), x0.gamma.x());
  p.r0 = (x0.m.z() - p.k3) / p.C;
  p.h = 0.5 * p.C * p.r0 * p.r0 + pendulum_potential(p, p.phi0);
  p.closed_form = p.mgx == 0.0 && p.mgy == 0.0;
  if (p.closed_form) {
    setup_closed_form(p);
  } else {
    setup_quadrature(p);
  }
  return p;
}

std::array<double, 2> pendulum_angle(const Pendulum& p, double t) {
  return p.closed_form ? closed_form_angle(p, t) : quadrature_angle(p, t);
}

State pendulum_state(const Pendulum& p, double t) {
  const auto [phi, r] = pendulum_angle(p, t);
  return {Vec3(0.0, 0.0, p.C * r + p.k3), Vec3(std::cos(phi), -std::sin(phi), 0.0)};
}

}  // namespace newtop
