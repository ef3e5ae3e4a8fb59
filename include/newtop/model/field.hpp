#pragma once
/// \file
/// The approximate (quadratic) field of docs/model.md §3: V(γ) = M g r0·γ + ½ λ γ·Iγ.

#include "newtop/model/body.hpp"

namespace newtop {

/// Field of a distant centre truncated at 1/R³ (docs/model.md §3). g (field intensity at O) and λ
/// have either sign: Newtonian centre g > 0, λ = 3g/R; Coulomb centre any signs; uniform gravity λ
/// = 0; Brun's field λ = −N. Plain data; use the named constructors to get the checked variants.
struct QuadraticField {
  double g = 0.0;
  double lambda_ = 0.0;

  /// Any (g, λ), both finite (Coulomb centre). Throws InputError otherwise.
  static QuadraticField coulomb(double g, double lambda);
  /// Newtonian centre from the intensity g and distance R > 0: λ = 3g/R.
  static QuadraticField from_g_R(double g, double R);
  /// Newtonian centre from μ = G·M′ > 0 and R > 0: g = μ/R², λ = 3μ/R³.
  static QuadraticField from_mu_R(double mu, double R);
  /// Uniform gravity of intensity g (classical heavy top): λ = 0.
  static QuadraticField uniform(double g);
  /// Brun's field (docs/model.md §3): each element pushed ∝ its mass and its distance to a plane
  /// with unit normal γ, at signed distance d from O along γ. V = ½N ∫ (ρ·γ − d)² dm = −½N γ·Iγ − N
  /// d M r0·γ
  /// + const, i.e. λ = −N and g = −N d (d = 0: the plane passes through O).
  static QuadraticField brun(double N, double plane_offset = 0.0);
};

/// V(γ) = M g r0·γ + ½ λ γ·Iγ (docs/model.md §3), the γ-dependent part of the potential.
inline double potential(const Body& body, const QuadraticField& field, const Vec3& gamma) {
  return body.mass() * field.g * body.center_of_mass().dot(gamma) +
         0.5 * field.lambda_ * gamma.dot(body.inertia().cwiseProduct(gamma));
}

/// ∂V/∂γ = M g r0 + λ Iγ (docs/model.md §4).
inline Vec3 grad_gamma(const Body& body, const QuadraticField& field, const Vec3& gamma) {
  return body.mass() * field.g * body.center_of_mass() +
         field.lambda_ * body.inertia().cwiseProduct(gamma);
}

/// Hessian ∂²V/∂γ² = λ I (constant for the quadratic field).
inline Mat3 hessian_gamma(const Body& body, const QuadraticField& field, const Vec3& /*gamma*/) {
  return field.lambda_ * body.inertia_matrix();
}

/// Moment of the field about O: L = γ × ∂V/∂γ (docs/model.md §2).
inline Vec3 moment(const Body& body, const QuadraticField& field, const Vec3& gamma) {
  return gamma.cross(grad_gamma(body, field, gamma));
}

/// The moment's derivative along δ, (∂L/∂γ) δ = δ × ∂V/∂γ + γ × λ Iδ, without forming ∂L/∂γ.
inline Vec3 moment_derivative(const Body& body, const QuadraticField& field, const Vec3& gamma,
                              const Vec3& delta) {
  return delta.cross(grad_gamma(body, field, gamma)) +
         gamma.cross(field.lambda_ * body.inertia().cwiseProduct(delta));
}

/// Jacobian of the moment, ∂L/∂γ = [γ]× λI − [M g r0 + λ Iγ]× ([v]× the matrix of v × ·).
inline Mat3 moment_jacobian(const Body& body, const QuadraticField& field, const Vec3& gamma) {
  auto cross = [](const Vec3& v) {
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
  };
  return cross(gamma) * hessian_gamma(body, field, gamma) - cross(grad_gamma(body, field, gamma));
}

}  // namespace newtop
