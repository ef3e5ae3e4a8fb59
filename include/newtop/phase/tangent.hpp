#pragma once
/// \file
/// The tangent map of the integrators (docs/chaos.md): a step carries, beside the state x = (m, γ),
/// tangent vectors δx = (δm, δγ) ∈ R⁶ (the columns of a 6 × n matrix, n ≤ 6) through the
/// derivative of the map actually iterated.
///
/// - Splitting methods: the exact derivative of each sub-flow of the composition (splitting.hpp).
///   A rotation about the body axis e_a by φ = t (m_a − k_a)/I_a, x' = R_a(φ) x for x = m and
///   x = γ, has δx' = R_a(φ) δx + (x' × e_a) (t/I_a) δm_a (dR/dφ x = x' × e_a). The spin of the
///   spin split, γ' = R(u) γ with the rotation vector u = −τ m (m fixed), has δm' = δm and
///   δγ' = R(u) δγ + τ γ' × (J(u) δm), J(u) = 1 + f₂ [u]× + f₃ [u]×² the left Jacobian of SO(3)
///   (f₂ = (1 − cos φ)/φ², f₃ = (φ − sin φ)/φ³, φ = |u|). The kick
///   m' = m + t L(γ) has δm' = δm + t (∂L/∂γ) δγ, δγ' = δγ, with ∂L/∂γ = [γ]× ∂²V/∂γ² − [∂V/∂γ]×
///   from each field's Hessian (moment_jacobian).
/// - Runge–Kutta methods: the variational equations δẋ = Df(x) δx integrated with the state by the
///   same formula.

#include <array>
#include <cmath>
#include <vector>

#include "newtop/integrate/methods.hpp"
#include "newtop/phase/tangent_vectors.hpp"

namespace newtop::phase {

/// A fixed-step tangent stepper: step(model, x, V, h) advances x and its tangent vectors V by h.
template <class S, class M>
concept TangentFixedStepper = requires(S s, const M& model, State& x, Tangent& V, double h) {
  s.step(model, x, V, h);
};

/// [v]×, the matrix of v × ·.
inline Mat3 cross_matrix(const Vec3& v) {
  Mat3 c;
  c << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return c;
}

/// Df(x): the Jacobian of the Euler–Poisson vector field (docs/model.md §4) in the order (m, γ):
/// ∂ṁ/∂m = [m]× I⁻¹ − [ω]×, ∂ṁ/∂γ = ∂L/∂γ, ∂γ̇/∂m = [γ]× I⁻¹, ∂γ̇/∂γ = −[ω]×.
template <Field F>
Eigen::Matrix<double, 6, 6> rhs_jacobian(const BasicModel<F>& model, const State& x) {
  const Vec3 w = omega(model.body, x);
  const Mat3 inv_i = model.body.inertia().cwiseInverse().asDiagonal();
  Eigen::Matrix<double, 6, 6> J;
  J.topLeftCorner<3, 3>() = cross_matrix(x.m) * inv_i - cross_matrix(w);
  J.topRightCorner<3, 3>() = moment_jacobian(model, x.gamma);
  J.bottomLeftCorner<3, 3>() = cross_matrix(x.gamma) * inv_i;
  J.bottomRightCorner<3, 3>() = -cross_matrix(w);
  return J;
}

/// The rotation sub-flow about body axis a over time t, with its derivative applied to V.
void axis_flow_tangent(const Body& body, int a, double t, State& x, Tangent& V);

/// The rotation about body axis a by θ = ta m_a + tb (the flow of ½α m_a² + β m_a over t, with
/// ta = t α, tb = t β), with its derivative applied to V (dθ/dm_a = ta).
void axis_flow_tangent(int a, double ta, double tb, State& x, Tangent& V);

/// The spin over τ (the flow of ½|m|²/I over t = τ I: γ turns about m by −τ|m|, m fixed), with
/// its derivative applied to V.
void spin_flow_tangent(double tau, State& x, Tangent& V);

/// The kick sub-flow over t, with its derivative applied to V.
template <Field F>
void kick_tangent(const BasicModel<F>& model, double t, State& x, Tangent& V) {
  if (V.cols() == 1) {
    const MomentAndDerivative L = moment_with_derivative(model, x.gamma, V.col(0).tail<3>());
    V.col(0).head<3>() += t * L.derivative;
    x.m += t * L.moment;
    return;
  }
  const Mat3 J = moment_jacobian(model, x.gamma);
  V.topRows<3>() += t * (J * V.bottomRows<3>());
  x.m += t * moment(model, x.gamma);
}

/// A splitting method with its tangent map: the composition of SplittingStepper (the same
/// coefficients, working axes and sub-flows), in the body frame. The axes split (the default of
/// every composition table) and the spin split; the exact split is refused (InputError).
class TangentSplittingStepper {
 public:
  TangentSplittingStepper(const CompositionTable& table, const SplitOrdering& ordering);
  /// The tangent map of a splitting stepper (the same coefficients and ordering).
  explicit TangentSplittingStepper(const SplittingStepper& stepper);
  int order() const { return order_; }
  template <Field F>
  void step(const BasicModel<F>& model, State& x, Tangent& V, double h) {
    if (model.body.inertia() != inertia_key_ || model.body.gyrostat() != gyrostat_key_) {
      frame_ = split_frame(model.body, ordering_);
      inertia_key_ = model.body.inertia();
      gyrostat_key_ = model.body.gyrostat();
    }
    const std::size_t s = c_.a.size();
    for (std::size_t i = 0; i < s; ++i) {
      if (c_.b[i] != 0.0) kick_tangent(model, c_.b[i] * h, x, V);
      free_body(model.body, c_.a[i] * h, x, V);
    }
    if (c_.b[s] != 0.0) kick_tangent(model, c_.b[s] * h, x, V);
  }
  /// The axes split: T(t) = R_i(t/2) R_j(t/2) R_k(t) R_j(t/2) R_i(t/2), (i, j, k) the split's
  /// axes. The spin split: the spin over t/I_k, then the rotations of ½ m_w² (1/I_w − 1/I_k) −
  /// m_w k_w/I_w about i (t/2), j (t, or t/2, k's gyrostat term over t, t/2 when k_k ≠ 0), i (t/2)
  /// — SpinFlow's order.
  void free_body(const Body& body, double t, State& x, Tangent& V) const;

