#include "newtop/model/model.hpp"

namespace newtop {

const char* to_string(FieldKind k) {
  switch (k) {
    case FieldKind::exact:
      return "exact";
    case FieldKind::multipole:
      return "multipole";
    case FieldKind::quadratic:
      break;
  }
  return "quadratic";
}

Model Model::quadratic(std::shared_ptr<const MassModel> mass_model, const QuadraticField& field,
                       const Vec3& gyrostat) {
  const Body body = body_of(*mass_model, gyrostat);
  return Model(QuadraticModel{body, field}, std::move(mass_model));
}

Model Model::exact(std::shared_ptr<const MassModel> mass_model, double mu, double R,
                   const Vec3& gyrostat) {
  const Body body = body_of(*mass_model, gyrostat);
  ExactField f = ExactField::make(mass_model, mu, R, body.principal_axes());
  return Model(BasicModel<ExactField>{body, std::move(f)}, std::move(mass_model));
}

Model Model::multipole(std::shared_ptr<const MassModel> mass_model, int order, double mu, double R,
                       const Vec3& gyrostat) {
  const Body body = body_of(*mass_model, gyrostat);
  MultipoleField f = MultipoleField::make(*mass_model, order, mu, R, body.principal_axes());
  return Model(BasicModel<MultipoleField>{body, std::move(f)}, std::move(mass_model));
}

CentreParameters centre_parameters(const Model& model) {
  if (const auto* e = std::get_if<BasicModel<ExactField>>(&model.variant())) {
    return {e->field.mu, e->field.R, 0};
  }
  if (const auto* m = std::get_if<BasicModel<MultipoleField>>(&model.variant())) {
    return {m->field.mu, m->field.R, m->field.order};
  }
  return {};
}

QuadraticModel quadratic_approximation(const Model& model) {
  if (model.kind() == FieldKind::quadratic) return model.quadratic();
  const CentreParameters c = centre_parameters(model);
  return {model.body(), QuadraticField::from_mu_R(c.mu, c.R)};
}

double potential(const Model& model, const Vec3& gamma) {
  return visit_model(model, [&](const auto& m) { return potential(m, gamma); });
}

Vec3 grad_gamma(const Model& model, const Vec3& gamma) {
  return visit_model(model, [&](const auto& m) -> Vec3 { return grad_gamma(m, gamma); });
}

Mat3 hessian_gamma(const Model& model, const Vec3& gamma) {
  return visit_model(model, [&](const auto& m) -> Mat3 { return hessian_gamma(m, gamma); });
}

Vec3 moment(const Model& model, const Vec3& gamma) {
  return visit_model(model, [&](const auto& m) -> Vec3 { return moment(m, gamma); });
}

Mat3 moment_jacobian(const Model& model, const Vec3& gamma) {
  return visit_model(model, [&](const auto& m) -> Mat3 { return moment_jacobian(m, gamma); });
}

State rhs(const Model& model, const State& s) {
  return visit_model(model, [&](const auto& m) { return rhs(m, s); });
}

}  // namespace newtop
