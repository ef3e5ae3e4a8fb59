// Permanent rotations ω = Ωγ in any field (docs/model.md §8): with k = 0 the fixed-point condition
// Ω² Iγ × γ + L(γ) = 0 says L(γ) = Ω² γ × Iγ, so the admissible axes are the curve
// f(γ) = γ·(L(γ) × (γ × Iγ)) = 0 on the sphere, with Ω² = L·(γ × Iγ)/|γ × Iγ|².

#include <cmath>
#include <numbers>

#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/model/model.hpp"

namespace newtop {
namespace {

// Bisections of a sign change of f along a meridian: the bracket (π/samples) shrinks to round-off.
constexpr int kBisections = 60;

}  // namespace

RotationFamilies permanent_rotations(const Model& model, int samples) {
  if (model.kind() == FieldKind::quadratic) return permanent_rotations(model.quadratic(), samples);
  const Body& body = model.body();
  if (!body.gyrostat().isZero(0.0)) {
    throw InputError(
        "gyrostat: permanent rotations (docs/model.md §8) need a body without rotor, k = [0, 0, "
        "0]; found "
        "k = " +
        format_vector(body.gyrostat()));
  }
  if (samples < 2 || samples > kMaxRotationSamples) {
    throw InputError("samples: expected an integer from 2 to " +
                     std::to_string(kMaxRotationSamples) +
                     " (samples per curve of the cone), found " + std::to_string(samples));
  }
  const Vec3& I = body.inertia();
  double moment_scale = 0.0;
  for (const Vec3& g : fibonacci_sphere(kSphereStarts)) {
    moment_scale = std::max(moment_scale, moment(model, g).norm());
  }
  RotationFamilies out;
  // A principal axis where L vanishes spins uniformly at any Ω (γ × Iγ = 0 there).
  for (int i = 0; i < 3; ++i) {
    for (double s : {1.0, -1.0}) {
      const Vec3 e = s * Vec3::Unit(i);
      if (moment(model, e).norm() <= kRotationDegeneracy * moment_scale) {
        out.principal_axes.push_back(e);
      }
    }
  }
  auto c_of = [&](const Vec3& g) -> Vec3 { return g.cross(I.cwiseProduct(g)); };
  auto f = [&](const Vec3& g) { return g.dot(moment(model, g).cross(c_of(g))); };
  auto at = [](double theta, double phi) {
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  // `samples` meridians φ ∈ [0, 2π), each cut into 2·samples arcs in θ: every sign change of f
  // is bisected to a point of the curve.
  const double pi = std::numbers::pi;
  for (int j = 0; j < 2 * samples; ++j) {
    const double phi = pi * j / samples;
    double t0 = 0.0, f0 = f(at(t0, phi));
    for (int k = 1; k <= 2 * samples; ++k) {
      const double t1 = pi * k / (2 * samples), f1 = f(at(t1, phi));
      if ((f0 < 0) != (f1 < 0) && f0 != 0 && f1 != 0) {
        double lo = t0, hi = t1, flo = f0;
        for (int it = 0; it < kBisections; ++it) {
          const double mid = 0.5 * (lo + hi), fm = f(at(mid, phi));
          if ((fm < 0) == (flo < 0)) {
            lo = mid, flo = fm;
          } else {
            hi = mid;
          }
        }
        const Vec3 g = at(0.5 * (lo + hi), phi);
        const Vec3 c = c_of(g);
        // Near a principal axis γ × Iγ → 0 and f changes sign through its zero, not the curve's.
        if (c.norm() > 1e-6 * I.maxCoeff()) {
          const double w2 = moment(model, g).dot(c) / c.squaredNorm();
          out.cone.push_back({g, w2, w2 >= 0});
        }
      }
      t0 = t1, f0 = f1;
    }
  }
  return out;
}

}  // namespace newtop
