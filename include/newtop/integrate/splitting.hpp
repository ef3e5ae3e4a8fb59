#pragma once
/// \file
/// Lie–Poisson splitting of H(m, γ) = Σ_i ½(m_i − k_i)²/I_i + V(γ) (spec §4) into exactly solvable
/// flows: rotations of m and γ about the body axes e_i, and the potential kick m += h γ × ∂V/∂γ.
/// Every sub-flow preserves γ·γ and m·γ exactly and is a Poisson map, so any composition is a
/// Poisson integrator. A symmetric second-order base is composed by a CompositionTable to order
/// 4, 6 or 8; one generic loop runs every table.

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/model/model.hpp"

namespace newtop {

/// How the symmetric base method is built from the sub-flows T_i (rotation about e_i) and K (kick).
/// kick_outside: K(h/2) T(h) K(h/2); otherwise T(h/2) K(h) T(h/2). The free-body part T(h) is
/// itself the symmetric (Strang) composition T_i(h/2) T_j(h/2) T_k(h) T_j(h/2) T_i(h/2) with (i, j,
/// k) = axes. With by_moment, axes name the axes by increasing moment (0 = least, 2 = largest)
/// rather than x, y, z. The orderings' errors differ by up to a factor ~40 on a generic body
/// (docs/performance.md, "Ordering of the free-body split").
struct SplitOrdering {
  std::array<int, 3> axes{0, 1, 2};
  bool kick_outside = false;
  bool by_moment = true;
};

/// The measured best ordering for a table: least-moment axis outermost, largest in the middle;
/// the kick inside for the second-order method (13× smaller state error than outside), outside for
/// the compositions (same error within a factor 1.7, 40% fewer sub-flows once the kicks of
/// adjacent stages merge).
inline SplitOrdering default_ordering(const CompositionTable& table) {
  return SplitOrdering{{0, 1, 2}, table.order > 2, true};
}

/// One sub-flow with its fraction of the step: axis −1 is the kick, 0..2 a rotation about e_axis.
struct SubFlow {
  int axis;
  double fraction;
};

/// Flattened sequence of sub-flows of a composition, with adjacent kicks (or adjacent rotations
/// about the same axis) merged.
std::vector<SubFlow> composition_program(const CompositionTable& table, const SplitOrdering& order);

/// Exact Lie–Poisson splitting integrator of any order given by a composition table.
///
/// Round-off: within a step the sub-flows act on y + d and accumulate only the small increment d
/// (rotations in the form δx = (cos θ − 1) x + sin θ (…), with cos θ − 1 = −2 sin²(θ/2)), and the
/// increment is added to the state by compensated (Kahan) summation whose carry lives in the
/// stepper. The carry is dropped whenever the state handed in is not the one last returned.
class SplittingStepper {
 public:
  explicit SplittingStepper(const CompositionTable& table)
      : SplittingStepper(table, default_ordering(table)) {}
  SplittingStepper(const CompositionTable& table, SplitOrdering ordering)
      : order_(table.order),
        by_moment_(ordering.by_moment),
        program_(composition_program(table, ordering)) {}

  int order() const { return order_; }
  /// Number of sub-flows (kicks + rotations) per step.
  std::size_t stages() const { return program_.size(); }

  template <Field F>
  void step(const BasicModel<F>& model, State& x, double h);

