// Point masses: validation, mass properties, and the field by direct sums written without the
// far field's cancellation (docs/exact_field.md, "Accuracy far from the body").

#include <cmath>
#include <string>

#include "detail.hpp"
#include "newtop/exact/mass_models.hpp"

namespace newtop {

PointMasses::PointMasses(std::vector<double> masses, std::vector<Vec3> positions)
    : masses_(std::move(masses)), positions_(std::move(positions)) {
  if (masses_.empty() || masses_.size() != positions_.size()) {
    throw InputError("points: expected at least one point mass [m, x, y, z], found " +
                     std::to_string(masses_.size()) + " masses and " +
                     std::to_string(positions_.size()) + " positions");
  }
  double mass = 0.0, second = 0.0;
  detail::DoubleDouble first[3];
  for (std::size_t i = 0; i < masses_.size(); ++i) {
    if (!std::isfinite(masses_[i]) || !(masses_[i] > 0)) {
      throw InputError("points: point " + std::to_string(i) + ": expected a mass > 0, found " +
                       format_number(masses_[i]));
    }
    if (!positions_[i].allFinite()) {
      throw InputError("points: point " + std::to_string(i) +
                       ": expected finite coordinates, found " + format_vector(positions_[i]));
    }
    mass += masses_[i];
    second += masses_[i] * positions_[i].squaredNorm();
    for (int k = 0; k < 3; ++k)
      first[k] = first[k] + detail::two_prod(masses_[i], positions_[i][k]);
  }
  // Σ m and Σ m |ρ|² bound every mass property (|D| ≤ √(M Σ m|ρ|²), |J| ≤ 2 Σ m|ρ|²).
  if (!std::isfinite(mass)) {
    throw InputError("points: the total mass overflows (sum of " + std::to_string(masses_.size()) +
                     " masses = " + format_number(mass) + ")");
  }
  if (!std::isfinite(second)) {
    throw InputError("points: the inertia tensor overflows (sum of m |rho|^2 = " +
                     format_number(second) + "): masses or coordinates too large");
  }
  first_moment_ = Vec3(first[0].value(), first[1].value(), first[2].value());
}

MassProperties mass_properties(const PointMasses& p) {
  MassProperties mp;
  for (std::size_t i = 0; i < p.masses().size(); ++i) {
    const Vec3& c = p.positions()[i];
    mp.mass += p.masses()[i];
    mp.inertia_tensor += p.masses()[i] * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  }
  mp.center_of_mass = p.first_moment() / mp.mass;
  return mp;
}

// In units of s = |x|: x̂ = x/s, ρ̃ = ρ/s, t = |ρ̃|² − 2 x̂·ρ̃ (so d² = s² (1 + t)). Every sum below
// has terms of the size of its result; the powers of 1/s are applied last.
Attraction attraction(const PointMasses& p, const Vec3& x) {
  const double s = x.norm();
  if (s == 0.0) {  // at O: Φ and ∇Φ by the plain sums, no moment arm
    Attraction a;
    for (std::size_t i = 0; i < p.masses().size(); ++i) {
      const double r = p.positions()[i].norm();
      a.potential += p.masses()[i] / r;
      a.gradient += (p.masses()[i] / (r * r * r)) * p.positions()[i];
    }
    return a;
  }
  const Vec3 xs = x / s;
  double phi = 0.0;
  Vec3 grad = Vec3::Zero(), dip = Vec3::Zero();
  for (std::size_t i = 0; i < p.masses().size(); ++i) {
    const double m = p.masses()[i];
    const Vec3 rho = p.positions()[i] / s;
    const detail::InversePowers w = detail::inverse_powers(rho.squaredNorm() - 2.0 * xs.dot(rho));
    phi += m / w.w;
    grad += (m * w.inv_w3) * (rho - xs);
    dip += (m * w.minus_1_3) * rho;
  }
  Attraction a;
  a.potential = phi / s;
  a.gradient = grad / s / s;
  a.moment = (p.first_moment() / s + dip).cross(xs) / s;
  return a;
}

GravityGradient gravity_gradient(const PointMasses& p, const Vec3& x) {
  const double s = x.norm();
  const Vec3 xs = x / s;
  Mat3 T = Mat3::Zero(), outer = Mat3::Zero();
  Vec3 dip3 = Vec3::Zero(), dip5 = Vec3::Zero();
  for (std::size_t i = 0; i < p.masses().size(); ++i) {
    const double m = p.masses()[i];
    const Vec3 rho = p.positions()[i] / s;
    const detail::InversePowers w = detail::inverse_powers(rho.squaredNorm() - 2.0 * xs.dot(rho));
    const Vec3 e = xs - rho;
    T += (3.0 * m * w.inv_w5) * (e * e.transpose());
    T.diagonal().array() -= m * w.inv_w3;
    dip3 += (m * w.minus_1_3) * rho;
    dip5 += (m * w.minus_1_5) * rho;
    outer += (m * w.inv_w5) * (rho.cross(xs) * rho.transpose());
  }
  // Σ m ρ/d³ = (D/s + Σ m ρ̃ (w⁻³ − 1))/s², Σ m ρ/d⁵ likewise with w⁻⁵ and 1/s⁴.
  const Vec3 D = p.first_moment() / s;
  GravityGradient g;
  g.tensor = T / s / s / s;
  g.moment_jacobian = (detail::cross_matrix(D + dip3) -
                       3.0 * ((D + dip5).cross(xs) * xs.transpose()) + 3.0 * outer) /
                      s / s;
  return g;
}

MomentAndDerivative moment_with_derivative(const PointMasses& p, const Vec3& x, const Vec3& u) {
  const double s = x.norm();
  if (s == 0.0) return {Vec3::Zero(), attraction(p, x).gradient.cross(u)};  // Jm = [∇Φ]× at O
  const Vec3 xs = x / s;
  Vec3 dip3 = Vec3::Zero(), dip5 = Vec3::Zero(), q = Vec3::Zero();
  for (std::size_t i = 0; i < p.masses().size(); ++i) {
    const double m = p.masses()[i];
    const Vec3 rho = p.positions()[i] / s;
    const detail::InversePowers w = detail::inverse_powers(rho.squaredNorm() - 2.0 * xs.dot(rho));
    dip3 += (m * w.minus_1_3) * rho;
    dip5 += (m * w.minus_1_5) * rho;
    q += (m * w.inv_w5 * rho.dot(u)) * rho;
  }
  const Vec3 D = p.first_moment() / s;
  MomentAndDerivative r;
  r.moment = (D + dip3).cross(xs) / s;
  r.derivative =
      ((D + dip3).cross(u) - 3.0 * xs.dot(u) * (D + dip5).cross(xs) + 3.0 * q.cross(xs)) / s / s;
  return r;
}

}  // namespace newtop
