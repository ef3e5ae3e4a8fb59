#pragma once
/// \file
/// Dense output: the state anywhere inside an accepted step of an adaptive method, from the
/// method's continuous extension. The driver hands each accepted step to observers as a DenseStep;
/// output at requested times (output_times.hpp) and event location read the state through it.

#include <array>
#include <concepts>
#include <span>

#include "newtop/model/attitude.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// An adaptive stepper with a continuous extension of its last accepted step:
/// `dense_state(model, t)` is the state at t between that step's ends (valid until the next
/// try_step).
template <class S, class M>
concept DenseStepper = requires(S s, const M& model, double t) {
  { s.dense_state(model, t) } -> std::same_as<State>;
};

/// One accepted step [t_old, t_new] of an adaptive run, as observers see it: state(t) for t between
/// the ends, the end point itself exactly. Valid only inside the observer call that receives it
/// (the stepper's next trial overwrites the data it reads). At the start of a run t_old = t_new =
/// t0 and state(t0) is the initial state. X: State, or OrientedState for a run with an attitude.
template <class S, class M, class X = State>
struct DenseStep {
  S& stepper;
  const M& model;
  double t_old;
  double t_new;
  const X& x_new;

  X state(double t) const {
    if (t == t_new) return x_new;
    if constexpr (kOriented<X>) {
      return stepper.dense_oriented_state(model, t);
    } else {
      return stepper.dense_state(model, t);
    }
  }
};

/// Hermite interpolation of a step: the polynomial u(θ), θ = (t − t_old)/h in [0, 1], of degree
/// 2N − 1 with u(θ_i) = y_i and u′(θ_i) = h f_i at N distinct nodes (N ≤ 4), in Newton form on the
/// doubled nodes (divided differences with repeated nodes, e.g. Stoer & Bulirsch §2.1.5). Its error
/// is y^(2N)(ξ) h^(2N) Π(θ − θ_i)² / (2N)! on top of the errors of the node values.
class HermiteInterpolant {
 public:
  using Point = std::array<double, 6>;
  static constexpr int kMaxNodes = 4;

  HermiteInterpolant() = default;
  /// Nodes theta (distinct, in [0, 1]), values y and scaled derivatives h·f at the nodes.
  HermiteInterpolant(std::span<const double> theta, std::span<const Point> y,
                     std::span<const Point> h_f);
  /// u(θ).
  Point operator()(double theta) const;

 private:
  int n_ = 0;  // 2N coefficients
  std::array<double, 2 * kMaxNodes> z_{};
  std::array<Point, 2 * kMaxNodes> c_{};
};

}  // namespace newtop
