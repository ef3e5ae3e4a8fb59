#include "newtop/exact/exact_field.hpp"

#include <cmath>
#include <limits>

#include "newtop/exact/multipole.hpp"

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
  ExactField f{std::move(model), mu, R, axes, 1, nullptr, 0};
  if (std::holds_alternative<Polyhedron>(*f.mass_model) && R >= kFarField * r) {
    const double q = r / R, eps = std::numeric_limits<double>::epsilon();
    f.far_order = static_cast<int>(std::ceil(std::log(0.5 * eps * (1 - q)) / std::log(q)));
    f.far_moments = std::make_shared<const MassMoments>(*f.mass_model, f.far_order);
  }
  return f;
}

namespace {

Attraction attraction_at(const ExactField& f, const Vec3& x) {
  if (f.far_moments) return multipole_attraction(*f.far_moments, f.far_order, x);
  return attraction(*f.mass_model, x, f.threads);
}

}  // namespace

FieldValues field_values(const ExactField& f, const Vec3& gamma) {
  const Vec3 gm = f.axes * gamma;
  const Attraction a = attraction_at(f, -f.R * gm);
  return complete(-f.mu * a.potential, f.mu * f.R * (f.axes.transpose() * a.gradient),
                  f.mu * gm.dot(a.gradient), gamma, f.R);
}

double potential(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  return -f.mu * attraction_at(f, -f.R * (f.axes * gamma)).potential;
}

Vec3 grad_gamma(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  const Attraction a = attraction_at(f, -f.R * (f.axes * gamma));
  return f.mu * f.R * (f.axes.transpose() * a.gradient);
}

double dV_dR(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  const Vec3 gm = f.axes * gamma;
  return f.mu * gm.dot(attraction_at(f, -f.R * gm).gradient);
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
