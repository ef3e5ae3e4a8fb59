// The Hessian ∂²V/∂γ² and the moment's Jacobian ∂L/∂γ of every field (γ a free vector of R³):
// against 50/100-digit references from R/r = 1.5 to 1e8, against central finite differences of
// ∂V/∂γ and of L, Laplace's equation for the gravity-gradient tensor, and the quadratic model.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "bodies.hpp"
#include "newtop/exact/multipole.hpp"

namespace newtop {
namespace test_hessian {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

const Vec3 kGamma = Vec3(0.3, -0.5, 0.8).normalized();

double rel(const Mat3& a, const Mat3& b) { return (a - b).norm() / b.norm(); }

// Far from the body (series, or point-mass sums) the Hessian is a sum of terms of its own size: a
// few roundings per term, κ ≲ 4 as for the moment: 32 ε. The moment's Jacobian, with the monopole
// left out analytically, adds two terms [∇Φ']× and [x]×∇∇Φ' of its size that partly cancel
// (κ ≲ 2 more): 64 ε.
constexpr double kFarTol = 32 * kEps;
constexpr double kFarJacobianTol = 64 * kEps;
// Near a polyhedron or an ellipsoid (R < kFarField r) the closed forms sum terms of size R·r (edge
// and face terms, or R_D's) into ∇Φ ~ r³/R² and ∇∇Φ ~ r³/R³: a loss of C (R/r)² with C ≲ 100
// ulps. The Jacobian [γ]× ∂²V/∂γ² − [∂V/∂γ]× then carries that relative error of both terms,
// whose monopole parts cancel: |δJ| ≤ near_tol (|∂V/∂γ| + |∂²V/∂γ²|).
double near_tol(double q) { return 100 * kEps * q * q; }

TEST(Hessian, AgainstHighPrecisionFromNearToFar) {
  const double mu = 3.7;
  std::printf("%-22s %8s %12s %12s\n", "body", "R/r", "hessian", "moment_jac");
  for (const test::Case& c : test::cases()) {
    const double r = max_radius(*c.model);
    const Body body = body_of(*c.model);
    for (double q : {1.5, 4.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8}) {
      const double R = q * r;
      const ExactField f = ExactField::make(c.model, mu, R);
      const test::Values ref = c.reference(mu, R, kGamma);
      const double eh = rel(hessian_gamma(body, f, kGamma), ref.hessian);
      const Mat3 dJ = moment_jacobian(body, f, kGamma) - ref.moment_jacobian;
      const double ej = dJ.norm() / ref.moment_jacobian.norm();
      std::printf("%-22s %8.1e %12.2e %12.2e\n", c.name.c_str(), q, eh, ej);
      const bool closed = !f.far_moments && !std::holds_alternative<PointMasses>(*c.model);
      if (closed) {
        EXPECT_LE(eh, near_tol(q)) << c.name << " R/r = " << q;
        EXPECT_LE(dJ.norm(), near_tol(q) * (ref.grad_gamma.norm() + ref.hessian.norm()))
            << c.name << " R/r = " << q;
      } else {
        EXPECT_LE(eh, kFarTol) << c.name << " R/r = " << q;
        EXPECT_LE(ej, kFarJacobianTol) << c.name << " R/r = " << q;
      }
    }
  }
}

// The moment and its derivative along δ in one call (a kick with one tangent vector): the moment
// bit for bit as moment(), the derivative against the high-precision Jacobian applied to δ, with
// the Jacobian's tolerances relative to |∂L/∂γ| |δ|.
TEST(Hessian, MomentWithDerivativeAlongOneVector) {
  const double mu = 3.7;
  const Vec3 deltas[] = {Vec3(1.0, 0.0, 0.0), Vec3(-0.2, 0.7, 0.4), kGamma, Vec3(1e-3, 2.0, -5.0)};
  for (const test::Case& c : test::cases()) {
    const double r = max_radius(*c.model);
    const Body body = body_of(*c.model);
    for (double q : {1.5, 4.0, 1e2, 1e5, 1e8}) {
      const double R = q * r;
      const ExactField f = ExactField::make(c.model, mu, R);
      const test::Values ref = c.reference(mu, R, kGamma);
      const bool closed = !f.far_moments && !std::holds_alternative<PointMasses>(*c.model);
      for (const Vec3& d : deltas) {
        const MomentAndDerivative L = moment_with_derivative(body, f, kGamma, d);
        EXPECT_EQ(L.moment, moment(body, f, kGamma)) << c.name << " R/r = " << q;
        const Vec3 err = L.derivative - ref.moment_jacobian * d;
        const double tol = closed ? near_tol(q) * (ref.grad_gamma.norm() + ref.hessian.norm())
                                  : kFarJacobianTol * ref.moment_jacobian.norm();
        EXPECT_LE(err.norm(), tol * d.norm()) << c.name << " R/r = " << q << " delta " << d.x();
      }
    }
  }
}

/// Central differences of f at γ with step h, column by column.
template <class F>
Mat3 central_difference(F&& f, const Vec3& gamma, double h) {
  Mat3 d;
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = h * Vec3::Unit(j);
    d.col(j) = (f(gamma + e) - f(gamma - e)) / (2 * h);
  }
  return d;
}

/// |D − f′| for the central difference D(h) of f: the truncation h²/6 |f‴| estimated by
/// Richardson, (D(2h) − D(h))/3 (doubled for safety), plus the round-off of f, δ |f|/h (δ the
/// relative accuracy of f). h = ε^(1/3) ℓ with ℓ = (R − r)/R the distance of the nearest mass seen
/// from the centre in units of |γ|, the scale on which f varies: the two errors balance near
/// ε^(2/3) ≈ 4e-11 relative.
template <class F>
void expect_derivative(F&& f, const Mat3& df, const Vec3& gamma, double ell, double delta,
                       const std::string& what) {
  const double h = std::cbrt(kEps) * ell;
  const Mat3 d1 = central_difference(f, gamma, h), d2 = central_difference(f, gamma, 2 * h);
  const double tol = 2 * (d2 - d1).norm() / 3 + delta * f(gamma).norm() / h;
  EXPECT_LE((df - d1).norm(), tol) << what;
  // The check can fail: the derivative itself is much larger than the tolerance.
  EXPECT_LT(tol, 1e-6 * df.norm()) << what;
}

TEST(Hessian, AgainstFiniteDifferencesOfTheGradientAndTheMoment) {
  const double mu = 2.0;
  for (const test::Case& c : test::cases()) {
    const double r = max_radius(*c.model);
    const Body body = body_of(*c.model);
    for (double q : {2.0, 30.0}) {  // closed form, and far field for the polyhedron/ellipsoid
      const double R = q * r, ell = (R - r) / R;
      const ExactField f = ExactField::make(c.model, mu, R, body.principal_axes());
      const bool closed = !f.far_moments && !std::holds_alternative<PointMasses>(*c.model);
      const std::string what = c.name + " R/r = " + std::to_string(q);
      expect_derivative([&](const Vec3& g) { return grad_gamma(body, f, g); },
                        hessian_gamma(body, f, kGamma), kGamma, ell, closed ? near_tol(q) : kFarTol,
                        what + " hessian");
      // δ relative to |L|: the closed form's moment carries near_tol of |∂V/∂γ| (≈ |L| (R/r)²).
      expect_derivative([&](const Vec3& g) { return moment(body, f, g); },
                        moment_jacobian(body, f, kGamma), kGamma, ell,
                        closed ? near_tol(q) * q * q : kFarTol, what + " moment_jacobian");
    }
  }
}

TEST(Hessian, GravityGradientObeysLaplace) {
  // ΔΦ = −4πσ inside a homogeneous body, 0 outside: tr ∇∇Φ. The closed forms sum terms of size
  // σ r (|x|/r)... of the tensor's size σ (r/|x|)³ times (|x|/r)²: 64 ε (|x|/r)² of 4πσ.
  const double sigma = 2.0;
  const Polyhedron box = make_box(Vec3(2, 3, 4), sigma);
  const Ellipsoid ell = Ellipsoid::make(Vec3(1, 2, 3), sigma);
  for (const Vec3& x : {Vec3(0.1, 0.2, 0.3), Vec3(-0.5, 0.4, 1.1), Vec3(5, 1, 2), Vec3(-3, 7, 9)}) {
    const double s = x.norm();
    const double tol = 64 * kEps * std::max(1.0, s * s) * 4 * M_PI * sigma;
    const bool in_box = (x.cwiseAbs().array() < Vec3(1, 1.5, 2).array()).all();
    EXPECT_NEAR(gravity_gradient(box, x).tensor.trace(), in_box ? -4 * M_PI * sigma : 0.0, tol)
        << x.transpose();
    const bool in_ell = x.cwiseQuotient(Vec3(1, 2, 3)).squaredNorm() < 1;
    EXPECT_NEAR(gravity_gradient(ell, x).tensor.trace(), in_ell ? -4 * M_PI * sigma : 0.0, tol)
        << x.transpose();
  }
}

TEST(Hessian, CubeGravityGradientAgainstThePrismClosedForm) {
  // The cube [-1, 1]³ of the reference data, inside and outside, against MacMillan's prism formula
  // in 100 digits (∂²Φ/∂x² = −σ [[[atan(vw/(ur))]]], ∂²Φ/∂x∂y = σ [[[ln(w + r)]]]): a second,
  // independent closed form. The points are those of the analytic cube grid (±0.5, ±1.5, ±4.5).
  const Polyhedron cube = make_box(Vec3(2, 2, 2), 1.0);
  for (const Vec3& x : {Vec3(0.5, -0.5, 0.5), Vec3(1.5, 0.5, -1.5), Vec3(-4.5, 1.5, 4.5)}) {
    // γ = −x/R with R = |x|, μ = 1: ∂²V/∂γ² = −R² ∇∇Φ(x).
    const double R = x.norm();
    const auto ref = test::box<test::Real100>(Vec3(-1, -1, -1), Vec3(1, 1, 1), 1.0, 1.0, R, -x / R);
    const Mat3 T = gravity_gradient(cube, x).tensor;
    const Mat3 want = -test::lower(ref.hessian) / (R * R);
    EXPECT_LE((T - want).norm(), near_tol(std::max(1.0, R)) * want.norm()) << x.transpose();
  }
}

TEST(Hessian, OrderThreeIsTheQuadraticModelOnTheSphere) {
  // On the tangent plane of the sphere the moment's Jacobian of the order-3 expansion is the
  // quadratic model's, [γ]× λI − [M g r0 + λ Iγ]× (off the sphere the two extend V differently).
  for (const test::Case& c : test::cases()) {
    const Body body = body_of(*c.model);
    const double r = max_radius(*c.model);
    for (double q : {1e1, 1e3, 1e6, 1e8}) {
      const double mu = 5.0, R = q * r;
      const MultipoleField m = MultipoleField::make(*c.model, 3, mu, R, body.principal_axes());
      const QuadraticField qf = QuadraticField::from_mu_R(mu, R);
      const Mat3 Jm = moment_jacobian(body, m, kGamma), Jq = moment_jacobian(body, qf, kGamma);
      const Mat3 P = Mat3::Identity() - kGamma * kGamma.transpose();
      EXPECT_LE(((Jm - Jq) * P).norm(), kFarJacobianTol * Jq.norm()) << c.name << " R/r = " << q;
    }
  }
}

}  // namespace
}  // namespace test_hessian
}  // namespace newtop
