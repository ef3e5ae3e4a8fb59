#pragma once
/// \file
/// Taylor's method on the orbit models (docs/orbit.md §5): the coefficients x^[k] = x^(k)/k! of
/// (m, γ, n) through a point, from the recurrences of the right-hand side. On a circular orbit the
/// equations are quadratic (Cauchy products of the series of m, γ, n and ω = I⁻¹(m − k)); on an
/// ellipse, in the true anomaly ν, the products are multiplied by the series of σ = dt/dν ∝
/// 1/(1 + e cos ν)² and of σλ ∝ (1 + e cos ν), whose coefficients follow from those of cos ν. The
/// order and the step are those of the engine's `taylor` (integrate/taylor.hpp: taylor_order and
/// taylor_step's rule on the norms of the coefficients p − 1 and p); every step is accepted and the
/// series is the method's continuous extension.

#include <array>
#include <cmath>

#include "newtop/integrate/concepts.hpp"
#include "newtop/orbit/orbit_model.hpp"

namespace newtop {

namespace detail {

/// The coefficients (m, γ, n)^[k], k = 0..order, of the solution through one point.
struct OrbitTaylorSeries {
  static constexpr int kMaxOrder = 30;  // taylor_order's largest
  int order = 0;
  std::array<std::array<double, 9>, kMaxOrder + 1> x{};
};

/// Fills s to the given order with the series through x (on an ellipse at the true anomaly nu).
void orbit_taylor_expand(const CircularOrbitModel& model, const OrbitState& x, int order,
                         OrbitTaylorSeries& s);
void orbit_taylor_expand(const EllipticOrbitModel& model, const OrbitState& x, double nu, int order,
                         OrbitTaylorSeries& s);
/// The coefficients 0..order − 1 of σ = dt/dν and σλ along an ellipse from the true anomaly nu
/// (the factors of the elliptic recurrences).
void orbit_anomaly_series(const EllipticOrbit& orbit, double nu, int order, double* sigma,
                          double* sigma_lambda);

/// The coefficients δx^[k], k = 0..order, of tangent vectors (columns) along a series of the state.
struct OrbitTangentSeries {
  static constexpr int kMaxColumns = 9;
  int order = 0;
  int columns = 0;
  std::array<std::array<std::array<double, 9>, OrbitTaylorSeries::kMaxOrder + 1>, kMaxColumns> v{};
};

/// The coefficients 1..s.order of each column of ts from its coefficient 0 (ts.v[c][0], c <
/// ts.columns), along the state's series s (on an ellipse at the true anomaly nu): the
/// variational equations δx′ = J(x) δx expanded with the state (orbit_taylor_tangent.cpp).
void orbit_taylor_expand_tangent(const CircularOrbitModel& model, const OrbitTaylorSeries& s,
                                 OrbitTangentSeries& ts);
void orbit_taylor_expand_tangent(const EllipticOrbitModel& model, const OrbitTaylorSeries& s,
                                 double nu, OrbitTangentSeries& ts);
/// Column c of the tangent series summed at h (Horner).
std::array<double, 9> orbit_tangent_sum(const OrbitTangentSeries& ts, int c, double h);
/// The step rule on the state's and the columns' coefficients together (the max norm of each
/// order over all of them; NaN when one is not finite).
double orbit_tangent_step(const OrbitTaylorSeries& s, const OrbitTangentSeries& ts, double abs_tol,
                          double rel_tol);

/// Throws InputError unless 1 ≤ order ≤ OrbitTaylorSeries::kMaxOrder.
void check_orbit_taylor_order(int order);
/// The series summed at h (Horner).
OrbitState orbit_taylor_sum(const OrbitTaylorSeries& s, double h);
/// The step of taylor_step's rule on the max norms of the coefficients (NaN when one is not
/// finite, +inf when the series is constant).
double orbit_taylor_step(const OrbitTaylorSeries& s, double abs_tol, double rel_tol);

}  // namespace detail

/// Taylor's method on an orbit model (CircularOrbitModel, EllipticOrbitModel), adaptive in its
/// step as the engine's TaylorStepper: an AdaptiveStepper of the driver with dense output. A step
/// of h from x is the series through x summed at h, with h the smaller of the step asked for and
/// the rule's; it is rejected only when the series is not finite (then dt shrinks by
/// kNonFiniteShrink).
class OrbitTaylorStepper {
 public:
  /// Order from the smaller tolerance (taylor_order) unless given.
  OrbitTaylorStepper(double abs_tol, double rel_tol, int order = 0);

  int order() const { return order_; }

  template <class M>
  double initial_step(const M& model, const OrbitState& x, double t0, double) {
    expand_at(model, x, t0);
    return step_;
  }

  template <class M>
  bool try_step(const M& model, OrbitState& x, double& t, double& dt) {
    expand_at(model, x, t);
    const double h_max = step_;
    if (!(h_max > 0.0)) {  // NaN: the series is not finite
      dt *= kNonFiniteShrink;
      return false;
    }
    const double h = std::abs(dt) <= h_max ? dt : (dt < 0 ? -h_max : h_max);
    x = detail::orbit_taylor_sum(series_[cur_], h);
    t0_ = t;
    t += h;
    expand_at(model, x, t);
    dt = h < 0 ? -step_ : step_;
    return true;
  }

  /// The series of the last accepted step at t (between its ends).
  template <class M>
  OrbitState dense_state(const M&, double t) const {
    return detail::orbit_taylor_sum(series_[1 - cur_], t - t0_);
  }

  /// One step of h from (t, x), the series summed at h, without the step rule (event location).
  template <class M>
  OrbitState formula_step(const M& model, const OrbitState& x, double t, double h) const {
    detail::OrbitTaylorSeries s;
    expand(model, x, t, s);
    return detail::orbit_taylor_sum(s, h);
  }

 private:
  /// The numbers a series depends on besides the point (the model's and, on an ellipse, ν).
  using Key = std::array<double, 10>;
  static Key key_of(const CircularOrbitModel& model, double t);
  static Key key_of(const EllipticOrbitModel& model, double nu);

  void expand(const CircularOrbitModel& model, const OrbitState& x, double,
              detail::OrbitTaylorSeries& s) const {
    detail::orbit_taylor_expand(model, x, order_, s);
  }
  void expand(const EllipticOrbitModel& model, const OrbitState& x, double nu,
              detail::OrbitTaylorSeries& s) const {
    detail::orbit_taylor_expand(model, x, nu, order_, s);
  }

  template <class M>
  void expand_at(const M& model, const OrbitState& x, double t) {
    const Key key = key_of(model, t);
    if (expanded_ && x == at_ && key == key_) return;  // the series through this point is at hand
    cur_ = 1 - cur_;
    expand(model, x, t, series_[cur_]);
    step_ = detail::orbit_taylor_step(series_[cur_], abs_tol_, rel_tol_);
    at_ = x;
    key_ = key;
    expanded_ = true;
  }

  double abs_tol_, rel_tol_;
  int order_;
  std::array<detail::OrbitTaylorSeries, 2> series_{};  // [cur_]: at the current point
  int cur_ = 0;
  bool expanded_ = false;
  OrbitState at_;
  Key key_{};
  double step_ = 0.0;
  double t0_ = 0.0;
};

static_assert(AdaptiveStepper<OrbitTaylorStepper, CircularOrbitModel, OrbitState>);
static_assert(AdaptiveStepper<OrbitTaylorStepper, EllipticOrbitModel, OrbitState>);

}  // namespace newtop
