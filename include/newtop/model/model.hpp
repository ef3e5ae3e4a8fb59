#pragma once
/// \file
/// Model: the body and the field of a run, whatever the field (docs/model.md §2–§4). The field is a
/// value that is any of the quadratic field of docs/model.md §3, the exact field of a mass model
/// (docs/model.md §2) or its multipole expansion; the body of an exact or multipole field is always
/// the mass model's (one source of mass properties). The steppers and kernels run on the concrete
/// BasicModel<F> that visit_model() hands them, so their loops stay monomorphic.
///
/// The model does not know mass models: the exact field, its multipole expansion and the mass
/// model are plugged in from newtop/exact, and only declared here. A model of such a field is held
/// by a shared pointer to an immutable BasicModel<F> (copies of a Model share it); what must see
/// the field — the factories from a mass model, body(), centre_parameters and the functions of a
/// Model below — is defined beside the fields (src/exact/model_fields.cpp). visit_model is
/// instantiated where the fields are complete: include newtop/exact/model_fields.hpp (or the
/// umbrella newtop/newtop.hpp) to call it.

#include <memory>
#include <type_traits>
#include <utility>
#include <variant>

#include "newtop/model/basic_model.hpp"

namespace newtop {

struct ExactField;      // newtop/exact/exact_field.hpp
struct MultipoleField;  // newtop/exact/multipole.hpp
class MassModel;        // newtop/exact/mass_models.hpp

/// Which field a model has.
enum class FieldKind { quadratic, exact, multipole };

/// "quadratic", "exact" or "multipole".
const char* to_string(FieldKind k);

class Model {
 public:
  /// A model of a field plugged in from newtop/exact: immutable, shared by the copies of a Model.
  /// A struct of its own, so that BasicModel<F> is no template argument of the Variant (argument-
  /// dependent lookup would instantiate it, and nothing here may need the field's definition).
  template <class F>
  struct Shared {
    std::shared_ptr<const BasicModel<F>> model;
  };
  using Variant = std::variant<QuadraticModel, Shared<ExactField>, Shared<MultipoleField>>;

  /// The quadratic field of docs/model.md §3 on a body given by its mass properties.
  Model(const Body& body, const QuadraticField& field) : v_(QuadraticModel{body, field}) {}
  /// The same, from the quadratic view (implicit: a quadratic model is a model).
  Model(const QuadraticModel& m) : v_(m) {}  // NOLINT(google-explicit-constructor)

  /// The quadratic field on the body of a mass model (rotor k).
  static Model quadratic(std::shared_ptr<const MassModel> mass_model, const QuadraticField& field,
                         const Vec3& gyrostat = Vec3::Zero());
  /// The exact field of a centre of parameter μ at distance R on the body of a mass model (rotor
  /// k): ExactField::make's checks, in the body's principal axes.
  static Model exact(std::shared_ptr<const MassModel> mass_model, double mu, double R,
                     const Vec3& gyrostat = Vec3::Zero());
  /// The multipole expansion of order p of that field (MultipoleField::make's checks).
  static Model multipole(std::shared_ptr<const MassModel> mass_model, int order, double mu,
                         double R, const Vec3& gyrostat = Vec3::Zero());

  /// The body: the mass model's for an exact or multipole field.
  const Body& body() const;
  FieldKind kind() const { return static_cast<FieldKind>(v_.index()); }
  /// The field as held: the quadratic model itself, a shared pointer to the others (visit_model
  /// and the accessors of newtop/exact/model_fields.hpp hand out the model itself).
  const Variant& variant() const { return v_; }
  /// The mass model the body derives from; null for a body given by its mass properties.
  const std::shared_ptr<const MassModel>& mass_model() const { return mass_model_; }
  /// The quadratic view; only for kind() == quadratic (std::bad_variant_access otherwise).
  const QuadraticModel& quadratic() const { return std::get<QuadraticModel>(v_); }

 private:
  Model(Variant v, std::shared_ptr<const MassModel> mass_model)
      : v_(std::move(v)), mass_model_(std::move(mass_model)) {}
  Variant v_;
  std::shared_ptr<const MassModel> mass_model_;
};

static_assert(static_cast<int>(FieldKind::exact) == 1 &&
                  static_cast<int>(FieldKind::multipole) == 2,
              "FieldKind follows the order of Model::Variant");

/// The one dispatch of a run: f(const BasicModel<F>&) for the model's field, the concrete model
/// itself (never the pointer that holds it), so that what f runs stays monomorphic. Call it where
/// the fields are complete (newtop/exact/model_fields.hpp).
template <class Fn>
decltype(auto) visit_model(const Model& model, Fn&& f) {
  return std::visit(
      [&f](const auto& held) -> decltype(auto) {
        if constexpr (std::is_same_v<std::decay_t<decltype(held)>, QuadraticModel>) {
          return std::forward<Fn>(f)(held);
        } else {
          return std::forward<Fn>(f)(*held.model);
        }
      },
      model.variant());
}

/// μ and R of an exact or multipole field (μ = 0, R = 0 for the quadratic field).
struct CentreParameters {
  double mu = 0.0, R = 0.0;
  int order = 0;  ///< the multipole order; 0 otherwise
};
CentreParameters centre_parameters(const Model& model);

/// The quadratic model of the same body and centre (g = μ/R², λ = 3μ/R³ for an exact or multipole
/// field; the model itself for the quadratic field): what a command compares with, labelled so.
QuadraticModel quadratic_approximation(const Model& model);

/// V, ∂V/∂γ, ∂²V/∂γ², the moment L, ∂L/∂γ and the right-hand side of the model's own field.
double potential(const Model& model, const Vec3& gamma);
Vec3 grad_gamma(const Model& model, const Vec3& gamma);
Mat3 hessian_gamma(const Model& model, const Vec3& gamma);
Vec3 moment(const Model& model, const Vec3& gamma);
Mat3 moment_jacobian(const Model& model, const Vec3& gamma);
State rhs(const Model& model, const State& s);

}  // namespace newtop