 private:
  int order_;
  bool by_moment_;
  std::vector<SubFlow> program_;
  State carry_{Vec3::Zero(), Vec3::Zero()};
  State last_{Vec3::Constant(NAN), Vec3::Constant(NAN)};
};

namespace detail {

/// sin θ and cos θ − 1 to round-off. For |θ| ≤ 0.1 (the usual case: θ = h ω_i) by their Taylor
/// series, truncated where the next term is below 2.5e-19 |θ| (for |θ| ≤ 0.01: after θ⁷ and θ⁸;
/// otherwise after θ¹¹ and θ¹²), evaluated with constant coefficients (no division) in Estrin's
/// scheme so that the dependency chain stays short; for larger angles by std::sin and
/// cos θ − 1 = −2 sin²(θ/2), which avoids the cancellation of cos θ − 1.
inline void sin_cosm1(double theta, double& s, double& cm1) {
  // Taylor coefficients (−1)ⁿ/(2n+1)! and (−1)ⁿ/(2n)!.
  constexpr double s1 = -1.0 / 6, s2 = 1.0 / 120, s3 = -1.0 / 5040, s4 = 1.0 / 362880,
                   s5 = -1.0 / 39916800;
  constexpr double c1 = -1.0 / 2, c2 = 1.0 / 24, c3 = -1.0 / 720, c4 = 1.0 / 40320,
                   c5 = -1.0 / 3628800, c6 = 1.0 / 479001600;
  const double a = std::abs(theta);
  if (a <= 0.01) {
    const double t2 = theta * theta, t4 = t2 * t2;
    s = theta + theta * t2 * ((s1 + t2 * s2) + t4 * s3);
    cm1 = t2 * ((c1 + t2 * c2) + t4 * (c3 + t2 * c4));
  } else if (a <= 0.1) {
    const double t2 = theta * theta, t4 = t2 * t2, t8 = t4 * t4;
    s = theta + theta * t2 * ((s1 + t2 * s2) + t4 * (s3 + t2 * s4) + t8 * s5);
    cm1 = t2 * ((c1 + t2 * c2) + t4 * (c3 + t2 * c4) + t8 * (c5 + t2 * c6));
  } else {
    const double sin_half = std::sin(0.5 * theta), cos_half = std::cos(0.5 * theta);
    s = 2.0 * sin_half * cos_half;
    cm1 = -2.0 * sin_half * sin_half;
  }
}

}  // namespace detail

template <Field F>
void SplittingStepper::step(const BasicModel<F>& model, State& x, double h) {
  if (!(x == last_)) carry_ = State{Vec3::Zero(), Vec3::Zero()};
  const Vec3& I = model.body.inertia();
  const Vec3& k = model.body.gyrostat();
  std::array<int, 3> axis{0, 1, 2};  // program axis -> body axis
  if (by_moment_) {
    if (I[axis[0]] > I[axis[1]]) std::swap(axis[0], axis[1]);
    if (I[axis[1]] > I[axis[2]]) std::swap(axis[1], axis[2]);
    if (I[axis[0]] > I[axis[1]]) std::swap(axis[0], axis[1]);
  }
  constexpr int next[3] = {1, 2, 0};
  const double inv_I[3] = {1.0 / I[0], 1.0 / I[1], 1.0 / I[2]};
  // y = (m, γ) at the start of the step; d = the increment accumulated by the sub-flows so far,
  // kept separately so that it carries no round-off of |y|; z = y + d (rounded) is the running
  // state from which each sub-flow computes its increment.
  const double y[6] = {x.m[0], x.m[1], x.m[2], x.gamma[0], x.gamma[1], x.gamma[2]};
  double d[6] = {0, 0, 0, 0, 0, 0};
  double z[6] = {y[0], y[1], y[2], y[3], y[4], y[5]};
  for (const SubFlow& f : program_) {
    const double hf = f.fraction * h;
    if (f.axis < 0) {
      const Vec3 g(z[3], z[4], z[5]);
      const Vec3 tau = hf * g.cross(grad_gamma(model, g));
      for (int n = 0; n < 3; ++n) {
        d[n] += tau[n];
        z[n] += tau[n];
      }
      continue;
    }
    // Rotation about e_i by θ = h ω_i: x_j' = c x_j + s x_k, x_k' = −s x_j + c x_k, written as
    // increments (c − 1) x_j + s x_k and (c − 1) x_k − s x_j, for m and for γ.
    const int i = axis[f.axis], j = next[i], kk = next[j];
    double s, cm1;
    // θ = h (m_i − k_i) / I_i; h/I_i stays off the serial dependency chain through z, which is
    // what bounds the speed of a step.
    detail::sin_cosm1((z[i] - k[i]) * (hf * inv_I[i]), s, cm1);
    for (int o = 0; o <= 3; o += 3) {
      const double a = z[o + j], b = z[o + kk];
      const double da = cm1 * a + s * b, db = cm1 * b - s * a;
      d[o + j] += da;
      d[o + kk] += db;
      z[o + j] += da;
      z[o + kk] += db;
    }
  }
  // Kahan summation of the increment into the state.
  double* c = carry_.m.data();
  double* cg = carry_.gamma.data();
  for (int n = 0; n < 6; ++n) {
    double& carry = n < 3 ? c[n] : cg[n - 3];
    const double add = d[n] + carry;
    const double sum = y[n] + add;
    carry = (y[n] - sum) + add;
    (n < 3 ? x.m[n] : x.gamma[n - 3]) = sum;
  }
  last_ = x;
}

}  // namespace newtop
