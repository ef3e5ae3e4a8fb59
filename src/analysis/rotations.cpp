#include "newtop/analysis/rotations.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace newtop {
namespace {

// |γ × Iγ| below this fraction of max I marks a principal axis, where Ω² of the cone formula is
// unbounded (every Ω is admissible there).
constexpr double kPrincipalAxis = 1e-9;

Vec3 linear_term(const QuadraticModel& model) {
  return model.body.mass() * model.field.g * model.body.center_of_mass();
}

void add_sample(const QuadraticModel& model, const Vec3& v, RotationFamilies& out) {
  if (!(v.norm() > 0)) return;
  const Vec3 gamma = v.normalized();
  const Vec3& I = model.body.inertia();
  if (gamma.cross(I.cwiseProduct(gamma)).norm() <= kPrincipalAxis * I.maxCoeff()) return;
  for (double sign : {1.0, -1.0}) {
    const double w2 = cone_omega_squared(model, sign * gamma);
    out.cone.push_back({sign * gamma, w2, w2 >= 0.0});
  }
}

/// γ(τ) ∝ (b_i Π_{j≠i} (I_j − τ)): the generator of the cone for the parameter τ, finite at τ =
/// I_i.
Vec3 generator(const Vec3& I, const Vec3& b, double tau) {
  return {b.x() * (I.y() - tau) * (I.z() - tau), b.y() * (I.x() - tau) * (I.z() - tau),
          b.z() * (I.x() - tau) * (I.y() - tau)};
}

void sample_cone(const QuadraticModel& model, const Vec3& b, int samples, RotationFamilies& out) {
  const Vec3& I = model.body.inertia();
  const double tol = kRotationDegeneracy * b.norm();
  const Vec3 coef{b.x() * (I.z() - I.y()), b.y() * (I.x() - I.z()), b.z() * (I.y() - I.x())};
  if (coef.norm() <= kRotationDegeneracy * b.norm() * I.maxCoeff()) {
    out.cone_is_whole_sphere = true;
    return;
  }
  // τ = centre + width·tan θ covers ℝ; θ avoids ±π/2, where γ → r0 (added once).
  const double centre = I.mean();
  const double width = std::max(I.maxCoeff() - I.minCoeff(), 1e-3 * I.mean());
  for (int k = 1; k < samples; ++k) {
    const double theta = std::numbers::pi * (static_cast<double>(k) / samples - 0.5);
    add_sample(model, generator(I, b, centre + width * std::tan(theta)), out);
  }
  add_sample(model, b, out);
  // Where x0_i = 0 the cone splits into the plane γ_i = 0 (sampled above) and the plane spanned by
  // e_i and (I − I_i E)⁻¹ b.
  for (int i = 0; i < 3; ++i) {
    if (std::abs(b[i]) > tol) continue;
    Vec3 u = Vec3::Zero();
    bool ok = true;
    for (int j = 0; j < 3; ++j) {
      if (j == i) continue;
      if (std::abs(I[j] - I[i]) <= kRotationDegeneracy * I.maxCoeff()) {
        ok = ok && std::abs(b[j]) <= tol;
      } else {
        u[j] = b[j] / (I[j] - I[i]);
      }
    }
    if (!ok || u.norm() == 0.0) continue;
    u.normalize();
    for (int k = 0; k < samples; ++k) {
      const double phi = std::numbers::pi * k / samples;  // −γ added by add_sample
      add_sample(model, std::cos(phi) * Vec3::Unit(i) + std::sin(phi) * u, out);
    }
  }
}

}  // namespace

double staude_cone(const Body& body, const Vec3& gamma) {
  return gamma.dot(body.inertia().cwiseProduct(gamma).cross(body.center_of_mass()));
}

double cone_omega_squared(const QuadraticModel& model, const Vec3& gamma) {
  const Vec3 gIg = gamma.cross(model.body.inertia().cwiseProduct(gamma));
  const double n2 = gIg.squaredNorm();
  if (n2 == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return model.field.lambda_ + gamma.cross(linear_term(model)).dot(gIg) / n2;
}

RotationFamilies permanent_rotations(const QuadraticModel& model, int samples) {
  if (!model.body.gyrostat().isZero(0.0)) {
    throw InputError(
        "gyrostat: permanent rotations (docs/model.md §8) need a body without rotor, k = [0, 0, "
        "0]; found k = " +
        format_vector(model.body.gyrostat()));
  }
  if (samples < 2 || samples > kMaxRotationSamples) {
    throw InputError("samples: expected an integer from 2 to " +
                     std::to_string(kMaxRotationSamples) +
                     " (samples per curve of the cone), found " + std::to_string(samples));
  }
  RotationFamilies out;
  const Vec3 b = linear_term(model);
  const double size = b.norm();
  const double tol = kRotationDegeneracy * size;
  for (int i = 0; i < 3; ++i) {
    // b ∥ e_i: the other two components vanish.
    if (std::abs(b[(i + 1) % 3]) <= tol && std::abs(b[(i + 2) % 3]) <= tol) {
      out.principal_axes.push_back(Vec3::Unit(i));
      out.principal_axes.push_back(-Vec3::Unit(i));
    }
  }
  if (size == 0.0) {
    if (model.field.lambda_ > 0) out.any_axis_omega = std::sqrt(model.field.lambda_);
    return out;
  }
  sample_cone(model, b, samples, out);
  return out;
}

}  // namespace newtop
