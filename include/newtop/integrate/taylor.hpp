#pragma once
/// \file
/// Taylor's method on the Euler–Poisson equations of the quadratic field (docs/model.md §3, §4):
/// the coefficients x^[n] = x^(n)(t)/n! of the solution through a point, to an order p chosen from
/// the tolerance, from the recurrences of the right-hand side (Cauchy products of the series of ω,
/// γ and q; the equations are quadratic), and the step from the size of the last two coefficients
/// (Jorba & Zou 2005). Every step is accepted; the series is the method's continuous extension.

#include <array>
#include <cmath>
#include <type_traits>

#include "newtop/core/types.hpp"
#include "newtop/integrate/concepts.hpp"
#include "newtop/model/attitude.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// The message of a Taylor run on a field other than the quadratic one.
inline constexpr const char* kTaylorFieldOnly =
    "method: taylor expands the quadratic field only (the exact and multipole fields run with "
    "dop853)";

namespace detail {

/// The Taylor coefficients of one solution through a point: m^[n], γ^[n] (and q^[n] with an
/// attitude) for n = 0..order, lanes (x, y, z, ·) and, for q, (x, y, z, w).
struct TaylorSeries {
  static constexpr int kMaxOrder = 40;
  using Lanes = std::array<double, 4>;
  int order = 0;
  bool attitude = false;
  alignas(32) std::array<Lanes, kMaxOrder + 1> m{}, gamma{}, q{};
};

/// The parameters of the recurrences: 1/I, k, M g r0, (B − C, C − A, A − B), λ (C − B, A − C, B −
/// A).
struct TaylorModel {
  alignas(32) std::array<double, 4> inv_i{}, k{}, b{}, d_spin{}, d_field{};
  Vec3 inertia = Vec3::Zero();  // I and λ as given, for of()
  double lambda = 0.0;
  bool set = false;

  TaylorModel() = default;
  explicit TaylorModel(const QuadraticModel& model);
  /// Whether these are the constants of `model` (the same I, k, M g r0, λ).
  bool of(const QuadraticModel& model) const;
};

/// Fills s with the coefficients through (m, γ) (and q when q is not null) to the given order: in
/// 4-lane vectors where the processor has AVX2, in 2-lane ones otherwise or when `baseline` is
/// set (for the test that both give the same bits).
void taylor_expand(const TaylorModel& model, const State& x, const Quaternion* q, int order,
                   TaylorSeries& s, bool baseline = false);
/// The series summed at h (Horner).
State taylor_state(const TaylorSeries& s, double h);
Quaternion taylor_attitude(const TaylorSeries& s, double h);
/// The step: min over n = p − 1, p of (ε / ‖x^[n]‖∞)^(1/n), times Jorba and Zou's safety factor
/// exp(−0.7/(p − 1)), with ε = max(abs_tol, rel_tol ‖x^[0]‖∞); +inf when the series is constant.
/// The powers through taylor_step_log2 and taylor_step_exp2 (below).
double taylor_step(const TaylorSeries& s, double abs_tol, double rel_tol);
/// The same rule from the max norms of a series' coefficients, norms[n] for n = 0..order (any
/// model's series: the orbit's Taylor method uses it).
double taylor_step_from_norms(const double* norms, int order, double abs_tol, double rel_tol);
/// The logarithm to base 2 and the power of two of the step rule (src/integrate/taylor_math.hpp):
/// newtop's own, the same bits in a scalar run and in every lane of an ensemble. Error bounds in
/// units in the last place of the result, for finite x > 0 and for normal results: the roundings
/// of the leading terms ((m − 1)/(m + 1), 2/ln 2 and the products: four) for the logarithm, those
/// of the sum's last additions and of the reduction's powers of two (two) for the power.
inline constexpr double kTaylorStepLog2Ulps = 4.0;
inline constexpr double kTaylorStepExp2Ulps = 2.0;
double taylor_step_log2(double x);
double taylor_step_exp2(double y);
/// The order for a tolerance: ⌈0.6 |ln tol|⌉ + 4 within [8, 30] (docs/methods.md, "Taylor").
int taylor_order(double tol);

}  // namespace detail

