#pragma once
/// \file
/// Lie–Poisson splitting of H(m, γ) = H_free(m) + V(γ) (docs/model.md §4) into exactly solvable
/// flows: the free body H_free = Σ_i ½(m_i − k_i)²/I_i and the potential kick m += t γ × ∂V/∂γ. A
/// step is
///   K(b₀h) T(a₁h) K(b₁h) … T(a_s h) K(b_s h),
/// with T the free-body flow (split into axis rotations, or solved exactly) and the coefficients
/// taken from a CompositionTable. Every sub-flow preserves γ·γ and m·γ exactly and is a Poisson
/// map, so every step is a Poisson integrator. One generic loop runs every table, splitting2's two
/// shapes (T K T, K T K) are written out (detail::StepShape); the sub-flows of T are unrolled at
/// compile time (sub_flows.hpp), and the per-model constants are computed once.
///
/// A state with an attitude (OrientedState) carries the rows of R, Rᵀ e_a, through the step as
/// passengers of every sub-flow: each rotation turns them with the same sin θ and cos θ − 1 as it
/// turns γ, the spin and the exact free-body flow apply to them the same map as to γ, and the kick
/// leaves them. R is converted to its quaternion (Eigen) at the end of the step and renormalised;
/// the stepper reports the largest renormalisation, |‖q‖ − 1| (round-off).

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/integrate/sub_flows.hpp"
#include "newtop/model/attitude.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

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
/// The same, with the rotation G of the flow: γ(t) = G γ(0), and every body-frame vector fixed in
/// space moves alike (the rows of the attitude: R(t)ᵀ = G R(0)ᵀ).
State free_body_flow(const Body& body, const State& x, double t, Mat3& rotation);

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

/// The rows of the attitude R (the inertial axes in the body frame, Rᵀ e_a) in the frame P, as the
/// passengers of the sub-flows: (row 0, row 1) in `a`, row 2 in both lanes of `b`.
struct AttitudePhase {
  Phase a, b;
};

template <class P>
inline AttitudePhase to_attitude_phase(const Quaternion& q) {
  const Mat3 R = q.toRotationMatrix();
  AttitudePhase r;
  for (int w = 0; w < 3; ++w) {
    const int i = P::axis[w];
    r.a.v[w] = P::sign[w] * Pair<double>{R(0, i), R(1, i)};
    r.b.v[w] = P::sign[w] * Pair<double>{R(2, i), R(2, i)};
  }
  return r;
}

/// The quaternion of the rows, renormalised; returns |‖q‖ − 1| before the renormalisation.
template <class P>
inline double from_attitude_phase(const AttitudePhase& r, Quaternion& q) {
  Mat3 R;
  for (int w = 0; w < 3; ++w) {
    const int i = P::axis[w];
    R(0, i) = P::sign[w] * r.a.m(w);
    R(1, i) = P::sign[w] * r.a.g(w);
    R(2, i) = P::sign[w] * r.b.m(w);
  }
  q = Quaternion(R);
  const double n = q.norm();
  q.coeffs() /= n;
  return std::abs(n - 1.0);
}

/// Both lanes of a passenger mapped by the body-frame matrix G.
template <class P>
inline void apply_rotation(const Mat3& G, Phase& a) {
  Vec3 x, y;
  for (int w = 0; w < 3; ++w) {
    x[P::axis[w]] = P::sign[w] * a.m(w);
    y[P::axis[w]] = P::sign[w] * a.g(w);
  }
  x = G * x;
  y = G * y;
  for (int w = 0; w < 3; ++w) a.set(w, P::sign[w] * x[P::axis[w]], P::sign[w] * y[P::axis[w]]);
}

/// The kick over t: m += t γ × ∂V/∂γ, the moment computed by moment(model, γ) in the body frame.
template <class P, Field F>
[[gnu::always_inline]] inline void kick(Phase& z, const BasicModel<F>& model, double t) {
  Vec3 g;
  for (int w = 0; w < 3; ++w) g[P::axis[w]] = P::sign[w] * z.g(w);
  const Vec3 L = moment(model, g);
  for (int w = 0; w < 3; ++w) z.v[w] += Pair<double>{(t * P::sign[w]) * L[P::axis[w]], 0.0};
}

