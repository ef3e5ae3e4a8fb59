#pragma once
/// \file
/// The exact field of a centre on an extended body (docs/model.md §2) and the quantities derived
/// from it: V(γ; R) = −μ ∫ dm / |Rγ + ρ|, ∂V/∂γ, ∂V/∂R, the moment L, the resultant force F, the
/// Hessian ∂²V/∂γ² and the moment's Jacobian ∂L/∂γ. A field here satisfies the Field concept
/// (potential and grad_gamma found by ADL) and has its own moment(), so every integrator runs in
/// it.

#include <memory>

#include "newtop/exact/attraction.hpp"
#include "newtop/exact/mass_models.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

class MassMoments;

/// V, ∂V/∂γ (γ a free vector of R³), ∂V/∂R, L = γ × ∂V/∂γ and
/// F = −(∂V/∂R) γ + (1/R) γ × (γ × ∂V/∂γ) at one γ (docs/model.md §2).
struct FieldValues {
  double potential = 0.0;
  Vec3 grad_gamma = Vec3::Zero();
  double dV_dR = 0.0;
  Vec3 moment = Vec3::Zero();
  Vec3 force = Vec3::Zero();
};

/// The quantities of docs/model.md §2 at γ from the attraction at x = −R P γ (P = axes): V = −μΦ,
/// ∂V/∂γ = μR Pᵀ∇Φ, ∂V/∂R = μ (Pγ)·∇Φ, L = μ Pᵀ (∇Φ × x) (the attraction's cancellation-free
/// moment), F = −(∂V/∂R) γ + γ × L / R (= −(∂V/∂R) γ + γ × (γ × ∂V/∂γ)/R).
FieldValues field_values_at(const Attraction& a, double mu, double R, const Mat3& axes,
                            const Vec3& gamma);

/// The exact field of a centre of gravitational parameter μ > 0 at distance R > 0 (position −Rγ
/// in the body frame). `axes` is the rotation P from the body's principal axes to the frame of
/// the mass model (Body::principal_axes()): a body-frame γ is Pγ in the model's frame.
/// `threads` > 1 evaluates a polyhedron in parallel (same bits for any count).
///
/// The moment L = γ × ∂V/∂γ is formed without the cancellation of the cross product (∂V/∂γ is
/// nearly radial, ≈ μM/R, while L is (r/R)² smaller): point masses by sums written without
/// subtraction, the series with the monopole left out analytically (docs/exact_field.md).
///
/// Far from a polyhedron or an ellipsoid the closed forms lose about ε (R/r)² of V (sums of terms
/// of size R·r making one of size r³/R) and more of the moment. From R ≥ kFarField·r on (r the
/// body's radius about O), make() therefore sets up the multipole series to the order p whose
/// rigorous truncation bound (r/R)^(p−2)/(1 − r/R) is below ε/2 (of V, and of the moment
/// relative to its quadrupole scale), and the field is evaluated from it: exact to round-off.
struct ExactField {
  std::shared_ptr<const MassModel> mass_model;
  double mu = 0.0;
  double R = 0.0;
  Mat3 axes = Mat3::Identity();
  int threads = 1;
  /// Far-field series of a polyhedron or ellipsoid (null: closed form) and its order.
  std::shared_ptr<const MassMoments> far_moments;
  int far_order = 0;

  static constexpr double kFarField = 4.0;

  /// Checks μ > 0 and R > 0 (finite), that the centre lies outside the sphere about O holding
  /// the body (R > max_radius), and that every derived quantity is a finite, normal number
  /// (check_field). Throws InputError naming mu or R.
  static ExactField make(std::shared_ptr<const MassModel> model, double mu, double R,
                         const Mat3& axes = Mat3::Identity());
};

/// The checks of ExactField::make for a field of μ and R about a mass model: μ > 0 and R > 0
/// finite, R > max_radius, and every derived quantity finite and normal: V, ∂V/∂γ and ∂²V/∂γ²
/// (of order μM/R), ∂V/∂R and F (μM/R²), the terms of the sums (M/R³), and the moment (μ|J|/R³,
/// J the inertia tensor at O). Throws InputError naming mu or R.
void check_field(const MassModel& model, double mu, double R);

/// All exact quantities at γ (body frame): one evaluation of the mass model.
/// V = −μ Φ(−Rγ), ∂V/∂γ = μR ∇Φ(−Rγ), ∂V/∂R = μ γ·∇Φ(−Rγ) with Φ(x) = ∫ dm/|x − ρ|.
FieldValues field_values(const ExactField& field, const Vec3& gamma);

double potential(const Body& body, const ExactField& field, const Vec3& gamma);
Vec3 grad_gamma(const Body& body, const ExactField& field, const Vec3& gamma);
/// ∂V/∂R at fixed γ.
double dV_dR(const Body& body, const ExactField& field, const Vec3& gamma);
/// L = γ × ∂V/∂γ = μ Pᵀ (∇Φ × x) at x = −RPγ, without the far field's cancellation (see
/// ExactField). Found by ADL, it is what moment(model, γ), the equations of motion and the
/// splitting's kick use.
Vec3 moment(const Body& body, const ExactField& field, const Vec3& gamma);
/// ∂²V/∂γ² = −μR² Pᵀ ∇∇Φ(−RPγ) P (γ a free vector of R³): point masses by sums, the polyhedron's
/// gravity-gradient tensor in closed form (Werner–Scheeres) or its far-field series, the ellipsoid
/// in Carlson's integrals or its series.
Mat3 hessian_gamma(const Body& body, const ExactField& field, const Vec3& gamma);
/// ∂L/∂γ = [γ]× ∂²V/∂γ² − [∂V/∂γ]× (the linearisation of the moment: stability, tangent maps),
/// formed without the monopole's cancellation (its contribution is exactly zero) for point masses
/// and the far-field series; from the closed forms near a polyhedron or an ellipsoid.
Mat3 moment_jacobian(const Body& body, const ExactField& field, const Vec3& gamma);
/// L and (∂L/∂γ) δ together (a kick with one tangent vector): one pass over point masses, L bit for
/// bit as moment(body, field, γ); the other models by their moment and Jacobian.
MomentAndDerivative moment_with_derivative(const Body& body, const ExactField& field,
                                           const Vec3& gamma, const Vec3& delta);

/// The body (principal moments, mass, centre of mass; principal axes reported) of a mass model:
/// its mass properties diagonalised by Body::from_tensor.
Body body_of(const MassModel& model, const Vec3& gyrostat = Vec3::Zero());

/// Body and exact field of a mass model in the body's principal axes.
BasicModel<ExactField> exact_model(std::shared_ptr<const MassModel> model, double mu, double R,
                                   const Vec3& gyrostat = Vec3::Zero());

}  // namespace newtop
