#pragma once
/// \file
/// First integrals of the Euler–Poisson equations (docs/model.md §5).

#include <optional>
#include <string>
#include <vector>

#include "newtop/model/model.hpp"

namespace newtop {

/// I1 = ½ ω·Iω + V(γ): the energy, conserved for every field.
template <Field F>
double energy(const BasicModel<F>& model, const State& s) {
  const Vec3 w = omega(model.body, s);
  return 0.5 * w.dot(model.body.inertia().cwiseProduct(w)) + potential(model, s.gamma);
}

/// I2 = (Iω + k)·γ = m·γ: the area integral, conserved for every V(γ).
inline double area(const State& s) { return s.m.dot(s.gamma); }

/// I3 = γ·γ = 1: the geometric integral (a Casimir).
inline double geometric(const State& s) { return s.gamma.squaredNorm(); }

/// Brun's integral (docs/model.md §5), I4 = |Iω|² − λ ABC γ·I⁻¹γ
///   = A²p² + B²q² + C²r² − λ(BC γ1² + CA γ2² + AB γ3²); conserved when r0 = 0 and k = 0.
double brun(const QuadraticModel& model, const State& s);

/// Lagrange's integral (docs/model.md §5), I4 = C r + k3 = m3; conserved when A = B, x0 = y0 = 0
/// and k = (0, 0, k3).
double lagrange(const QuadraticModel& model, const State& s);

/// Relative tolerance with which the conditions of docs/model.md §5 (A = B, x0 = y0 = 0, k1 = k2 =
/// 0, r0 = 0) are recognised: parameters written in a file to 15 digits and converted to binary
/// must still count as equal.
inline constexpr double kConditionTolerance = 1e-12;

/// True when Brun's integral holds for the model: M g r0 = 0 (no linear term) and k = 0.
bool brun_holds(const QuadraticModel& model);
/// True when Lagrange's integral holds: A = B, M g x0 = M g y0 = 0 and k1 = k2 = 0.
bool lagrange_holds(const QuadraticModel& model);

/// Names of the integrals conserved by this model, in the order energy, area, geometric, brun,
/// lagrange.
std::vector<std::string> conserved_integrals(const QuadraticModel& model);

/// The value of each integral at a state, where it holds (std::nullopt otherwise).
struct IntegralValues {
  double energy = 0.0;
  double area = 0.0;
  double geometric = 0.0;
  std::optional<double> brun;
  std::optional<double> lagrange;
};

/// All integrals of docs/model.md §5 at s; brun and lagrange filled only where they hold.
IntegralValues integrals(const QuadraticModel& model, const State& s);

/// Integrals for any field: energy, area and geometric (the extra integrals need the quadratic
/// field).
template <Field F>
IntegralValues integrals(const BasicModel<F>& model, const State& s) {
  return {energy(model, s), area(s), geometric(s), std::nullopt, std::nullopt};
}

/// The energy of the model's own field: ½ ω·Iω + V(γ) with that field's V. Defined, with
/// integrals(Model, s), beside the fields (src/exact/model_fields.cpp).
double energy(const Model& model, const State& s);

/// The integrals of the model's own field: energy, area and geometric for every field; Brun's and
/// Lagrange's only for the quadratic field, where they hold (in an exact or multipole field
/// neither holds in general).
IntegralValues integrals(const Model& model, const State& s);

/// The names of the integrals conserved in the model's own field (as integrals(Model, s) fills).
std::vector<std::string> conserved_integrals(const Model& model);

/// The drift of the integrals over a run (docs/model.md §5): the largest |I(x) − I(x0)| of each
/// integral that holds, x0 being the first state observed, and the largest |m| seen (the scale of
/// the area integral's drift). The one observer of the integrals' drift of every run: simulate,
/// section, sweep points and ensembles feed it the integrals at each accepted step.
struct IntegralsDrift {
  IntegralValues initial;    ///< the integrals at the first state observed
  IntegralValues max_drift;  ///< max |I − I(x0)|, with brun/lagrange where `initial` has them
  double max_m = 0.0;        ///< max |m| over the states given to observe(model, s)
  bool started = false;

  /// The integrals at the next state; the first one is the start.
  void observe(const IntegralValues& v);
  /// The integrals of the model's own field at s, and |m|.
  void observe(const Model& model, const State& s);
  /// Takes the larger drift of each integral from another run (each against its own start).
  void merge(const IntegralsDrift& other);
};

/// The drift of the Casimirs over a run, relative: max |γ·γ − γ0·γ0| / γ0·γ0 and
/// max |m·γ − m0·γ0| / max |m|. It bounds the state's relative error from below (δ(γ·γ) ≈ 2γ·δγ),
/// so beyond kThreshold = 1e-6 the state is certainly wrong in its sixth digit, and the run is
/// flagged. A splitting method keeps both at round-off (~1e-13 over 1e6 steps). An adaptive method
/// at tolerance τ drifts linearly in time, by 0.1–4 τ per unit of time on the examples (brun,
/// lagrange_like, heavy_top, coulomb at τ = 1e-4 … 1e-12 over T = 100 and 1e4): the flag is raised
/// where τ·T approaches 1e-6 (τ = 1e-8 over 1e4) and never at the default 1e-12 before T ~ 1e6.
struct CasimirDrift {
  static constexpr double kThreshold = 1e-6;
  double geometric = 0.0;
  double area = 0.0;
  bool exceeded() const { return !(geometric <= kThreshold && area <= kThreshold); }
};

/// The Casimirs' relative drift of a run observed by `drift` (area relative to max |m|; 0 when m
/// stayed 0).
CasimirDrift casimir_drift(const IntegralsDrift& drift);

}  // namespace newtop