/// T(t) by rotations about the three axes, Strang-split (FreeBodySplit::axes).
struct AxesFlow {
  template <class P, class... A>
  [[gnu::always_inline]] static void flow(Phase& z, const SplitFrame& f, const Body&, double t,
                                          A&... a) {
    const double t2 = 0.5 * t;
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0], a...);
    axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1], a...);
    axis_flow<2>(z, t * f.rate[2], -t * f.k_over_i[2], a...);
    axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1], a...);
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0], a...);
  }
};

/// T(t) by the spin split (FreeBodySplit::spin); Gyrostat: k_r ≠ 0.
template <bool Gyrostat>
struct SpinFlow {
  template <class P, class... A>
  [[gnu::always_inline]] static void flow(Phase& z, const SplitFrame& f, const Body&, double t,
                                          A&... a) {
    const double t2 = 0.5 * t;
    spin_flow(z, t * f.inv_ref, a...);
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0], a...);
    if constexpr (Gyrostat) {
      axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1], a...);
      axis_flow<2>(z, 0.0, -t * f.k_over_i[2], a...);
      axis_flow<1>(z, t2 * f.rate[1], -t2 * f.k_over_i[1], a...);
    } else {
      axis_flow<1>(z, t * f.rate[1], -t * f.k_over_i[1], a...);
    }
    axis_flow<0>(z, t2 * f.rate[0], -t2 * f.k_over_i[0], a...);
  }
};

/// T(t) exact (FreeBodySplit::exact).
struct ExactFlow {
  template <class P, class... A>
  [[gnu::always_inline]] static void flow(Phase& z, const SplitFrame&, const Body& body, double t,
                                          A&... a) {
    State x;
    to_state<P>(z, x);
    if constexpr (sizeof...(A) == 0) {
      z = to_phase<P>(free_body_flow(body, x, t));
    } else {
      Mat3 G;
      z = to_phase<P>(free_body_flow(body, x, t, G));
      (apply_rotation<P>(G, a), ...);
    }
  }
};

/// What a step kernel returns: nothing, or with an attitude its renormalisation |‖q‖ − 1|.
template <class X>
using StepResult = std::conditional_t<kOriented<X>, double, void>;

/// The shape of a step known at compile time: any table (the loop over the coefficients, a zero
/// kick skipped), or splitting2's T(a₁h) K(b₁h) T(a₂h) (b₀ = b₂ = 0) and K(b₀h) T(a₁h) K(b₁h)
/// written out, without the loop and the tests of b (the state then stays in registers).
enum class StepShape { any, tkt, ktk };

/// The shape of the coefficients c.
inline StepShape step_shape(const SplittingCoefficients& c) {
  if (c.a.size() == 2 && c.b[0] == 0.0 && c.b[1] != 0.0 && c.b[2] == 0.0) return StepShape::tkt;
  if (c.a.size() == 1 && c.b[0] != 0.0 && c.b[1] != 0.0) return StepShape::ktk;
  return StepShape::any;
}

/// All stages of a step, the last kick included, for coefficients of the shape S.
template <class P, class T, StepShape S, Field F, class... A>
[[gnu::always_inline]] inline void run_stages(Phase& z, const BasicModel<F>& model,
                                              const SplitFrame& f, const SplittingCoefficients& c,
                                              double h, A&... passengers) {
  const double* a = c.a.data();
  const double* b = c.b.data();
  if constexpr (S == StepShape::tkt) {
    T::template flow<P>(z, f, model.body, a[0] * h, passengers...);
    kick<P>(z, model, b[1] * h);
    T::template flow<P>(z, f, model.body, a[1] * h, passengers...);
  } else if constexpr (S == StepShape::ktk) {
    kick<P>(z, model, b[0] * h);
    T::template flow<P>(z, f, model.body, a[0] * h, passengers...);
    kick<P>(z, model, b[1] * h);
  } else {
    const std::size_t s = c.a.size();
    for (std::size_t i = 0; i < s; ++i) {
      if (b[i] != 0.0) kick<P>(z, model, b[i] * h);
      T::template flow<P>(z, f, model.body, a[i] * h, passengers...);
    }
    if (b[s] != 0.0) kick<P>(z, model, b[s] * h);
  }
}

/// One step in the frame P for coefficients of the shape S (see run_stages), an attitude's rows
/// carried as passengers.
template <class P, class T, StepShape S, Field F, class X>
[[gnu::flatten]] StepResult<X> run_step(const BasicModel<F>& model, X& x, const SplitFrame& f,
                                        const SplittingCoefficients& c, double h) {
  Phase z = to_phase<P>(x);
  if constexpr (kOriented<X>) {
    AttitudePhase r = to_attitude_phase<P>(x.q);
    run_stages<P, T, S>(z, model, f, c, h, r.a, r.b);
    to_state<P>(z, x);
    return from_attitude_phase<P>(r, x.q);
  } else {
    run_stages<P, T, S>(z, model, f, c, h);
    to_state<P>(z, x);
  }
}

