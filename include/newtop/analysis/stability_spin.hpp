#pragma once
/// \file
/// Spin about a principal axis pointing at the centre (docs/model.md §9): Beletsky's closed form,
/// the characteristic polynomial with the centre of mass on the axis, numerical thresholds and
/// scans.

#include <optional>
#include <string>
#include <vector>

#include "newtop/analysis/stability.hpp"

namespace newtop {

/// Rank of the spin axis's moment among the three: least, middle or largest (ties count as the
/// larger rank only when strictly greater than the other moment: A = B < C makes C largest and
/// A, B least).
enum class AxisClass { least, middle, largest };
const char* to_string(AxisClass c);
AxisClass axis_class(const Body& body, int axis);

/// γ = e_axis, ω = Ω e_axis: the spin about a principal axis pointing at the centre. A fixed point
/// when M g r0 is along e_axis (always for r0 = 0).
State principal_spin(const Body& body, int axis, double Omega);

/// Moments relabelled so that the spin axis plays C (docs/model.md §9): (A, B, C) = (I_j, I_k,
/// I_axis) with (axis, j, k) cyclic.
Vec3 spin_frame_moments(const Body& body, int axis);

/// Coefficients (1, −[(a + b)λ − (1 + ab)Ω²], ab (λ − Ω²)²) of Beletsky's quadratic in σ = s²
/// (docs/model.md §9, r0 = 0), a = (C − B)/A, b = (C − A)/B in the spin frame.
Eigen::Vector3d beletsky_polynomial(const Body& body, double lambda, int axis, double Omega);

/// Ω* = √λ (√a + √b)/(1 + √(ab)) (docs/model.md §9): the spin is linearly stable for Ω > Ω* and
/// unstable below. Defined for λ > 0 when the spin axis has the largest moment (a, b ≥ 0, a + b >
/// 0); nullopt otherwise (least: stable for all Ω; middle: unstable except Ω = √λ).
std::optional<double> beletsky_threshold(const Body& body, double lambda, int axis);

/// Coefficients (c, 0, β, 0, AB) (constant term first) of the quartic AB s⁴ + β s² + c of
/// docs/model.md §9, the characteristic polynomial on the leaf with r0 = z0 e_z (spin frame), k_z =
/// M g z0.
Eigen::Matrix<double, 5, 1> axis_spin_polynomial(const QuadraticModel& model, int axis,
                                                 double Omega);

/// Spectral verdict of the spin at one Ω (the spin must be a fixed point).
Spectrum spin_stability(const QuadraticModel& model, int axis, double Omega);

/// Upper end of the Ω range searched by numeric_threshold: 8 (√(|λ| max I / min I) +
/// √(|M g r0| max I) / min I), above every threshold of docs/model.md §9 (Ω* ≤ 2√λ; the sleeping
/// top's 2√(A M g z0)/C).
double spin_omega_range(const QuadraticModel& model);

/// Ω ≥ 0 above which the spin stays linearly stable up to spin_omega_range: found by sampling
/// `samples` points and bisecting the last unstable → stable change to round-off. nullopt when the
/// spin is stable everywhere or still unstable at the end of the range.
std::optional<double> numeric_threshold(const QuadraticModel& model, int axis, int samples = 200);

/// One point of a stability diagram.
struct ScanPoint {
  double omega;
  double max_real_part;
  bool linearly_stable;
  std::optional<bool> lyapunov_stable;
};

/// Points of scan_omega at most: 1e5 eigenvalue problems take well under a second, and their JSON
/// list is ~10 MB.
inline constexpr int kMaxScanPoints = 100000;

/// Stability along Ω ∈ [w1, w2] at n ≥ 2 equally spaced points (n = 1: w1 only), n ≤
/// kMaxScanPoints; throws InputError otherwise or for a non-finite end.
std::vector<ScanPoint> scan_omega(const QuadraticModel& model, int axis, double w1, double w2,
                                  int n);

/// A parameter of a spin's stability diagram and its value: `omega` (the spin rate Ω), `lambda`
/// (λ of the Coulomb field), `A`, `B` or `C` (the principal moments).
struct SpinParameter {
  std::string name;
  double value;
};

/// Throws InputError unless `name` is omega, lambda, A, B or C; `what` names the option.
void check_spin_parameter(const std::string& what, const std::string& name);

/// The spin's spectrum about `axis` at Ω = omega in the model `base` with the parameters replaced
/// (the body rebuilt from its principal moments, mass and centre of mass; the field as Coulomb's
/// with base's g and the λ given). nullopt where the parameters make no body (a moment ≤ 0, the
/// triangle inequality fails): the point is nonphysical.
std::optional<Spectrum> spin_stability_at(const QuadraticModel& base, int axis, double omega,
                                          const std::vector<SpinParameter>& parameters);

/// The verdict at one point of a two-parameter diagram.
enum class GridVerdict { stable, unstable, nonphysical };
/// "stable", "unstable", "nonphysical".
const char* to_string(GridVerdict v);

/// A two-parameter stability diagram of a spin (`newtop stability --scan`): the point (first[i],
/// second[k]) at index i·second.size() + k (the second parameter varies fastest).
struct StabilityGrid {
  std::string first_name, second_name;
  std::vector<double> first, second;
  std::vector<double> max_real_part;  ///< NaN where nonphysical
  std::vector<GridVerdict> verdict;
};

}  // namespace newtop
