// The non-convex Eros mesh (14,744 faces): its exact field far away against a point-mass
// discretisation of the same volume, and its closed form at intermediate distance against its own
// multipole series.

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "newtop/exact/multipole.hpp"
#include "newtop/io/mesh.hpp"

namespace newtop {
namespace test_eros {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const std::string kData = std::string(NEWTOP_DATA_DIR) + "/polyhedra/";

const Polyhedron& eros() {
  static const Polyhedron p = io::load_polyhedron(kData + "eros.face", 2.67);
  return p;
}

const Vec3 kGamma = Vec3(0.48, -0.61, 0.63).normalized();

using LD = long double;

/// Signed point masses reproducing every mass moment of the polyhedron through degree 7 exactly:
/// each tetrahedron (O, a, b, c) in collapsed coordinates p = u ((1 − v) a + v (1 − w) b + v w c),
/// dV = u² v det(a, b, c) du dv dw, with 5-point Gauss–Legendre rules per axis (exact to degree 9
/// in u, so for polynomials of degree ≤ 7 against the weight u² v). Non-convex parts seen from O
/// give tetrahedra of negative volume, hence signed masses. Nodes, weights, points and masses in
/// long double: rounded to double, the rule would miss the first moment by ε M r, which far away
/// is ε R/r of the moment.
struct Discretisation {
  const Polyhedron& p;
  std::vector<LD> t, w;   // nodes and weights on [0, 1]
  double abs_mass = 0.0;  // Σ |m_i|

  explicit Discretisation(const Polyhedron& poly) : p(poly) {
    using Rule = boost::math::quadrature::gauss<LD, 5>;
    for (std::size_t i = 0; i < Rule::abscissa().size(); ++i) {
      const LD a = Rule::abscissa()[i], b = Rule::weights()[i];
      t.push_back((1 + a) / 2);
      w.push_back(b / 2);
      if (a != 0) {
        t.push_back((1 - a) / 2);
        w.push_back(b / 2);
      }
    }
    each([&](LD m, const LD*) { abs_mass += static_cast<double>(m < 0 ? -m : m); });
  }

