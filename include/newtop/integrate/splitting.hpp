#pragma once
/// \file
/// Lie–Poisson splitting of H(m, γ) = H_free(m) + V(γ) (spec §4) into exactly solvable flows: the
/// free body H_free = Σ_i ½(m_i − k_i)²/I_i and the potential kick m += t γ × ∂V/∂γ. A step is
///   K(b₀h) T(a₁h) K(b₁h) … T(a_s h) K(b_s h),
/// with T the free-body flow (split into axis rotations, or solved exactly) and the coefficients
/// taken from a CompositionTable. Every sub-flow preserves γ·γ and m·γ exactly and is a Poisson
/// map, so every step is a Poisson integrator. One generic loop runs every table; the sub-flows of
/// T are unrolled at compile time (sub_flows.hpp), and the per-model constants are computed once.

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/integrate/sub_flows.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// How the free-body flow T is computed.
enum class FreeBodySplit {
  /// Strang splitting into rotations about the three body axes:
  /// T(t) = R_i(t/2) R_j(t/2) R_k(t) R_j(t/2) R_i(t/2), with (i, j, k) = axes.
  axes,
  /// ½ m·I⁻¹m = ½|m|²/I_r + ½ Σ α_i m_i² with α_i = 1/I_i − 1/I_r and r = axes[2]: the |m|² flow (γ
  /// turns about m, m fixed) commutes with the rest and is exact; the rest is split into rotations
  /// about the two other axes: T(t) = S(t) R'_i(t/2) R'_j(t) R'_i(t/2), (i, j) = (axes[0],
  /// axes[1]).
  /// A gyrostatic k_r ≠ 0 adds a rotation of constant angle about e_r in the middle.
  spin,
  /// The exact Euler–Poinsot flow (free_body_flow.hpp); needs k = 0.
  exact,
};

/// How the base method is built from the free-body flow T and the kick K.
/// kick_outside: K(h/2) T(h) K(h/2); otherwise T(h/2) K(h) T(h/2). With by_moment, axes name the
/// axes by increasing moment (0 = least, 2 = largest) rather than x, y, z. The orderings' errors
/// differ by up to a factor ~40 on a generic body (docs/performance.md, "Ordering of the split").
struct SplitOrdering {
  std::array<int, 3> axes{0, 1, 2};
  bool kick_outside = false;
  bool by_moment = true;
  FreeBodySplit free_body = FreeBodySplit::axes;
};

/// The measured best ordering for a table (docs/performance.md): see splitting.cpp.
SplitOrdering default_ordering(const CompositionTable& table);

/// The step as alternating kicks and free-body flows, K(b₀h) T(a₁h) K(b₁h) … T(a_s h) K(b_s h)
/// (b.size() = a.size() + 1; a zero kick is skipped).
struct SplittingCoefficients {
  std::vector<double> a;
  std::vector<double> b;
};

/// The coefficients of a table built with an ordering: a composition Φ(γ_s h) … Φ(γ_1 h) of the
/// symmetric base Φ (adjacent kicks merged, and adjacent free-body flows when T is exact), or a
/// near-integrable table's own (a, b). Throws InputError for a near-integrable table with a split
/// free body (its order needs the exact flow).
SplittingCoefficients splitting_coefficients(const CompositionTable& table,
                                             const SplitOrdering& ordering);

/// The working frame of the split: working axis w is body axis `axis[w]` with sign `sign[w]` (a
/// proper signed permutation, so the equations keep their form), and the per-model constants of
/// the sub-flows in working order.
struct SplitFrame {
  std::array<int, 3> axis{0, 1, 2};
  std::array<double, 3> sign{1.0, 1.0, 1.0};
  std::array<double, 3> rate{};      ///< rotation rate per unit m_w: 1/I_w (axes), α_w (spin)
  std::array<double, 3> k_over_i{};  ///< k_w/I_w
  double inv_ref = 0.0;              ///< spin split: 1/I_r
  bool gyrostat_ref = false;         ///< spin split: k_r ≠ 0
};

SplitFrame split_frame(const Body& body, const SplitOrdering& ordering);

/// Exact free-body flow of a body-frame state over t (free_body_flow.cpp); declared here so that
/// the stepper can run it as T.
State free_body_flow(const Body& body, const State& x, double t);

namespace detail {

/// A working frame known at compile time: working axis w is body axis Axis_w, the last one
/// reversed when the permutation is odd, so that the frame is proper and cross products keep
/// their form. One kernel per permutation keeps every index a constant (no trips through memory).
template <int A0, int A1, int A2>
struct Axes {
  static constexpr int axis[3] = {A0, A1, A2};
  static constexpr bool odd = ((A0 > A1) + (A0 > A2) + (A1 > A2)) % 2 == 1;
  static constexpr double sign[3] = {1.0, 1.0, odd ? -1.0 : 1.0};
  static int index() { return A0 * 3 + A1; }  // unique per permutation, < 9
};

template <class P>
inline Phase to_phase(const State& x) {
  Phase z;
  for (int w = 0; w < 3; ++w)
    z.v[w] = P::sign[w] * Pair<double>{x.m[P::axis[w]], x.gamma[P::axis[w]]};
  return z;
}

template <class P>
inline void to_state(const Phase& z, State& x) {
  for (int w = 0; w < 3; ++w) {
    x.m[P::axis[w]] = P::sign[w] * z.m(w);
    x.gamma[P::axis[w]] = P::sign[w] * z.g(w);
  }
}

/// The kick over t: m += t γ × ∂V/∂γ, the moment computed by moment(model, γ) in the body frame.
template <class P, Field F>
inline void kick(Phase& z, const BasicModel<F>& model, double t) {
  Vec3 g;
  for (int w = 0; w < 3; ++w) g[P::axis[w]] = P::sign[w] * z.g(w);
  const Vec3 L = moment(model, g);
  for (int w = 0; w < 3; ++w) z.v[w] += Pair<double>{(t * P::sign[w]) * L[P::axis[w]], 0.0};
}

/// T(t) by rotations about the three axes, Strang-split (FreeBodySplit::axes).
struct AxesFlow {
  template <class P>
  static void flow(Phase& z, const SplitFrame& f, const Body&, double t) {
    const double t2 = 0.5 * t;
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0]);
    axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1]);
    axis_flow<2>(z, t * f.rate[2], -t * f.k_over_i[2]);
    axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1]);
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0]);
  }
};

