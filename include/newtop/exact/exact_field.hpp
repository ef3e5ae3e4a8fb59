#pragma once
/// \file
/// The exact field of a centre on an extended body (spec §2) and the quantities derived from it:
/// V(γ; R) = −μ ∫ dm / |Rγ + ρ|, ∂V/∂γ, ∂V/∂R, the moment L and the resultant force F.
/// A field here satisfies the Field concept (potential and grad_gamma found by ADL), so every
/// integrator runs in it.

#include <memory>

#include "newtop/exact/mass_models.hpp"
#include "newtop/model/model.hpp"

namespace newtop {

class MassMoments;

/// V, ∂V/∂γ (γ a free vector of R³), ∂V/∂R, L = γ × ∂V/∂γ and
/// F = −(∂V/∂R) γ + (1/R) γ × (γ × ∂V/∂γ) at one γ (spec §2).
struct FieldValues {
  double potential = 0.0;
  Vec3 grad_gamma = Vec3::Zero();
  double dV_dR = 0.0;
  Vec3 moment = Vec3::Zero();
  Vec3 force = Vec3::Zero();
};

/// Completes FieldValues from V, ∂V/∂γ and ∂V/∂R: L = γ × ∂V/∂γ, F = −(∂V/∂R) γ + γ × (γ ×
/// ∂V/∂γ)/R.
FieldValues complete(double V, const Vec3& grad_gamma, double dV_dR, const Vec3& gamma, double R);

/// The exact field of a centre of gravitational parameter μ > 0 at distance R > 0 (position −Rγ
/// in the body frame). `axes` is the rotation P from the body's principal axes to the frame of
/// the mass model (Body::principal_axes()): a body-frame γ is Pγ in the model's frame.
/// `threads` > 1 evaluates a polyhedron in parallel (same bits for any count).
///
/// Far from a polyhedron the closed form loses about ε (R/r)² of V to cancellation (sums of terms
/// of size R·r making one of size r³/R). From R ≥ kFarField·r on (r the body's radius about O),
/// make() therefore sets up the multipole series to the order whose rigorous truncation bound
/// (r/R)^p/(1 − r/R) is below ε/2 of V, and the field is evaluated from it: exact to round-off.
struct ExactField {
  std::shared_ptr<const MassModel> mass_model;
  double mu = 0.0;
  double R = 0.0;
  Mat3 axes = Mat3::Identity();
  int threads = 1;
  /// Far-field series of a polyhedron (null: closed form) and its order.
  std::shared_ptr<const MassMoments> far_moments;
  int far_order = 0;

  static constexpr double kFarField = 16.0;

  /// Checks μ > 0, R > 0 (finite) and that the centre lies outside the sphere about O holding the
  /// body (R > max_radius); throws InputError naming mu or R.
  static ExactField make(std::shared_ptr<const MassModel> model, double mu, double R,
                         const Mat3& axes = Mat3::Identity());
};

/// All exact quantities at γ (body frame): one evaluation of the mass model.
/// V = −μ Φ(−Rγ), ∂V/∂γ = μR ∇Φ(−Rγ), ∂V/∂R = μ γ·∇Φ(−Rγ) with Φ(x) = ∫ dm/|x − ρ|.
FieldValues field_values(const ExactField& field, const Vec3& gamma);

double potential(const Body& body, const ExactField& field, const Vec3& gamma);
Vec3 grad_gamma(const Body& body, const ExactField& field, const Vec3& gamma);
/// ∂V/∂R at fixed γ.
double dV_dR(const Body& body, const ExactField& field, const Vec3& gamma);

/// The body (principal moments, mass, centre of mass; principal axes reported) of a mass model:
/// its mass properties diagonalised by Body::from_tensor.
Body body_of(const MassModel& model, const Vec3& gyrostat = Vec3::Zero());

/// Body and exact field of a mass model in the body's principal axes.
BasicModel<ExactField> exact_model(std::shared_ptr<const MassModel> model, double mu, double R,
                                   const Vec3& gyrostat = Vec3::Zero());

}  // namespace newtop
