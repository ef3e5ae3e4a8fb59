#pragma once
/// \file
/// Taylor's method with its tangent map (the chaos indicators, MEGNO, λ_max): the variational
/// equations δẋ = Df(x(t)) δx along the series of x(t). They are linear in δx, so the coefficients
/// of each tangent vector come from the state's Cauchy sums with one factor of each product
/// replaced by the tangent's: δ(ω₂ω₃) = δω₂ ω₃ + ω₂ δω₃, and so on (docs/methods.md, "Taylor's
/// method").

#include <array>
#include <cmath>
#include <type_traits>

#include "newtop/integrate/taylor.hpp"
#include "newtop/phase/tangent_vectors.hpp"

namespace newtop {
namespace detail {

/// The Taylor coefficients δm^[n], δγ^[n] (n = 0..order) of up to 6 tangent vectors, lanes (x, y,
/// z, ·), along the TaylorSeries of the state.
struct TaylorTangentSeries {
  using Lanes = TaylorSeries::Lanes;
  using Column = std::array<Lanes, TaylorSeries::kMaxOrder + 1>;
  int order = 0;
  int columns = 0;
  alignas(32) std::array<Column, 6> m{}, gamma{};
};

/// Fills ts with the coefficients of the columns of V along s (its order; without an attitude):
/// in 4-lane vectors where the processor has AVX2, in 2-lane ones otherwise or with `baseline`.
void taylor_expand_tangent(const TaylorModel& model, const TaylorSeries& s, const phase::Tangent& V,
                           TaylorTangentSeries& ts, bool baseline = false);
/// The tangent series summed at h into V (its columns).
void taylor_tangent_sum(const TaylorTangentSeries& ts, double h, phase::Tangent& V);
/// taylor_step over the state and the tangent vectors together (the max norm of each coefficient
/// over all of them).
double taylor_tangent_step(const TaylorSeries& s, const TaylorTangentSeries& ts, double abs_tol,
                           double rel_tol);

}  // namespace detail

namespace phase {

/// Taylor's method (TaylorStepper's order and step rule) on the state and its tangent vectors: a
/// step from (x, V) sums the series of both at h, h the smaller of the step asked for and the
/// step of the coefficients of the state and the vectors together (the indicators renormalise the
/// vectors after every step, so the tolerance applies to O(1) numbers, as for the Runge–Kutta
/// pairs' tangent maps). Never rejected unless a series is not finite (dt shrinks by
/// kNonFiniteShrink). The quadratic field only: other fields throw InputError (kTaylorFieldOnly).
class TangentTaylorStepper {
 public:
  TangentTaylorStepper(double abs_tol, double rel_tol, int order = 0);
  int order() const { return order_; }

  /// The step of the state's series at x (the vectors are not known yet).
  template <Field F>
  double initial_step(const BasicModel<F>& model, const State& x, double, double) {
    if constexpr (!std::is_same_v<F, QuadraticField>) {
      throw InputError(kTaylorFieldOnly);
    } else {
      expand_state(model, x);
      return newtop::detail::taylor_step(series_, abs_tol_, rel_tol_);
    }
  }

  /// One step as AdaptiveStepper::try_step, carrying V; dt becomes the step of the series at the
  /// starting point, with the sign of the step.
  template <Field F>
  bool try_step(const BasicModel<F>& model, State& x, Tangent& V, double& t, double& dt) {
    if constexpr (!std::is_same_v<F, QuadraticField>) {
      throw InputError(kTaylorFieldOnly);
    } else {
      expand_state(model, x);
      newtop::detail::taylor_expand_tangent(params_, series_, V, tangent_);
      const double h_max =
          newtop::detail::taylor_tangent_step(series_, tangent_, abs_tol_, rel_tol_);
      if (!(h_max > 0.0)) {  // NaN: a series is not finite
        dt *= kNonFiniteShrink;
        return false;
      }
      const double h = std::abs(dt) <= h_max ? dt : (dt < 0 ? -h_max : h_max);
      x = newtop::detail::taylor_state(series_, h);
      newtop::detail::taylor_tangent_sum(tangent_, h, V);
      t += h;
      dt = h < 0 ? -h_max : h_max;
      return true;
    }
  }

 private:
  void expand_state(const QuadraticModel& model, const State& x);

  double abs_tol_, rel_tol_;
  int order_;
  newtop::detail::TaylorModel params_;
  newtop::detail::TaylorSeries series_;
  newtop::detail::TaylorTangentSeries tangent_;
};

}  // namespace phase
}  // namespace newtop
