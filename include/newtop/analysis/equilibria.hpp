#pragma once
/// \file
/// Equilibria of the body at rest (ω = 0) in the quadratic field (docs/model.md §7).
///
/// An equilibrium is a unit γ with γ × ∂V/∂γ = 0, i.e. M g r0 + λ Iγ = κ γ for a multiplier κ.
/// Writing b = M g r0 and d_i = λ I_i: γ_i = b_i / (κ − d_i), where κ solves the secular equation
/// Σ_i b_i² / (κ − d_i)² = 1, plus the degenerate solutions κ = d_i when b_i = 0.

#include <vector>

#include "newtop/model/basic_model.hpp"

namespace newtop {

class Model;  // newtop/model/model.hpp

/// Type of a critical point of V on the unit sphere, from the Hessian of V restricted to the
/// tangent plane (λ I − κ E projected on γ⊥).
enum class EquilibriumType { minimum, saddle, maximum, degenerate };

/// "minimum", "saddle", "maximum" or "degenerate".
const char* to_string(EquilibriumType t);

/// One isolated equilibrium γ (ω = 0).
struct Equilibrium {
  Vec3 gamma;        ///< unit vector O′→O in the body frame
  double kappa;      ///< multiplier κ = γ·∂V/∂γ
  double potential;  ///< V(γ)
  EquilibriumType type;
  Eigen::Vector2d hessian;  ///< eigenvalues of the Hessian of V on the sphere at γ (ascending)
  /// γ·(Iγ × r0): zero because the Staude (Ampère) cone has a generator along γ (docs/model.md §7).
  double staude_residual;
};

/// A circle of equilibria: a body with two equal values of λ I_i (and the matching components of
/// r0 zero) rests in every orientation γ = γ_axis e_axis + ρ (cos φ e_j + sin φ e_k). The two
/// axes spanning the circle's plane are the ones other than `axis`.
struct EquilibriumCircle {
  int axis;           ///< index (0, 1, 2) of the axis normal to the plane of the circle
  double gamma_axis;  ///< the fixed component γ_axis
  double kappa;
  double potential;
};

/// All equilibria of a model.
struct EquilibriumSet {
  /// V is constant on the sphere (λ I ∝ E and M g r0 = 0, e.g. uniform gravity with r0 = 0):
  /// every orientation is an equilibrium and `equilibria` is empty.
  bool every_orientation = false;
  std::vector<Equilibrium> equilibria;     ///< isolated equilibria, sorted by increasing κ
  std::vector<EquilibriumCircle> circles;  ///< continuous families (symmetric bodies)
  int minima = 0, saddles = 0, maxima = 0, degenerate = 0;
  /// minima − saddles + maxima (Euler characteristic of the sphere: 2 when all are isolated and
  /// non-degenerate).
  int euler_characteristic() const { return minima - saddles + maxima; }
  /// True when the count rule applies (no circle, no degenerate point, not every orientation)
  /// and holds.
  bool count_rule_holds() const {
    return !every_orientation && circles.empty() && degenerate == 0 && euler_characteristic() == 2;
  }
};

/// Relative size below which a component of M g r0, or a difference of the λ I_i, counts as zero:
/// parameters written in a file to 15 digits must still count as exactly degenerate.
inline constexpr double kEquilibriumDegeneracy = 1e-12;

/// Coefficients (constant term first) of the secular polynomial of docs/model.md §7 in κ,
/// P(κ) = Σ_g β_g Π_{h≠g} (κ − d_h)² − Π_h (κ − d_h)², over the distinct values d_g of λ I_i whose
/// components of b = M g r0 are not all zero, with β_g = Σ_{i: d_i = d_g} b_i². Degree 2·(number
/// of such groups) ≤ 6; leading coefficient −1.
Eigen::VectorXd secular_polynomial(const QuadraticModel& model);

/// Real roots of a polynomial (coefficients constant term first, leading one non-zero) from the
/// eigenvalues of its companion matrix; roots whose imaginary part exceeds `imag_tolerance` times
/// the largest root modulus are dropped. Not polished.
std::vector<double> real_polynomial_roots(const Eigen::VectorXd& coefficients,
                                          double imag_tolerance);

/// Hessian of V restricted to the unit sphere at a critical point γ with multiplier κ, in an
/// orthonormal basis of γ⊥: Tᵀ (λ I − κ E) T.
Eigen::Matrix2d sphere_hessian(const QuadraticModel& model, const Vec3& gamma, double kappa);

/// Builds the Equilibrium record at a critical point γ (classifies it from sphere_hessian).
Equilibrium make_equilibrium(const QuadraticModel& model, const Vec3& gamma);

/// Every equilibrium of the model (docs/model.md §7): the roots of the secular polynomial
/// (companion-matrix eigenvalues polished by Newton's method on Σ β_g/(κ − d_g)² = 1), the
/// degenerate solutions κ = λ I_i where b_i = 0, circles of equilibria for symmetric bodies, and
/// the case where V is constant. Requires k-independent input only (the gyrostat plays no role at
/// rest).
EquilibriumSet find_equilibria(const QuadraticModel& model);

/// Fibonacci-lattice starts of the search on the sphere.
inline constexpr int kSphereStarts = 400;

/// n nearly uniform points on the unit sphere (Fibonacci lattice).
std::vector<Vec3> fibonacci_sphere(int n);

/// Hessian of V restricted to the unit sphere at a critical point γ of any field, in an
/// orthonormal basis of γ⊥, from the field's moment Jacobian ∂L/∂γ (no cancellation far away).
Eigen::Matrix2d sphere_hessian(const Model& model, const Vec3& gamma);

/// The critical points of V on the sphere reached from `starts` by Levenberg–Marquardt on the
/// moment L(γ) = 0 (tangent steps, renormalised), deduplicated, typed from sphere_hessian and
/// sorted by increasing κ = γ·∂V/∂γ (as find_equilibria). `staude_residual` is NaN (the Staude cone
/// is the quadratic field's). Every orientation is an equilibrium when L vanishes at every start.
EquilibriumSet sphere_equilibria(const Model& model, const std::vector<Vec3>& starts);

/// Every equilibrium of a model in its own field: find_equilibria(QuadraticModel) for the
/// quadratic field; otherwise sphere_equilibria from the quadratic model's equilibria (and points
/// of its circles) plus kSphereStarts lattice points. The count rule (minima − saddles + maxima =
/// 2 when all are non-degenerate) checks that none was missed.
EquilibriumSet find_equilibria(const Model& model);

}  // namespace newtop
