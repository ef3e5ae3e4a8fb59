// Multipole series of the exact field (docs/model.md §3): Taylor coefficients of 1/|x|, the sums
// over the mass moments with their first and second derivatives, and MultipoleField. The series are
// summed for the body scaled by its radius r (ỹ = y/r, M̃_α = M_α / r^|α|), every term then of size
// M (r/R)^(n+1), and the powers of r applied at the end.

#include "newtop/exact/multipole.hpp"

#include <cmath>
#include <string>

#include "detail.hpp"
#include "table.hpp"

namespace newtop {
namespace {

using detail::cross_matrix;
using detail::Table;

// Orders above this gain nothing in double precision for a centre outside the body and make
// the (degree+1)³ tables needlessly large.
constexpr int kMaxOrder = 30;

/// S(ỹ) = Σ_{|α| < order} M̃_α c̃_α(ỹ) and its derivatives in ỹ, all terms and those with |α| ≥ 1
/// (`*_rest`: the monopole's gradient is parallel to ỹ and gives no moment), and the first omitted
/// degree (`next`, where the moments reach it).
struct Sums {
  double V = 0.0, next = 0.0;
  Vec3 grad = Vec3::Zero(), grad_rest = Vec3::Zero();
  Mat3 hess = Mat3::Zero(), hess_rest = Mat3::Zero();
};

Sums sums(const MassMoments& M, int order, const Vec3& y, bool hessian) {
  const int d = order + (hessian ? 1 : 0);
  Table c(d);
  c.v = inverse_distance_taylor(y, d);
  Sums s;
  for (int i = 0; i <= order; ++i)
    for (int j = 0; i + j <= order; ++j)
      for (int k = 0; i + j + k <= order; ++k) {
        if (i + j + k > M.degree()) continue;
        const double m = M.scaled(i, j, k);
        if (i + j + k == order) {
          s.next += m * c(i, j, k);
          continue;
        }
        s.V += m * c(i, j, k);
        const Vec3 g =
            m * Vec3((i + 1) * c(i + 1, j, k), (j + 1) * c(i, j + 1, k), (k + 1) * c(i, j, k + 1));
        s.grad += g;
        if (i + j + k > 0) s.grad_rest += g;
        if (!hessian) continue;
        const double a[3] = {i + 1.0, j + 1.0, k + 1.0};
        Mat3 h;
        h(0, 0) = a[0] * (i + 2) * c(i + 2, j, k);
        h(1, 1) = a[1] * (j + 2) * c(i, j + 2, k);
        h(2, 2) = a[2] * (k + 2) * c(i, j, k + 2);
        h(0, 1) = h(1, 0) = a[0] * a[1] * c(i + 1, j + 1, k);
        h(0, 2) = h(2, 0) = a[0] * a[2] * c(i + 1, j, k + 1);
        h(1, 2) = h(2, 1) = a[1] * a[2] * c(i, j + 1, k + 1);
        s.hess += m * h;
        if (i + j + k > 0) s.hess_rest += m * h;
      }
  return s;
}

}  // namespace

std::vector<double> inverse_distance_taylor(const Vec3& x, int degree) {
  Table c(degree);
  const double r2 = x.squaredNorm();
  c(0, 0, 0) = 1.0 / std::sqrt(r2);
  for (int n = 1; n <= degree; ++n) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const int k = n - i - j;
        const double lin =
            x.x() * c.at(i - 1, j, k) + x.y() * c.at(i, j - 1, k) + x.z() * c.at(i, j, k - 1);
        const double quad = c.at(i - 2, j, k) + c.at(i, j - 2, k) + c.at(i, j, k - 2);
        c(i, j, k) = -((2.0 * n - 1.0) * lin + (n - 1.0) * quad) / (r2 * n);
      }
    }
  }
  return std::move(c.v);
}

// Φ(x) = S(−x/r)/r, ∇Φ = −∇S/r², ∇∇Φ = ∇∇S/r³ (derivatives of S in ỹ = −x/r), moment
// ∇Φ' × x = ∇S' × ỹ / r (Φ' without the monopole), its Jacobian (−[∇S']× + [ỹ]× ∇∇S')/r².
Attraction multipole_attraction(const MassMoments& M, int order, const Vec3& x) {
  const double r = M.scale();
  const Vec3 y = -x / r;
  const Sums s = sums(M, order, y, false);
  return {s.V / r, -s.grad / r / r, s.grad_rest.cross(y) / r};
}

GravityGradient multipole_gravity_gradient(const MassMoments& M, int order, const Vec3& x) {
  const double r = M.scale();
  const Vec3 y = -x / r;
  const Sums s = sums(M, order, y, true);
  return {s.hess / r / r / r, (cross_matrix(y) * s.hess_rest - cross_matrix(s.grad_rest)) / r / r};
}

MultipoleField MultipoleField::make(const MassModel& model, int order, double mu, double R,
                                    const Mat3& axes) {
  if (order < 1 || order > kMaxOrder) {
    throw InputError("order: expected an integer in [1, " + std::to_string(kMaxOrder) +
                     "], found " + std::to_string(order));
  }
  check_field(model, mu, R);
  return {std::make_shared<const MassMoments>(model, order), order, mu, R, axes};
}

FieldValues field_values(const MultipoleField& f, const Vec3& gamma) {
  return field_values_at(multipole_attraction(*f.moments, f.order, -f.R * (f.axes * gamma)), f.mu,
                         f.R, f.axes, gamma);
}

double potential(const Body& /*body*/, const MultipoleField& f, const Vec3& gamma) {
  return field_values(f, gamma).potential;
}

Vec3 grad_gamma(const Body& /*body*/, const MultipoleField& f, const Vec3& gamma) {
  return field_values(f, gamma).grad_gamma;
}

Vec3 moment(const Body& /*body*/, const MultipoleField& f, const Vec3& gamma) {
  return field_values(f, gamma).moment;
}

Mat3 hessian_gamma(const Body& /*body*/, const MultipoleField& f, const Vec3& gamma) {
  const GravityGradient g =
      multipole_gravity_gradient(*f.moments, f.order, -f.R * (f.axes * gamma));
  return -f.mu * (f.R * (f.R * (f.axes.transpose() * g.tensor * f.axes)));
}

Mat3 moment_jacobian(const Body& /*body*/, const MultipoleField& f, const Vec3& gamma) {
  const GravityGradient g =
      multipole_gravity_gradient(*f.moments, f.order, -f.R * (f.axes * gamma));
  return -f.mu * (f.R * (f.axes.transpose() * g.moment_jacobian * f.axes));
}

TruncationError truncation_error(const MultipoleField& f, const Vec3& gamma) {
  const MassMoments& M = *f.moments;
  const Sums s = sums(M, f.order, f.R * (f.axes * gamma) / M.scale(), false);
  const double r = M.max_radius();
  return {f.mu * std::abs(s.next) / M.scale(),
          f.mu * M.mass() * std::pow(r / f.R, f.order) / (f.R - r)};
}

}  // namespace newtop
