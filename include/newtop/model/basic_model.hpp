#pragma once
/// \file
/// BasicModel<F> (body + one concrete field) and State (m, γ) of the Euler–Poisson equations
/// (docs/model.md §4): the monomorphic view the steppers and kernels run on. newtop/model/model.hpp
/// holds Model, the model of a run whatever its field.

#include <concepts>

#include "newtop/model/body.hpp"
#include "newtop/model/field.hpp"

namespace newtop {

/// A field is anything with free functions potential(body, field, γ) and grad_gamma(body, field, γ)
/// found by argument-dependent lookup: V(γ) and ∂V/∂γ regarded as functions of a free vector γ.
template <class F>
concept Field = requires(const Body& b, const F& f, const Vec3& g) {
  { potential(b, f, g) } -> std::convertible_to<double>;
  { grad_gamma(b, f, g) } -> std::convertible_to<Vec3>;
};

/// Body plus one concrete field: pure data, immutable by convention. A view: the body of an
/// exact or multipole field must be the mass model's (Model's factories see to it). F is checked
/// to be a Field where a BasicModel<F> is made (the class is instantiated), not where it is named:
/// Model names BasicModel<ExactField> of a field it only declares (newtop/model/model.hpp).
template <class F>
struct BasicModel {
  static_assert(Field<F>, "BasicModel<F>: F needs potential(body, F, gamma) and grad_gamma");
  Body body;
  F field;
};

/// The model of the book: the quadratic field of docs/model.md §3 (closed forms, the integrals of
/// docs/model.md §5, the analytic cases).
using QuadraticModel = BasicModel<QuadraticField>;

/// Phase-space point of the Lie–Poisson form (docs/model.md §4): angular momentum m = Iω + k and
/// the unit vector γ along O′→O, both in the body frame. Time travels beside it.
struct State {
  Vec3 m = Vec3::Zero();
  Vec3 gamma = Vec3::UnitZ();

  bool operator==(const State&) const = default;
};

/// ω = I⁻¹(m − k) = ∂H/∂m.
inline Vec3 omega(const Body& body, const State& s) {
  return (s.m - body.gyrostat()).cwiseQuotient(body.inertia());
}

/// State from the angular velocity ω and γ: m = Iω + k.
inline State state_from_omega(const Body& body, const Vec3& omega, const Vec3& gamma) {
  return {body.inertia().cwiseProduct(omega) + body.gyrostat(), gamma};
}

template <Field F>
double potential(const BasicModel<F>& model, const Vec3& gamma) {
  return potential(model.body, model.field, gamma);
}

template <Field F>
Vec3 grad_gamma(const BasicModel<F>& model, const Vec3& gamma) {
  return grad_gamma(model.body, model.field, gamma);
}

/// ∂²V/∂γ² (γ a free vector of R³), for a field with its own hessian_gamma(body, field, γ).
template <Field F>
Mat3 hessian_gamma(const BasicModel<F>& model, const Vec3& gamma) {
  return hessian_gamma(model.body, model.field, gamma);
}

/// ∂L/∂γ, for a field with its own moment_jacobian(body, field, γ).
template <Field F>
Mat3 moment_jacobian(const BasicModel<F>& model, const Vec3& gamma) {
  return moment_jacobian(model.body, model.field, gamma);
}

/// (∂L/∂γ) δ, the derivative of the moment along δ (a tangent vector's kick): the field's own
/// moment_derivative(body, field, γ, δ) where it has one (the quadratic field: no Jacobian
/// formed), moment_jacobian(model, γ) δ otherwise.
template <Field F>
Vec3 moment_derivative(const BasicModel<F>& model, const Vec3& gamma, const Vec3& delta) {
  if constexpr (requires { moment_derivative(model.body, model.field, gamma, delta); }) {
    return moment_derivative(model.body, model.field, gamma, delta);
  } else {
    return moment_jacobian(model, gamma) * delta;
  }
}

/// A field that forms L(γ) and (∂L/∂γ) δ in one pass, moment_with_derivative(body, field, γ, δ)
/// (point masses).
template <class F>
concept FieldWithMomentDerivative = Field<F> &&
    requires(const Body& b, const F& f, const Vec3& g, const Vec3& d) {
  { moment_with_derivative(b, f, g, d) } -> std::convertible_to<MomentAndDerivative>;
};

/// L(γ) and (∂L/∂γ) δ together: the field's own pass where it has one, moment and
/// moment_derivative otherwise.
template <Field F>
MomentAndDerivative moment_with_derivative(const BasicModel<F>& model, const Vec3& gamma,
                                           const Vec3& delta);

/// A field with its own moment(body, field, γ) (found by ADL): one formed without the
/// cancellation of γ × ∂V/∂γ, whose normal part can exceed the moment by (R/r)² far from the body
/// (newtop/exact/exact_field.hpp).
template <class F>
concept FieldWithMoment = Field<F> && requires(const Body& b, const F& f, const Vec3& g) {
  { moment(b, f, g) } -> std::convertible_to<Vec3>;
};

/// Moment about O, L = γ × ∂V/∂γ (docs/model.md §2), for any field: the field's own moment where it
/// has one, the cross product otherwise.
template <Field F>
Vec3 moment(const BasicModel<F>& model, const Vec3& gamma) {
  if constexpr (FieldWithMoment<F>) {
    return moment(model.body, model.field, gamma);
  } else {
    return gamma.cross(grad_gamma(model.body, model.field, gamma));
  }
}

template <Field F>
MomentAndDerivative moment_with_derivative(const BasicModel<F>& model, const Vec3& gamma,
                                           const Vec3& delta) {
  if constexpr (requires { moment_with_derivative(model.body, model.field, gamma, delta); }) {
    return moment_with_derivative(model.body, model.field, gamma, delta);
  } else {
    return {moment(model, gamma), moment_derivative(model, gamma, delta)};
  }
}

/// Time derivative of the state (docs/model.md §4): ṁ = m × ω + γ × ∂V/∂γ, γ̇ = γ × ω, with ω =
/// I⁻¹(m − k). Equivalent to I ω̇ + ω × (Iω + k) = γ × ∂V/∂γ, γ̇ + ω × γ = 0.
template <Field F>
State rhs(const BasicModel<F>& model, const State& s) {
  const Vec3 w = omega(model.body, s);
  return {s.m.cross(w) + moment(model, s.gamma), s.gamma.cross(w)};
}

}  // namespace newtop