/// Taylor's method of order p (taylor_order of the smaller tolerance unless given), adaptive in
/// its step: the AdaptiveStepper and DenseStepper of the quadratic field. A step of h from x is
/// the series through x summed at h, with h the smaller of the step asked for and taylor_step;
/// it is never rejected unless the series is not finite (then dt shrinks by kNonFiniteShrink).
/// With an attitude q̇ = ½ q ⊗ (0, ω) is expanded with (m, γ) and q renormalised after each step.
/// Other fields: InputError (kTaylorFieldOnly) from the first call.
class TaylorStepper {
 public:
  TaylorStepper(double abs_tol, double rel_tol, int order = 0);

  int order() const { return order_; }
  double abs_tol() const { return abs_tol_; }
  double rel_tol() const { return rel_tol_; }

  template <Field F, PhaseState X>
  double initial_step(const BasicModel<F>& model, const X& x, double, double) {
    expand_at(model, x);
    return step_;
  }

  template <Field F, PhaseState X>
  bool try_step(const BasicModel<F>& model, X& x, double& t, double& dt) {
    expand_at(model, x);
    const double h_max = step_;
    if (!(h_max > 0.0)) {  // NaN: the series is not finite
      dt *= kNonFiniteShrink;
      return false;
    }
    const double h = std::abs(dt) <= h_max ? dt : (dt < 0 ? -h_max : h_max);
    advance(x, h);
    t0_ = t;
    t += h;
    expand_at(model, x);
    dt = h < 0 ? -step_ : step_;
    return true;
  }

  /// The series of the last accepted step at t (between its ends).
  template <Field F>
  State dense_state(const BasicModel<F>&, double t) const {
    return detail::taylor_state(series_[1 - cur_], t - t0_);
  }
  /// The same for a run with an attitude (q renormalised).
  template <Field F>
  OrientedState dense_oriented_state(const BasicModel<F>&, double t) const {
    const double h = t - t0_;
    return with_attitude(detail::taylor_state(series_[1 - cur_], h),
                         detail::taylor_attitude(series_[1 - cur_], h).normalized());
  }

  /// The largest renormalisation |‖q‖ − 1| of the attitude in one step so far.
  double attitude_projection() const { return projection_; }

 private:
  template <Field F, PhaseState X>
  void expand_at(const BasicModel<F>& model, const X& x) {
    if constexpr (!std::is_same_v<F, QuadraticField>) {
      throw InputError(kTaylorFieldOnly);
    } else {
      const Quaternion* q = nullptr;
      if constexpr (kOriented<X>) q = &x.q;
      const bool same_model = params_.of(model);
      if (expanded_ && same_model && x.m == at_.m && x.gamma == at_.gamma &&
          (q == nullptr ? !series_[cur_].attitude
                        : series_[cur_].attitude && q->coeffs() == at_q_.coeffs())) {
        return;  // the series through this point of this model is at hand
      }
      if (!same_model) params_ = detail::TaylorModel(model);
      cur_ = 1 - cur_;
      detail::taylor_expand(params_, x, q, order_, series_[cur_]);
      step_ = detail::taylor_step(series_[cur_], abs_tol_, rel_tol_);
      at_ = x;
      if (q != nullptr) at_q_ = *q;
      expanded_ = true;
    }
  }

  void advance(State& x, double h);
  void advance(OrientedState& x, double h);

  double abs_tol_, rel_tol_;
  int order_;
  std::array<detail::TaylorSeries, 2> series_{};  // [cur_]: at the current point
  int cur_ = 0;
  bool expanded_ = false;
  State at_;
  Quaternion at_q_ = Quaternion::Identity();
  detail::TaylorModel params_;  // the recurrences' constants of the last model
  double step_ = 0.0;           // taylor_step of series_[cur_]
  double t0_ = 0.0, projection_ = 0.0;
};

static_assert(AdaptiveStepper<TaylorStepper, QuadraticModel>);
static_assert(AdaptiveStepper<TaylorStepper, QuadraticModel, OrientedState>);

}  // namespace newtop
