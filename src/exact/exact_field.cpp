#include "newtop/exact/exact_field.hpp"

#include <cmath>

namespace newtop {

FieldValues complete(double V, const Vec3& grad, double dV_dR, const Vec3& gamma, double R) {
  FieldValues v{V, grad, dV_dR, gamma.cross(grad), Vec3::Zero()};
  v.force = -dV_dR * gamma + gamma.cross(gamma.cross(grad)) / R;
  return v;
}

ExactField ExactField::make(std::shared_ptr<const MassModel> model, double mu, double R,
                            const Mat3& axes) {
  if (!std::isfinite(mu) || !(mu > 0)) {
    throw InputError("mu: expected a finite number > 0, found " + format_number(mu));
  }
  const double r = max_radius(*model);
  if (!std::isfinite(R) || !(R > r)) {
    throw InputError("R: expected a distance greater than the body's radius about O (" +
                     format_number(r) + "), found " + format_number(R));
  }
  return {std::move(model), mu, R, axes, 1};
}

FieldValues field_values(const ExactField& f, const Vec3& gamma) {
  const Vec3 gm = f.axes * gamma;
  const Attraction a = attraction(*f.mass_model, -f.R * gm, f.threads);
  return complete(-f.mu * a.potential, f.mu * f.R * (f.axes.transpose() * a.gradient),
                  f.mu * gm.dot(a.gradient), gamma, f.R);
}

double potential(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  return -f.mu * attraction(*f.mass_model, -f.R * (f.axes * gamma), f.threads).potential;
}

Vec3 grad_gamma(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  const Attraction a = attraction(*f.mass_model, -f.R * (f.axes * gamma), f.threads);
  return f.mu * f.R * (f.axes.transpose() * a.gradient);
}

double dV_dR(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  const Vec3 gm = f.axes * gamma;
  return f.mu * gm.dot(attraction(*f.mass_model, -f.R * gm, f.threads).gradient);
}

Body body_of(const MassModel& model, const Vec3& gyrostat) {
  const MassProperties mp = mass_properties(model);
  return Body::from_tensor(mp.inertia_tensor, mp.mass, mp.center_of_mass, gyrostat);
}

BasicModel<ExactField> exact_model(std::shared_ptr<const MassModel> model, double mu, double R,
                                   const Vec3& gyrostat) {
  Body body = body_of(*model, gyrostat);
  ExactField field = ExactField::make(std::move(model), mu, R, body.principal_axes());
  return {std::move(body), std::move(field)};
}

}  // namespace newtop
