#pragma once
/// \file
/// The tangent stepper of any scalar stepper: tangent_of(stepper). newtop's own methods have their
/// exact tangent maps (tangent.hpp, tangent_adaptive.hpp, tangent_taylor.hpp): the splitting
/// methods the derivative of each sub-flow, rk4, the embedded pairs and Taylor's method the
/// variational equations. Any other fixed-step stepper of the conformance suite (a FixedStepper on
/// State) is wrapped in FiniteDifferenceTangent: the derivative of its own one-step map by central
/// differences. with_tangent_stepper() gives the tangent stepper of a method by name.

#include <algorithm>
#include <cmath>

#include "newtop/integrate/methods.hpp"
#include "newtop/phase/tangent.hpp"
#include "newtop/phase/tangent_adaptive.hpp"
#include "newtop/phase/tangent_taylor.hpp"

namespace newtop::phase {

/// The derivative of a fixed-step stepper's one-step map Φ_h by central differences: for each
/// tangent vector v, (Φ_h(x + δv) − Φ_h(x − δv)) / (2δ), with δ = kFiniteDifferenceStep ·
/// max(1, |x|∞) / |v|∞ (truncation O(δ²), round-off O(ε/δ): about 1e-10 relative for a smooth
/// map). Costs 2n + 1 steps for n vectors; the state advances by the stepper's own step.
template <class S>
class FiniteDifferenceTangent {
 public:
  /// ε^(1/3), the step that balances truncation and round-off of a central difference.
  static constexpr double kFiniteDifferenceStep = 6.0555e-6;

  explicit FiniteDifferenceTangent(const S& stepper) : s_(stepper) {}
  int order() const { return s_.order(); }

  template <Field F>
  void step(const BasicModel<F>& model, State& x, Tangent& V, double h) {
    const double scale = std::max({1.0, x.m.cwiseAbs().maxCoeff(), x.gamma.cwiseAbs().maxCoeff()});
    for (Eigen::Index c = 0; c < V.cols(); ++c) {
      const double size = V.col(c).cwiseAbs().maxCoeff();
      if (!(size > 0)) continue;  // a zero vector stays zero
      const double delta = kFiniteDifferenceStep * scale / size;
      const Eigen::Matrix<double, 6, 1> v = V.col(c);
      State plus{x.m + delta * v.head<3>(), x.gamma + delta * v.tail<3>()};
      State minus{x.m - delta * v.head<3>(), x.gamma - delta * v.tail<3>()};
      s_.step(model, plus, h);
      s_.step(model, minus, h);
      V.col(c).head<3>() = (plus.m - minus.m) / (2 * delta);
      V.col(c).tail<3>() = (plus.gamma - minus.gamma) / (2 * delta);
    }
    s_.step(model, x, h);
  }

 private:
  S s_;
};

/// The tangent stepper of S: FiniteDifferenceTangent<S> unless newtop has S's exact map.
template <class S>
struct TangentOf {
  using type = FiniteDifferenceTangent<S>;
  static type make(const S& s) { return type(s); }
};

template <>
struct TangentOf<SplittingStepper> {
  using type = TangentSplittingStepper;
  static type make(const SplittingStepper& s) { return type(s); }
};

template <>
struct TangentOf<Rk4Stepper> {
  using type = TangentRk4Stepper;
  static type make(const Rk4Stepper&) { return type(); }
};

template <class E, int Order>
struct TangentOf<EmbeddedRkStepper<E, Order>> {
  using type = TangentAdaptiveStepper<newtop::detail::RebindStateT<E, TangentOdeState>, E, Order>;
  static type make(const EmbeddedRkStepper<E, Order>& s) { return type(s.abs_tol(), s.rel_tol()); }
};

template <>
struct TangentOf<Dop853Stepper> {
  using type = TangentDop853Stepper;
  static type make(const Dop853Stepper& s) { return type(s.abs_tol(), s.rel_tol()); }
};

template <>
struct TangentOf<TaylorStepper> {
  using type = TangentTaylorStepper;
  static type make(const TaylorStepper& s) { return type(s.abs_tol(), s.rel_tol(), s.order()); }
};

/// The tangent stepper of a scalar stepper (same method, same coefficients or tolerances).
template <class S>
typename TangentOf<S>::type tangent_of(const S& stepper) {
  return TangentOf<S>::make(stepper);
}

/// Calls fn(tangent stepper) for the named method (check_tangent_method first): the tangent_of
/// the stepper with_stepper() makes, so that the tangent run iterates the same method.
template <class Fn>
decltype(auto) with_tangent_stepper(const MethodSettings& settings, Fn&& fn) {
  check_tangent_method(settings);
  return with_stepper(settings, [&](auto& s) {
    auto t = tangent_of(s);
    return fn(t);
  });
}

}  // namespace newtop::phase