/// T(t) by the spin split (FreeBodySplit::spin); Gyrostat: k_r ≠ 0.
template <bool Gyrostat>
struct SpinFlow {
  template <class P>
  static void flow(Phase& z, const SplitFrame& f, const Body&, double t) {
    const double t2 = 0.5 * t;
    spin_flow(z, t * f.inv_ref);
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0]);
    if constexpr (Gyrostat) {
      axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1]);
      axis_flow<2>(z, 0.0, -t * f.k_over_i[2]);
      axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1]);
    } else {
      axis_flow<1>(z, t * f.rate[1], -t * f.k_over_i[1]);
    }
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0]);
  }
};

/// T(t) exact (FreeBodySplit::exact).
struct ExactFlow {
  template <class P>
  static void flow(Phase& z, const SplitFrame&, const Body& body, double t) {
    State x;
    to_state<P>(z, x);
    z = to_phase<P>(free_body_flow(body, x, t));
  }
};

/// One step in the frame P: the generic loop over the coefficients.
template <class P, class T, Field F>
[[gnu::flatten]] void run_step(const BasicModel<F>& model, State& x, const SplitFrame& f,
                               const SplittingCoefficients& c, double h) {
  Phase z = to_phase<P>(x);
  const std::size_t s = c.a.size();
  for (std::size_t i = 0; i < s; ++i) {
    if (c.b[i] != 0.0) kick<P>(z, model, c.b[i] * h);
    T::template flow<P>(z, f, model.body, c.a[i] * h);
  }
  if (c.b[s] != 0.0) kick<P>(z, model, c.b[s] * h);
  to_state<P>(z, x);
}

template <Field F>
using StepKernel = void (*)(const BasicModel<F>&, State&, const SplitFrame&,
                            const SplittingCoefficients&, double);

/// The kernel of T for the permutation (axis[0], axis[1], axis[2]).
template <class T, Field F>
StepKernel<F> step_kernel(const std::array<int, 3>& axis) {
  switch (axis[0] * 3 + axis[1]) {
    case 1:
      return &run_step<Axes<0, 1, 2>, T, F>;
    case 2:
      return &run_step<Axes<0, 2, 1>, T, F>;
    case 3:
      return &run_step<Axes<1, 0, 2>, T, F>;
    case 5:
      return &run_step<Axes<1, 2, 0>, T, F>;
    case 6:
      return &run_step<Axes<2, 0, 1>, T, F>;
    default:
      return &run_step<Axes<2, 1, 0>, T, F>;
  }
}

}  // namespace detail

/// Lie–Poisson splitting integrator of any table (composition or near-integrable).
///
/// Round-off: each rotation adds to the state an increment computed in a cancellation-free form
/// ((cos θ − 1) x_j + sin θ x_k), rounded once; the rounding errors are unbiased, so γ·γ, m·γ and
/// the energy follow Brouwer's law (errors ∝ √t; docs/performance.md).
class SplittingStepper {
 public:
  explicit SplittingStepper(const CompositionTable& table)
      : SplittingStepper(table, default_ordering(table)) {}
  SplittingStepper(const CompositionTable& table, SplitOrdering ordering)
      : order_(table.order),
        ordering_(ordering),
        coefficients_(splitting_coefficients(table, ordering)) {}

  int order() const { return order_; }
  /// The most sub-flows (kicks, rotations, spins or exact free-body flows) one step applies.
  std::size_t stages() const;

  template <Field F>
  void step(const BasicModel<F>& model, State& x, double h);

 private:
  int order_;
  SplitOrdering ordering_;
  SplittingCoefficients coefficients_;
  // Per-model constants, recomputed when the body changes.
  Vec3 inertia_key_ = Vec3::Constant(NAN);
  Vec3 gyrostat_key_ = Vec3::Constant(NAN);
  SplitFrame frame_;
};

template <Field F>
void SplittingStepper::step(const BasicModel<F>& model, State& x, double h) {
  if (model.body.inertia() != inertia_key_ || model.body.gyrostat() != gyrostat_key_) {
    frame_ = split_frame(model.body, ordering_);
    inertia_key_ = model.body.inertia();
    gyrostat_key_ = model.body.gyrostat();
  }
  detail::StepKernel<F> kernel = nullptr;
  switch (ordering_.free_body) {
    case FreeBodySplit::axes:
      kernel = detail::step_kernel<detail::AxesFlow, F>(frame_.axis);
      break;
    case FreeBodySplit::spin:
      kernel = frame_.gyrostat_ref ? detail::step_kernel<detail::SpinFlow<true>, F>(frame_.axis)
                                   : detail::step_kernel<detail::SpinFlow<false>, F>(frame_.axis);
      break;
    case FreeBodySplit::exact:
      kernel = &detail::run_step<detail::Axes<0, 1, 2>, detail::ExactFlow, F>;
      break;
  }
  kernel(model, x, frame_, coefficients_, h);
}

}  // namespace newtop
