#pragma once
/// \file
/// Uniform (permanent) rotations ω = Ω γ of a body without rotor (k = 0) in the quadratic field
/// (docs/model.md §8). Condition: γ × ((Ω² − λ) Iγ − M g r0) = 0.

#include <optional>
#include <vector>

#include "newtop/model/basic_model.hpp"

namespace newtop {

class Model;  // newtop/model/model.hpp

/// The state of the uniform rotation with angular velocity ω = Ω γ about the unit axis γ.
inline State permanent_rotation(const Body& body, const Vec3& gamma, double Omega) {
  return state_from_omega(body, Omega * gamma, gamma);
}

/// γ·(Iγ × r0): zero on the Staude (Ampère) cone of admissible axes (docs/model.md §7, §8).
double staude_cone(const Body& body, const Vec3& gamma);

/// Ω² along an axis γ of the Staude cone that is not a principal axis (docs/model.md §8):
/// Ω² = λ + M g (γ × r0)·(γ × Iγ) / |γ × Iγ|². NaN where γ × Iγ = 0 (a principal axis).
double cone_omega_squared(const QuadraticModel& model, const Vec3& gamma);

/// One sampled axis of the cone with its Ω²; admissible when Ω² ≥ 0 (either sense of rotation).
struct ConeAxis {
  Vec3 gamma;
  double omega_squared;
  bool admissible;
};

/// The families of permanent rotations of a model (docs/model.md §8).
struct RotationFamilies {
  /// Principal axes ±e_i about which the body spins uniformly at every Ω (r0 = 0, or M g r0
  /// along e_i).
  std::vector<Vec3> principal_axes;
  /// r0 = 0 and λ > 0: the body spins uniformly about any axis with Ω = ±√λ.
  std::optional<double> any_axis_omega;
  /// True when the cone equation holds identically (e.g. a symmetric body with r0 on its axis):
  /// every axis is admissible with Ω² from cone_omega_squared.
  bool cone_is_whole_sphere = false;
  /// Samples of the Staude cone (r0 ≠ 0), both nappes; principal axes left out.
  std::vector<ConeAxis> cone;
};

/// Relative size below which M g r0, or one of its components, counts as zero.
inline constexpr double kRotationDegeneracy = 1e-12;

/// Samples per curve at most: the cone has up to four curves, each sampled on both nappes, so
/// 1e5 samples give at most 8e5 axes (32 MB, a 50 MB CSV), far more than any plot needs.
inline constexpr int kMaxRotationSamples = 100000;

/// The rotation families of docs/model.md §8, with the cone sampled at about `samples` points per
/// curve (2 ≤ samples ≤ kMaxRotationSamples, otherwise InputError naming the bound): γ(τ) ∝ (I −
/// τE)⁻¹ r0 for τ ∈ ℝ (each τ a generator, τ → ±∞ gives r0 itself), plus the extra plane spanned by
/// e_i and (I − I_i E)⁻¹ r0 where x0_i = 0. Throws InputError for a body with a rotor (k ≠ 0),
/// whose rotations are outside docs/model.md §8.
RotationFamilies permanent_rotations(const QuadraticModel& model, int samples);

/// The permanent rotations in the model's own field: permanent_rotations(QuadraticModel) for the
/// quadratic field; otherwise (k = 0) the axes where L(γ) = Ω² γ × Iγ, i.e. the curve
/// γ·(L × (γ × Iγ)) = 0 found by bisection along 2·samples meridians (each in 2·samples arcs),
/// in `cone` with Ω² = L·(γ × Iγ)/|γ × Iγ|², and the principal axes where L = 0 (any Ω).
RotationFamilies permanent_rotations(const Model& model, int samples);

}  // namespace newtop