 private:
  int order_;
  SplitOrdering ordering_;
  SplittingCoefficients c_;
  Vec3 inertia_key_ = Vec3::Constant(NAN), gyrostat_key_ = Vec3::Constant(NAN);
  SplitFrame frame_;
};

/// Classical RK4 on the state and the variational equations together. One vector (the Lyapunov
/// exponent, MEGNO, FLI) and six (the spectrum) take fixed-size paths: one vector by the
/// directional derivative Df(x)v = (m × δω + δm × ω + (∂L/∂γ) δγ, γ × δω + δγ × ω), δω = I⁻¹δm,
/// without forming Df (moment_derivative); six by the same formula column by column, with ∂L/∂γ
/// formed once per stage.
class TangentRk4Stepper {
 public:
  int order() const { return 4; }
  template <Field F>
  void step(const BasicModel<F>& model, State& x, Tangent& V, double h) const {
    if (V.cols() == 1) {
      Eigen::Matrix<double, 6, 1> W = V;
      rk4(model, x, W, h);
      V = W;
    } else if (V.cols() == 6) {
      Eigen::Matrix<double, 6, 6> W = V;
      rk4(model, x, W, h);
      V = W;
    } else {
      rk4(model, x, V, h);
    }
  }

 private:
  /// ẋ = f(x) and Ẇ = Df(x) W at (y, W).
  template <Field F, class W>
  static void f(const BasicModel<F>& model, const State& y, const W& w, State& dy, W& dw) {
    const Vec3 om = omega(model.body, y);
    if constexpr (W::ColsAtCompileTime == 1) {
      const Vec3 dm = w.template head<3>(), dg = w.template tail<3>();
      const Vec3 d_omega = dm.cwiseQuotient(model.body.inertia());
      Vec3 dL;
      if constexpr (FieldWithMomentDerivative<F>) {  // one pass over the masses
        const MomentAndDerivative L = moment_with_derivative(model.body, model.field, y.gamma, dg);
        dy = State{y.m.cross(om) + L.moment, y.gamma.cross(om)};
        dL = L.derivative;
      } else {
        dy = State{y.m.cross(om) + moment(model, y.gamma), y.gamma.cross(om)};
        dL = moment_derivative(model, y.gamma, dg);
      }
      dw.template head<3>() = y.m.cross(d_omega) + dm.cross(om) + dL;
      dw.template tail<3>() = y.gamma.cross(d_omega) + dg.cross(om);
    } else if constexpr (W::ColsAtCompileTime != Eigen::Dynamic) {
      dy = State{y.m.cross(om) + moment(model, y.gamma), y.gamma.cross(om)};
      const Mat3 Jm = moment_jacobian(model, y.gamma);
      const Vec3 inv_i = model.body.inertia().cwiseInverse();
      for (int c = 0; c < W::ColsAtCompileTime; ++c) {
        const Vec3 dm = w.col(c).template head<3>(), dg = w.col(c).template tail<3>();
        const Vec3 d_omega = dm.cwiseProduct(inv_i);
        dw.col(c).template head<3>() = y.m.cross(d_omega) + dm.cross(om) + Jm * dg;
        dw.col(c).template tail<3>() = y.gamma.cross(d_omega) + dg.cross(om);
      }
    } else {
      dy = State{y.m.cross(om) + moment(model, y.gamma), y.gamma.cross(om)};
      dw.noalias() = rhs_jacobian(model, y) * w;
    }
  }

  template <Field F, class W>
  static void rk4(const BasicModel<F>& model, State& x, W& V, double h) {
    auto add = [](const State& y, double c, const State& k) {
      return State{y.m + c * k.m, y.gamma + c * k.gamma};
    };
    State k1, k2, k3, k4;
    W l1(6, V.cols()), l2(6, V.cols()), l3(6, V.cols()), l4(6, V.cols());
    f(model, x, V, k1, l1);
    f(model, add(x, h / 2, k1), W(V + (h / 2) * l1), k2, l2);
    f(model, add(x, h / 2, k2), W(V + (h / 2) * l2), k3, l3);
    f(model, add(x, h, k3), W(V + h * l3), k4, l4);
    x.m += (h / 6) * (k1.m + 2 * k2.m + 2 * k3.m + k4.m);
    x.gamma += (h / 6) * (k1.gamma + 2 * k2.gamma + 2 * k3.gamma + k4.gamma);
    V += (h / 6) * (l1 + 2 * l2 + 2 * l3 + l4);
  }
};

}  // namespace newtop::phase