  /// Calls f(m, x) for every point mass.
  template <class F>
  void each(F&& f) const {
    for (const Triangle& tri : p.faces()) {
      const Vec3 &a = p.vertices()[tri[0]], &b = p.vertices()[tri[1]], &c = p.vertices()[tri[2]];
      const LD det = p.density() * (LD(a[0]) * (LD(b[1]) * c[2] - LD(b[2]) * c[1]) +
                                    LD(a[1]) * (LD(b[2]) * c[0] - LD(b[0]) * c[2]) +
                                    LD(a[2]) * (LD(b[0]) * c[1] - LD(b[1]) * c[0]));
      for (std::size_t i = 0; i < t.size(); ++i)
        for (std::size_t j = 0; j < t.size(); ++j)
          for (std::size_t k = 0; k < t.size(); ++k) {
            const LD u = t[i], v = t[j], s = t[k];
            LD x[3];
            for (int n = 0; n < 3; ++n) {
              x[n] = u * ((1 - v) * a[n] + v * (1 - s) * b[n] + v * s * c[n]);
            }
            f(det * w[i] * w[j] * w[k] * u * u * v, x);
          }
    }
  }
};

/// Φ, ∇Φ, ∇Φ × x and ∇∇Φ at x by direct sums in long double (64-bit significand): the sums lose
/// about ε_ld √N (N ≈ 1.8e6) ≈ 2e-16, and the moment in addition ε_ld |x|/r to the dipole's
/// cancellation.
struct Sums {
  double potential;
  Vec3 gradient, moment;
  Mat3 tensor;
};

Sums direct(const Discretisation& d, const Vec3& x) {
  LD phi = 0, g[3] = {0, 0, 0}, L[3] = {0, 0, 0}, T[3][3] = {};
  d.each([&](LD m, const LD* p) {
    const LD e[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    const LD r2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2], r = std::sqrt(r2);
    const LD m1 = m / r, m3 = m1 / r2, m5 = m3 / r2;
    phi += m1;
    for (int i = 0; i < 3; ++i) {
      g[i] -= m3 * e[i];
      for (int j = 0; j < 3; ++j) T[i][j] += 3 * m5 * e[i] * e[j] - (i == j ? m3 : 0);
    }
    // ρ × x / d³, from ρ itself (e × x would cancel |x|/r of its digits).
    L[0] += m3 * (p[1] * x[2] - p[2] * x[1]);
    L[1] += m3 * (p[2] * x[0] - p[0] * x[2]);
    L[2] += m3 * (p[0] * x[1] - p[1] * x[0]);
  });
  Sums s{static_cast<double>(phi), Vec3::Zero(), Vec3::Zero(), Mat3::Zero()};
  for (int i = 0; i < 3; ++i) {
    s.gradient[i] = static_cast<double>(g[i]);
    s.moment[i] = static_cast<double>(L[i]);
    for (int j = 0; j < 3; ++j) s.tensor(i, j) = static_cast<double>(T[i][j]);
  }
  return s;
}

TEST(Eros, FarFieldAgreesWithAPointMassDiscretisation) {
  const Polyhedron& p = eros();
  const auto model = std::make_shared<const MassModel>(p);
  const double r = max_radius(*model), M = mass_properties(p).mass;
  const Discretisation d(p);
  const Body body = body_of(*model);
  for (double q : {30.0, 100.0, 1000.0}) {
    const double R = q * r;
    const ExactField f = ExactField::make(model, 1.0, R);
    ASSERT_TRUE(f.far_moments);  // the series, as ExactField evaluates it from R = 4r on
    const FieldValues v = field_values(f, kGamma);
    const Sums s = direct(d, -R * kGamma);
    // The discretisation has the polyhedron's moments through degree 7: the first difference is
    // of degree 8, at most 2 Σ|m| r⁸ in the moments, |Φ| error ≤ 2 Σ|m| r⁸/(R⁹ (1 − r/R)) against
    // Φ ≈ M/R (each derivative multiplies by ≲ 10/R). Round-off: 64 ε.
    const double trunc = 2 * d.abs_mass / M * std::pow(1 / q, 8) / (1 - 1 / q);
    const double tol = 64 * kEps + 10 * trunc, tol2 = 64 * kEps + 100 * trunc;
    // The moment is the dipole ((r/R) of the gradient) or the quadrupole ((r/R)²): relative to
    // itself the discretisation's difference is up to (R/r)² larger, and the long-double sum
    // loses ε_ld R/r ≈ 1e-16 to the dipole's cancellation.
    const double tol_moment = 64 * kEps + 100 * trunc * q * q;
    EXPECT_NEAR(v.potential, -s.potential, tol * s.potential) << q;
    EXPECT_LE((v.grad_gamma - R * s.gradient).norm(), tol * R * s.gradient.norm()) << q;
    EXPECT_LE((v.moment - s.moment).norm(), tol_moment * s.moment.norm()) << q;
    const Mat3 H = hessian_gamma(body, f, kGamma), want = -R * R * s.tensor;
    EXPECT_LE((H - want).norm(), tol2 * want.norm()) << q;
  }
}

TEST(Eros, ClosedFormAgreesWithItsMultipoleSeriesAtIntermediateDistance) {
  // Below R = 4r ExactField evaluates the closed form. Against the series of order 30: the
  // truncation's rigorous bound (r/R)^30/(1 − r/R) relative to V (the gradient's degree-n terms
  // carry a factor n + 1 ≤ 31, the tensor's (n + 1)(n + 2)); the closed form's round-off
  // C ε (R/r)² of V, ∇Φ and ∇∇Φ, C ≲ 300 for meshes of thousands of faces.
  const Polyhedron& p = eros();
  const auto model = std::make_shared<const MassModel>(p);
  const double r = max_radius(*model);
  const MassMoments moments(*model, 30);
  for (double q : {2.0, 3.0, 3.9}) {
    const double R = q * r;
    const ExactField f = ExactField::make(model, 1.0, R);
    ASSERT_FALSE(f.far_moments);
    const Attraction closed = attraction(p, -R * kGamma);
    const Attraction series = multipole_attraction(moments, 30, -R * kGamma);
    const double trunc = std::pow(1 / q, 30) / (1 - 1 / q), round = 300 * kEps * q * q;
    EXPECT_NEAR(closed.potential, series.potential, (round + trunc) * series.potential) << q;
    EXPECT_LE((closed.gradient - series.gradient).norm(),
              (round + 31 * trunc) * series.gradient.norm())
        << q;
    // The closed form's moment is ∇Φ × x: its error is that of ∇Φ times |x|.
    EXPECT_LE((closed.moment - series.moment).norm(),
              (round + 31 * trunc) * series.gradient.norm() * R)
        << q;
    const GravityGradient gc = gravity_gradient(p, -R * kGamma),
                          gs = multipole_gravity_gradient(moments, 30, -R * kGamma);
    EXPECT_LE((gc.tensor - gs.tensor).norm(), (round + 31 * 32 * trunc) * gs.tensor.norm()) << q;
  }
}

}  // namespace
}  // namespace test_eros
}  // namespace newtop
