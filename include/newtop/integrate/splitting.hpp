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
/// rather than x, y, z. The orderings' errors differ by up to a factor ~40 on a generic body; the
/// default (kick inside, least-moment axis outermost, largest-moment axis in the middle) was the
/// most accurate in the measurement of docs/performance.md, "Ordering of the free-body split".
struct SplitOrdering {
  std::array<int, 3> axes{0, 1, 2};
  bool kick_outside = false;
  bool by_moment = true;
};

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
  explicit SplittingStepper(const CompositionTable& table, SplitOrdering ordering = {})
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
/// series in Horner form, truncated where the next term is below 2.5e-19 |θ| (sin: θ¹¹/11!,
/// cos − 1: θ¹²/12!), several times cheaper than the library calls; otherwise by std::sin and
/// cos − 1 = −2 sin²(θ/2), which avoids the cancellation of cos θ − 1.
inline void sin_cosm1(double theta, double& s, double& cm1) {
  if (std::abs(theta) <= 0.1) {
    const double t2 = theta * theta;
    s = theta * (1 - t2 / 6 * (1 - t2 / 20 * (1 - t2 / 42 * (1 - t2 / 72 * (1 - t2 / 110)))));
    cm1 = -t2 / 2 * (1 - t2 / 12 * (1 - t2 / 30 * (1 - t2 / 56 * (1 - t2 / 90 * (1 - t2 / 132)))));
  } else {
    const double s2 = std::sin(0.5 * theta), c2 = std::cos(0.5 * theta);
    s = 2.0 * s2 * c2;
    cm1 = -2.0 * s2 * s2;
  }
}

/// Increment of the rotation ẋ = x × (w e_i) over time h: x_j' = c x_j + s x_k, x_k' = −s x_j + c
/// x_k with (i, j, k) cyclic, c = cos(wh), s = sin(wh); returns x' − x computed without
/// cancellation.
inline void add_rotation_increment(int i, double cm1, double s, const Vec3& x, Vec3& d) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  d[j] += cm1 * x[j] + s * x[k];
  d[k] += cm1 * x[k] - s * x[j];
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
  Vec3 dm = Vec3::Zero(), dg = Vec3::Zero();
  for (const SubFlow& f : program_) {
    const double hf = f.fraction * h;
    if (f.axis < 0) {
      const Vec3 g = x.gamma + dg;
      dm += hf * g.cross(grad_gamma(model, g));
    } else {
      const int i = axis[f.axis];
      const double theta = hf * (x.m[i] + dm[i] - k[i]) / I[i];
      double s, cm1;
      detail::sin_cosm1(theta, s, cm1);
      const Vec3 m = x.m + dm, g = x.gamma + dg;
      detail::add_rotation_increment(i, cm1, s, m, dm);
      detail::add_rotation_increment(i, cm1, s, g, dg);
    }
  }
  // Kahan summation of the increment into the state.
  const Vec3 am = dm + carry_.m, ag = dg + carry_.gamma;
  const Vec3 m_new = x.m + am, g_new = x.gamma + ag;
  carry_.m = (x.m - m_new) + am;
  carry_.gamma = (x.gamma - g_new) + ag;
  x.m = m_new;
  x.gamma = g_new;
  last_ = x;
}

}  // namespace newtop
