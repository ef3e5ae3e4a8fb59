#pragma once
/// \file
/// Multipole expansion of the exact field (docs/model.md §3) to any order in 1/R:
/// 1/|x + ρ| = Σ_α c_α(x) ρ^α with c_α the Taylor coefficients of 1/|x| (x = Rγ), so
/// V_p(γ; R) = −μ Σ_{|α| ≤ p−1} M_α c_α(Rγ), where M_α = ∫ ρ^α dm are the mass moments. The terms
/// of degree n = |α| fall as R^−(n+1); order p keeps 1/R … 1/R^p. Order 3 is the quadratic model
/// of docs/model.md §3 with its γ-independent terms kept; order 4 adds the octupole.

#include <memory>
#include <vector>

#include "newtop/exact/exact_field.hpp"

namespace newtop {

/// Mass moments M_α = ∫ ρ^α dm for |α| ≤ degree (exact for every mass model: polyhedra by
/// signed tetrahedra, ellipsoids from the moments of the ball, points by sums with the first
/// moment D = Σ m ρ summed accurately), plus M and max |ρ|. The first moments are the mass
/// model's accurate D (first_moment()). Stored for the body scaled by r = scale(), the power of two
/// in (max_radius, 2 max_radius]: M̃_α = ∫ (ρ/r)^α dm, so that no degree overflows.
class MassMoments {
 public:
  MassMoments(const MassModel& model, int degree);
  int degree() const { return degree_; }
  /// M_(i,j,k) = ∫ x^i y^j z^k dm, i + j + k ≤ degree (= M̃ r^(i+j+k); may overflow for a large
  /// body at a high degree, where the scaled moments do not).
  double operator()(int i, int j, int k) const;
  /// M̃_(i,j,k) = ∫ (x/r)^i (y/r)^j (z/r)^k dm, |M̃| ≤ M.
  double scaled(int i, int j, int k) const { return m_[index(i, j, k)]; }
  /// The length r of the scaled moments: a power of two in (max_radius, 2 max_radius], or 1 for a
  /// body all at O.
  double scale() const { return scale_; }
  double mass() const { return m_[0]; }
  /// Radius of a sphere about O holding the body.
  double max_radius() const { return max_radius_; }

 private:
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(i) * (degree_ + 1) + j) * (degree_ + 1) + k;
  }
  int degree_;
  std::vector<double> m_;
  double max_radius_;
  double scale_ = 1.0;
};

/// Taylor coefficients c_α(x), |α| ≤ degree, of 1/|x + h| in h, by the recurrence
/// |x|² n c_α = −(2n − 1) Σ_j x_j c_{α−e_j} − (n − 1) Σ_j c_{α−2e_j} (n = |α|). Dense (degree+1)³
/// array indexed (i·(d+1) + j)·(d+1) + k, zero where i + j + k > degree.
std::vector<double> inverse_distance_taylor(const Vec3& x, int degree);

/// Φ(x) = ∫ dm/|x − ρ|, ∇Φ and the moment ∇Φ × x from the series Σ_{|α| ≤ order−1} M_α c_α(−x)
/// (terms through |x|^−order); needs moments of degree ≥ order − 1. The moment sums the terms
/// |α| ≥ 1 only: the monopole's gradient M ∇(1/|x|) is parallel to x and has no moment, so it is
/// left out analytically and each order's moment comes from its own coefficients — no cancellation.
Attraction multipole_attraction(const MassMoments& moments, int order, const Vec3& x);

/// ∇∇Φ from the same series (Taylor coefficients to degree order + 1), and the moment's Jacobian
/// [∇Φ']× − [x]× ∇∇Φ' from the terms |α| ≥ 1 (Φ' = Φ − M/|x|; the monopole's part is exactly
/// zero). Needs moments of degree ≥ order − 1.
GravityGradient multipole_gravity_gradient(const MassMoments& moments, int order, const Vec3& x);

/// Truncated multipole expansion of order p ≥ 1 (terms through 1/R^p) as a Field. The moments are
/// computed to degree p so that the first omitted term is available as an error estimate.
struct MultipoleField {
  std::shared_ptr<const MassMoments> moments;
  int order = 3;
  double mu = 0.0;
  double R = 0.0;
  Mat3 axes = Mat3::Identity();

  /// Checks order in [1, 30] and what ExactField::make checks (μ, R, and that every derived
  /// quantity is finite); throws InputError naming order, mu or R.
  static MultipoleField make(const MassModel& model, int order, double mu, double R,
                             const Mat3& axes = Mat3::Identity());
};

FieldValues field_values(const MultipoleField& field, const Vec3& gamma);
double potential(const Body& body, const MultipoleField& field, const Vec3& gamma);
Vec3 grad_gamma(const Body& body, const MultipoleField& field, const Vec3& gamma);
/// L = γ × ∂V/∂γ without the monopole's cancellation (multipole_attraction).
Vec3 moment(const Body& body, const MultipoleField& field, const Vec3& gamma);
/// ∂²V/∂γ² = −μR² Pᵀ ∇∇Φ(−RPγ) P.
Mat3 hessian_gamma(const Body& body, const MultipoleField& field, const Vec3& gamma);
/// ∂L/∂γ = [γ]× ∂²V/∂γ² − [∂V/∂γ]×, without the monopole's cancellation.
Mat3 moment_jacobian(const Body& body, const MultipoleField& field, const Vec3& gamma);

/// Truncation error of V at γ: `next_term`, the magnitude of the first omitted term (1/R^(p+1)),
/// and `bound`, a rigorous bound of |V − V_p| from |P_n| ≤ 1:
/// μ M r^p / (R^p (R − r)) with r the body's max radius.
struct TruncationError {
  double next_term = 0.0;
  double bound = 0.0;
};
TruncationError truncation_error(const MultipoleField& field, const Vec3& gamma);

}  // namespace newtop
