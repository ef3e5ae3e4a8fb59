#include "newtop/orbit/orbit_model.hpp"

#include <algorithm>
#include <cmath>

namespace newtop {

void check_orbit_body(const Body& body) {
  if (body.center_of_mass() != Vec3::Zero()) {
    throw InputError(
        "center_of_mass: expected [0, 0, 0] on an orbit (the body turns about its centre of "
        "mass), found " +
        format_vector(body.center_of_mass()));
  }
}

OrbitState rhs(const CircularOrbitModel& model, const OrbitState& s) {
  const Body& b = model.body();
  const Vec3 w = omega(b, s);
  const double w0 = model.orbit().rate;
  return {s.m.cross(w) + model.orbit().lambda_ * s.gamma.cross(b.inertia().cwiseProduct(s.gamma)),
          s.gamma.cross(w) + w0 * s.normal.cross(s.gamma), s.normal.cross(w)};
}

OrbitState rhs(const EllipticOrbitModel& model, const OrbitState& s, double nu) {
  const Body& b = model.body();
  const Vec3 w = omega(b, s);
  const double sigma = time_per_anomaly(model.orbit(), nu);
  const double lambda = lambda_at(model.orbit(), nu);
  return {sigma * (s.m.cross(w) + lambda * s.gamma.cross(b.inertia().cwiseProduct(s.gamma))),
          sigma * s.gamma.cross(w) + s.normal.cross(s.gamma), sigma * s.normal.cross(w)};
}

namespace {

double kinetic(const Body& b, const OrbitState& s) {
  const Vec3 d = s.m - b.gyrostat();
  return 0.5 * d.dot(d.cwiseQuotient(b.inertia()));
}

double gradient_energy(const Body& b, double lambda, const Vec3& gamma) {
  return 0.5 * lambda * gamma.dot(b.inertia().cwiseProduct(gamma));
}

}  // namespace

double jacobi_integral(const CircularOrbitModel& model, const OrbitState& s) {
  return kinetic(model.body(), s) + gradient_energy(model.body(), model.orbit().lambda_, s.gamma) -
         model.orbit().rate * s.normal.dot(s.m);
}

double hamiltonian(const EllipticOrbitModel& model, const OrbitState& s, double nu) {
  const double sigma = time_per_anomaly(model.orbit(), nu);
  return sigma * (kinetic(model.body(), s) +
                  gradient_energy(model.body(), lambda_at(model.orbit(), nu), s.gamma)) -
         s.normal.dot(s.m);
}

OrbitCasimirs casimirs(const OrbitState& s) {
  return {s.gamma.squaredNorm(), s.normal.squaredNorm(), s.gamma.dot(s.normal)};
}

double casimir_error(const OrbitState& s) {
  const OrbitCasimirs c = casimirs(s);
  return std::max(
      {std::abs(c.gamma_gamma - 1.0), std::abs(c.normal_normal - 1.0), std::abs(c.gamma_normal)});
}

void check_orbit_state(const OrbitState& s, double tolerance) {
  if (!s.m.allFinite()) {
    throw InputError("omega: expected finite components, found " + format_vector(s.m));
  }
  if (!s.gamma.allFinite() || std::abs(s.gamma.norm() - 1.0) > tolerance) {
    throw InputError("gamma: expected a unit vector, found " + format_vector(s.gamma));
  }
  if (!s.normal.allFinite() || std::abs(s.normal.norm() - 1.0) > tolerance) {
    throw InputError("normal: expected a unit vector, found " + format_vector(s.normal));
  }
  if (std::abs(s.gamma.dot(s.normal)) > tolerance) {
    throw InputError("normal: expected a vector orthogonal to gamma, found gamma·normal = " +
                     format_number(s.gamma.dot(s.normal)));
  }
}

Mat3 orbital_frame(const OrbitState& s) {
  Mat3 F;
  F << s.gamma, s.normal.cross(s.gamma), s.normal;
  return F;
}

OrbitState state_from_relative(const Body& body, const Mat3& frame, const Vec3& omega_relative,
                               double orbit_rate) {
  const Vec3 n = frame.col(2);
  const Vec3 w = omega_relative + orbit_rate * n;
  return {body.inertia().cwiseProduct(w) + body.gyrostat(), frame.col(0), n};
}

Vec3 relative_omega(const Body& body, const OrbitState& s, double orbit_rate) {
  return omega(body, s) - orbit_rate * s.normal;
}

}  // namespace newtop
