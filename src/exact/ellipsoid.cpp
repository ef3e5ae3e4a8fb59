// Homogeneous ellipsoid: validation, mass properties, and the field in Carlson's symmetric
// elliptic integrals (Boost.Math).

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "detail.hpp"
#include "newtop/exact/mass_models.hpp"

namespace newtop {
namespace {

void check_finite(const char* name, const Vec3& v) {
  if (!v.allFinite()) {
    throw InputError(std::string(name) + ": expected finite numbers, found " + format_vector(v));
  }
}

/// The confocal parameter λ ≥ 0 of x (0 inside): the largest root of Σ u_i²/(a_i² + λ) = 1. It lies
/// in [|u|² − max a², |u|² − min a²]; with λ = |u|² − ν the equation becomes
/// ψ(ν) = Σ u_i² (ν − a_i²)/(a_i² + λ) = 0, ψ increasing, ψ(min a²) ≤ 0 ≤ ψ(min(max a², |u|²)):
/// a bracket of width ≤ max a² − min a² that stays well conditioned however far x is (the
/// equation in λ itself is flat, to round-off, over a bracket of width |u|² far away).
/// Returns q = a² + λ.
Vec3 confocal(const Vec3& u, const Vec3& a2) {
  const double U = u.squaredNorm();
  if (!(u.cwiseAbs2().cwiseQuotient(a2).sum() > 1.0)) return a2;
  auto psi = [&](double nu) {
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += u[i] * u[i] * (nu - a2[i]) / ((U - nu) + a2[i]);
    return s;
  };
  const double lo = a2.minCoeff(), hi = std::min(a2.maxCoeff(), U);
  double nu = lo;
  if (psi(lo) < 0) {
    if (!(psi(hi) > 0)) {
      nu = hi;
    } else {
      std::uintmax_t iters = 200;
      const auto root = boost::math::tools::toms748_solve(
          psi, lo, hi, boost::math::tools::eps_tolerance<double>(52), iters);
      nu = 0.5 * (root.first + root.second);
    }
  }
  const double lambda = std::max(U - nu, 0.0);
  return a2 + Vec3::Constant(lambda);
}

struct Carlson {
  Vec3 u, q, rd;  // u = x − centre, q = a² + λ, rd_i = R_D(q_j, q_k, q_i)
  double k;       // πσabc
  bool outside;
};

Carlson carlson(const Ellipsoid& e, const Vec3& x) {
  using boost::math::ellint_rd;
  Carlson c;
  c.u = x - e.center;
  const Vec3 a2 = e.semi_axes.cwiseAbs2();
  c.q = confocal(c.u, a2);
  c.outside = c.q != a2;
  c.rd = Vec3(ellint_rd(c.q.y(), c.q.z(), c.q.x()), ellint_rd(c.q.z(), c.q.x(), c.q.y()),
              ellint_rd(c.q.x(), c.q.y(), c.q.z()));
  c.k = std::numbers::pi * e.density * e.semi_axes.prod();
  return c;
}

}  // namespace

Ellipsoid Ellipsoid::make(const Vec3& semi_axes, double density, const Vec3& center) {
  check_finite("semi_axes", semi_axes);
  if (!(semi_axes.minCoeff() > 0)) {
    throw InputError("semi_axes: expected three lengths > 0, found " + format_vector(semi_axes));
  }
  if (!std::isfinite(density) || !(density > 0)) {
    throw InputError("density: expected a finite number > 0, found " + format_number(density));
  }
  check_finite("center", center);
  const double volume = 4.0 / 3.0 * std::numbers::pi * semi_axes.prod();
  if (!std::isfinite(volume) || !std::isfinite(semi_axes.squaredNorm())) {
    throw InputError("semi_axes: the volume overflows, found " + format_vector(semi_axes));
  }
  const double M = density * volume;
  if (!std::isfinite(M)) {
    throw InputError("density: the mass density * volume overflows (" + format_number(density) +
                     " * " + format_number(volume) + ")");
  }
  if (!std::isfinite(M * semi_axes.squaredNorm())) {
    throw InputError("semi_axes: the inertia tensor M (a^2 + b^2)/5 overflows (M = " +
                     format_number(M) + ", semi_axes = " + format_vector(semi_axes) + ")");
  }
  if (!std::isfinite(M * center.squaredNorm())) {
    throw InputError("center: the inertia tensor about O overflows (M |center|^2 with M = " +
                     format_number(M) + ", center = " + format_vector(center) + ")");
  }
  return {semi_axes, density, center};
}

MassProperties mass_properties(const Ellipsoid& e) {
  const Vec3 s2 = e.semi_axes.cwiseAbs2();
  const Vec3& c = e.center;
  MassProperties mp;
  mp.mass = e.density * 4.0 / 3.0 * std::numbers::pi * e.semi_axes.prod();
  mp.center_of_mass = c;
  const Vec3 Jc = mp.mass / 5.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
  mp.inertia_tensor =
      Mat3(Jc.asDiagonal()) + mp.mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  return mp;
}

Attraction attraction(const Ellipsoid& e, const Vec3& x) {
  const Carlson c = carlson(e, x);
  // The potential is stationary in λ, so ∇Φ has no term from ∂λ/∂x.
  Attraction a;
  a.potential = c.k * (2.0 * boost::math::ellint_rf(c.q.x(), c.q.y(), c.q.z()) -
                       2.0 / 3.0 * c.u.cwiseAbs2().dot(c.rd));
  a.gradient = -(4.0 / 3.0) * c.k * c.u.cwiseProduct(c.rd);
  a.moment = a.gradient.cross(x);
  return a;
}

GravityGradient gravity_gradient(const Ellipsoid& e, const Vec3& x) {
  const Carlson c = carlson(e, x);
  GravityGradient g;
  g.tensor = Mat3((-(4.0 / 3.0) * c.k * c.rd).asDiagonal());
  if (c.outside) {
    const Vec3 uq = c.u.cwiseQuotient(c.q);
    g.tensor += (4.0 * c.k / (std::sqrt(c.q.prod()) * uq.squaredNorm())) * (uq * uq.transpose());
  }
  const Vec3 grad = -(4.0 / 3.0) * c.k * c.u.cwiseProduct(c.rd);
  g.moment_jacobian = detail::cross_matrix(grad) - detail::cross_matrix(x) * g.tensor;
  return g;
}

}  // namespace newtop