template <Field F, class X = State>
using StepKernel = StepResult<X> (*)(const BasicModel<F>&, X&, const SplitFrame&,
                                     const SplittingCoefficients&, double);

/// The kernel of T for the shape S and the permutation (axis[0], axis[1], axis[2]).
template <class T, StepShape S, Field F, class X = State>
StepKernel<F, X> step_kernel(const std::array<int, 3>& axis) {
  switch (axis[0] * 3 + axis[1]) {
    case 1:
      return &run_step<Axes<0, 1, 2>, T, S, F, X>;
    case 2:
      return &run_step<Axes<0, 2, 1>, T, S, F, X>;
    case 3:
      return &run_step<Axes<1, 0, 2>, T, S, F, X>;
    case 5:
      return &run_step<Axes<1, 2, 0>, T, S, F, X>;
    case 6:
      return &run_step<Axes<2, 0, 1>, T, S, F, X>;
    default:
      return &run_step<Axes<2, 1, 0>, T, S, F, X>;
  }
}

/// The kernel of T for the permutation and the shape of the coefficients.
template <class T, Field F, class X = State>
StepKernel<F, X> step_kernel(const std::array<int, 3>& axis, StepShape shape) {
  switch (shape) {
    case StepShape::tkt:
      return step_kernel<T, StepShape::tkt, F, X>(axis);
    case StepShape::ktk:
      return step_kernel<T, StepShape::ktk, F, X>(axis);
    default:
      return step_kernel<T, StepShape::any, F, X>(axis);
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
        coefficients_(splitting_coefficients(table, ordering)),
        shape_(detail::step_shape(coefficients_)) {}

  int order() const { return order_; }
  /// The most sub-flows (kicks, rotations, spins or exact free-body flows) one step applies.
  std::size_t stages() const;
  /// The split of the free body and the working axes.
  const SplitOrdering& ordering() const { return ordering_; }
  /// The composition's coefficients in the order they are applied.
  const SplittingCoefficients& coefficients() const { return coefficients_; }

  /// One step of x (m, γ, and the attitude when X = OrientedState).
  template <Field F, PhaseState X>
  void step(const BasicModel<F>& model, X& x, double h);

  /// The largest renormalisation |‖q‖ − 1| of the attitude in one step so far (0 without one).
  double attitude_projection() const { return projection_; }

 private:
  int order_;
  SplitOrdering ordering_;
  SplittingCoefficients coefficients_;
  detail::StepShape shape_;
  // Per-model constants, recomputed when the body changes.
  Vec3 inertia_key_ = Vec3::Constant(NAN);
  Vec3 gyrostat_key_ = Vec3::Constant(NAN);
  SplitFrame frame_;
  double projection_ = 0.0;
};

template <Field F, PhaseState X>
void SplittingStepper::step(const BasicModel<F>& model, X& x, double h) {
  if (model.body.inertia() != inertia_key_ || model.body.gyrostat() != gyrostat_key_) {
    frame_ = split_frame(model.body, ordering_);
    inertia_key_ = model.body.inertia();
    gyrostat_key_ = model.body.gyrostat();
  }
  detail::StepKernel<F, X> kernel = nullptr;
  switch (ordering_.free_body) {
    case FreeBodySplit::axes:
      kernel = detail::step_kernel<detail::AxesFlow, F, X>(frame_.axis, shape_);
      break;
    case FreeBodySplit::spin:
      kernel = frame_.gyrostat_ref
                   ? detail::step_kernel<detail::SpinFlow<true>, F, X>(frame_.axis, shape_)
                   : detail::step_kernel<detail::SpinFlow<false>, F, X>(frame_.axis, shape_);
      break;
    case FreeBodySplit::exact:
      kernel =
          &detail::run_step<detail::Axes<0, 1, 2>, detail::ExactFlow, detail::StepShape::any, F, X>;
      break;
  }
  if constexpr (kOriented<X>) {
    projection_ = std::max(projection_, kernel(model, x, frame_, coefficients_, h));
  } else {
    kernel(model, x, frame_, coefficients_, h);
  }
}

}  // namespace newtop
