#include "newtop/exact/exact_field.hpp"

#include <cmath>
#include <limits>

#include "newtop/exact/multipole.hpp"

namespace newtop {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Numbers at or above this keep every bit in a product or quotient (no gradual underflow).
constexpr double kNormal = std::numeric_limits<double>::min() / kEps;

}  // namespace

FieldValues field_values_at(const Attraction& a, double mu, double R, const Mat3& P,
                            const Vec3& gamma) {
  FieldValues v;
  v.potential = -mu * a.potential;
  v.grad_gamma = mu * (R * (P.transpose() * a.gradient));
  v.dV_dR = mu * (P * gamma).dot(a.gradient);
  v.moment = mu * (P.transpose() * a.moment);
  v.force = -v.dV_dR * gamma + gamma.cross(v.moment) / R;
  return v;
}

void check_field(const MassModel& model, double mu, double R) {
  if (!std::isfinite(mu) || !(mu > 0)) {
    throw InputError("mu: expected a finite number > 0, found " + format_number(mu));
  }
  const double r = max_radius(model);
  if (!std::isfinite(R) || !(R > r)) {
    throw InputError("R: expected a distance greater than the body's radius about O (" +
                     format_number(r) + "), found " + format_number(R));
  }
  const MassProperties mp = mass_properties(model);
  // The sums' terms with μ = 1 are of order M/R (Φ), M/R² (∇Φ) and M/R³ (∇∇Φ, and the scale of
  // the moment's terms).
  const double M = mp.mass, s1 = M / R, s2 = s1 / R, s3 = s2 / R;
  if (!std::isfinite(s2)) {
    throw InputError("R: the field of the body's mass M = " + format_number(M) +
                     " at R = " + format_number(R) + " overflows (M/R^2 = " + format_number(s2) +
                     "); expected a larger R");
  }
  if (!(s3 >= kNormal)) {
    throw InputError("R: expected a distance at which the field's terms (of order M/R^3 = " +
                     format_number(s3) + ") are normal double numbers, found " + format_number(R));
  }
  if (!std::isfinite(mu * s1) || !std::isfinite(mu * s2)) {
    throw InputError("mu: the potential mu M/R = " + format_number(mu * s1) +
                     " or the force mu M/R^2 = " + format_number(mu * s2) +
                     " overflows; expected a smaller mu, found " + format_number(mu));
  }
  const double J = mp.inertia_tensor.norm(), moment = J / R / R / R;
  if (J > 0 && !(moment >= kNormal)) {
    throw InputError("R: expected a distance at which the field's moment (of order |J|/R^3 = " +
                     format_number(moment) + ") is a normal double number, found " +
                     format_number(R));
  }
  if (J > 0 && !(mu * moment >= kNormal)) {
    throw InputError("mu: the field's moment (of order mu |J|/R^3 = " + format_number(mu * moment) +
                     ") underflows; expected a larger mu, found " + format_number(mu));
  }
}

ExactField ExactField::make(std::shared_ptr<const MassModel> model, double mu, double R,
                            const Mat3& axes) {
  check_field(*model, mu, R);
  const double r = max_radius(*model);
  ExactField f{std::move(model), mu, R, axes, 1, nullptr, 0};
  if (!std::holds_alternative<PointMasses>(*f.mass_model) && R >= kFarField * r) {
    // (r/R)^(p−2)/(1 − r/R) ≤ ε/2: the truncation below round-off in V and in the moment.
    const double q = r / R;
    f.far_order = 2 + static_cast<int>(std::ceil(std::log(0.5 * kEps * (1 - q)) / std::log(q)));
    f.far_moments = std::make_shared<const MassMoments>(*f.mass_model, f.far_order);
  }
  return f;
}

namespace {

Vec3 centre(const ExactField& f, const Vec3& gamma) { return -f.R * (f.axes * gamma); }

Attraction attraction_at(const ExactField& f, const Vec3& x) {
  if (f.far_moments) return multipole_attraction(*f.far_moments, f.far_order, x);
  return attraction(*f.mass_model, x, f.threads);
}

GravityGradient gravity_gradient_at(const ExactField& f, const Vec3& x) {
  if (f.far_moments) return multipole_gravity_gradient(*f.far_moments, f.far_order, x);
  return gravity_gradient(*f.mass_model, x, f.threads);
}

}  // namespace

FieldValues field_values(const ExactField& f, const Vec3& gamma) {
  return field_values_at(attraction_at(f, centre(f, gamma)), f.mu, f.R, f.axes, gamma);
}

double potential(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  return -f.mu * attraction_at(f, centre(f, gamma)).potential;
}

Vec3 grad_gamma(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  return f.mu * (f.R * (f.axes.transpose() * attraction_at(f, centre(f, gamma)).gradient));
}

double dV_dR(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  return f.mu * (f.axes * gamma).dot(attraction_at(f, centre(f, gamma)).gradient);
}

Vec3 moment(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  return f.mu * (f.axes.transpose() * attraction_at(f, centre(f, gamma)).moment);
}

Mat3 hessian_gamma(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  const Mat3 T = gravity_gradient_at(f, centre(f, gamma)).tensor;
  return -f.mu * (f.R * (f.R * (f.axes.transpose() * T * f.axes)));
}

Mat3 moment_jacobian(const Body& /*body*/, const ExactField& f, const Vec3& gamma) {
  const Mat3 J = gravity_gradient_at(f, centre(f, gamma)).moment_jacobian;
  return -f.mu * (f.R * (f.axes.transpose() * J * f.axes));
}

MomentAndDerivative moment_with_derivative(const Body& /*body*/, const ExactField& f,
                                           const Vec3& gamma, const Vec3& delta) {
  const Vec3 x = centre(f, gamma), u = f.axes * delta;
  MomentAndDerivative a;
  if (f.far_moments) {
    a = {multipole_attraction(*f.far_moments, f.far_order, x).moment,
         multipole_gravity_gradient(*f.far_moments, f.far_order, x).moment_jacobian * u};
  } else {
    a = moment_with_derivative(*f.mass_model, x, u, f.threads);
  }
  // x = −RPγ: ∂x/∂γ = −RP.
  return {f.mu * (f.axes.transpose() * a.moment),
          -f.mu * (f.R * (f.axes.transpose() * a.derivative))};
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
