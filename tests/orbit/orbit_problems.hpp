#pragma once
// Reference satellites and helpers shared by the orbit tests.

#include <cmath>
#include <limits>

#include "newtop/orbit/orbit_integrate.hpp"

namespace newtop::test {

inline constexpr double kOrbitEps = std::numeric_limits<double>::epsilon();

/// A generic triaxial gyrostat (no symmetry, rotor along no axis), O(1) moments.
inline Body orbit_body(const Vec3& k = Vec3(0.1, -0.2, 0.3)) {
  return Body::from_principal(Vec3(1.0, 1.6, 2.1), 1.0, Vec3::Zero(), k);
}

/// A rotation matrix from a (not normalised) quaternion.
inline Mat3 rotation(double w, double x, double y, double z) {
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

/// A state with unit γ ⊥ n from a rotation (its first and third columns) and a tumbling ω.
inline OrbitState tumbling_state(const Body& body, const Vec3& w = Vec3(0.3, -0.5, 0.9)) {
  const Mat3 S = rotation(0.8, -0.3, 0.5, 0.1);
  return {body.inertia().cwiseProduct(w) + body.gyrostat(), S.col(0), S.col(2)};
}

inline double max_distance(const OrbitState& a, const OrbitState& b) {
  return std::max({(a.m - b.m).cwiseAbs().maxCoeff(), (a.gamma - b.gamma).cwiseAbs().maxCoeff(),
                   (a.normal - b.normal).cwiseAbs().maxCoeff()});
}

/// Fehlberg 7(8) at a tolerance near round-off.
inline OrbitState reference(const CircularOrbitModel& m, const OrbitState& x, double t0, double t1,
                            double tol = 1e-14) {
  return integrate_adaptive(m, x, t0, t1, OrbitAdaptiveOptions{tol, tol}).state;
}
inline OrbitState reference(const EllipticOrbitModel& m, const OrbitState& x, double nu0,
                            double nu1, double tol = 1e-14) {
  return integrate_adaptive(m, x, nu0, nu1, OrbitAdaptiveOptions{tol, tol}).state;
}

}  // namespace newtop::test
