// The exact and multipole fields plugged into Model (model_fields.hpp): the factories from a mass
// model, and Model's functions that must see those fields (declared in newtop/model/model.hpp and
// newtop/model/integrals.hpp, which only declare the fields).

#include "newtop/exact/model_fields.hpp"

#include <string>

#include "newtop/model/integrals.hpp"

namespace newtop {
namespace {

template <class F>
Model::Shared<F> shared(const Body& body, F field) {
  return {std::make_shared<const BasicModel<F>>(BasicModel<F>{body, std::move(field)})};
}

template <class F>
const BasicModel<F>* held(const Model& model) {
  const auto* p = std::get_if<Model::Shared<F>>(&model.variant());
  return p ? p->model.get() : nullptr;
}

template <class F>
const BasicModel<F>& held_or_throw(const Model& model, const char* expected) {
  const BasicModel<F>* m = held<F>(model);
  if (!m) {
    throw InputError(std::string("model: expected ") + expected + " field, found a " +
                     to_string(model.kind()) + " one");
  }
  return *m;
}

}  // namespace

Model Model::quadratic(std::shared_ptr<const MassModel> mass_model, const QuadraticField& field,
                       const Vec3& gyrostat) {
  const Body body = body_of(*mass_model, gyrostat);
  return Model(QuadraticModel{body, field}, std::move(mass_model));
}

Model Model::exact(std::shared_ptr<const MassModel> mass_model, double mu, double R,
                   const Vec3& gyrostat) {
  const Body body = body_of(*mass_model, gyrostat);
  ExactField f = ExactField::make(mass_model, mu, R, body.principal_axes());
  return Model(shared(body, std::move(f)), std::move(mass_model));
}

Model Model::multipole(std::shared_ptr<const MassModel> mass_model, int order, double mu, double R,
                       const Vec3& gyrostat) {
  const Body body = body_of(*mass_model, gyrostat);
  MultipoleField f = MultipoleField::make(*mass_model, order, mu, R, body.principal_axes());
  return Model(shared(body, std::move(f)), std::move(mass_model));
}

const Body& Model::body() const {
  return visit_model(*this, [](const auto& m) -> const Body& { return m.body; });
}

const ExactField* exact_field(const Model& model) {
  const auto* m = held<ExactField>(model);
  return m ? &m->field : nullptr;
}

const MultipoleField* multipole_field(const Model& model) {
  const auto* m = held<MultipoleField>(model);
  return m ? &m->field : nullptr;
}

const BasicModel<ExactField>& exact_model(const Model& model) {
  return held_or_throw<ExactField>(model, "an exact");
}

const BasicModel<MultipoleField>& multipole_model(const Model& model) {
  return held_or_throw<MultipoleField>(model, "a multipole");
}

CentreParameters centre_parameters(const Model& model) {
  if (const ExactField* e = exact_field(model)) return {e->mu, e->R, 0};
  if (const MultipoleField* m = multipole_field(model)) return {m->mu, m->R, m->order};
  return {};
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

double energy(const Model& model, const State& s) {
  return visit_model(model, [&](const auto& m) { return energy(m, s); });
}

IntegralValues integrals(const Model& model, const State& s) {
  return visit_model(model, [&](const auto& m) { return integrals(m, s); });
}

}  // namespace newtop
