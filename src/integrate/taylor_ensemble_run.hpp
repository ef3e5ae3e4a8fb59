#pragma once
// The run of a batch through one block of lanes of the Taylor ensemble (taylor_ensemble.cpp;
// private to src/integrate): the kernels' series (taylor_ensemble_kernel.hpp) and, lane by lane,
// the adaptive driver's loop (driver.hpp, run_adaptive; phase/chaos_run.hpp,
// integrate_tangent_adaptive) with TaylorStepper's (TangentTaylorStepper's) try_step, decision for
// decision. Included by taylor_ensemble.cpp only, which is compiled with -ffp-contract=off.

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "newtop/integrate/taylor.hpp"
#include "newtop/integrate/taylor_ensemble.hpp"
#include "taylor_ensemble_kernel.hpp"
#include "taylor_lanes.hpp"

namespace newtop::detail::taylor_ensemble_run {

using detail::TaylorLaneKernel;
using detail::taylor_lanes::Lanes;

static_assert(detail::taylor_ensemble_simd::K == detail::taylor_lanes::K &&
              detail::taylor_ensemble_simd::kInverse == detail::taylor_lanes::kInverse);

inline TaylorLaneKernel kernel_of(SimdPath path) {
  switch (path) {
#if defined(__x86_64__) && defined(__GNUC__)
    case SimdPath::avx2:
      return detail::taylor_lane_kernel_avx2();
    case SimdPath::avx512:
      return detail::taylor_lane_kernel_avx512();
#endif
    default:
      return detail::taylor_lane_kernel_portable();
  }
}

/// The driver's variables (run_adaptive) of the trajectory in a lane. `next`: how the lane's
/// dt follows from the series about to be formed at its state: the first trial step
/// (initial_step), the step after an accepted one (try_step's last line), or dt unchanged after a
/// rejected trial.
struct LaneRun {
  enum class Next { initial, after_step, retry };
  std::size_t point = 0;
  bool active = false, stepping = false, last = false;
  Next next = Next::initial;
  double t = 0, dt = 0, h = 0, h_max = 0, dt_tried = 0;
  std::int64_t sample = 0;  // the next output time
  Outcome out;
};

/// One run of a batch through one block of lanes.
class BatchRun {
 public:
  BatchRun(const TaylorEnsemble& e, std::span<const QuadraticModel> models,
           std::span<const State> states, double t0, double t1, const IntegrateOptions& opt,
           const TaylorEnsembleObserver& obs, std::vector<double>& workspace,
           std::span<const TangentVector> v0 = {}, const TaylorTangentObserver* tangent = nullptr)
      : e_(e),
        kernel_(kernel_of(e.path())),
        L_(static_cast<std::size_t>(kernel_.lanes)),
        models_(models),
        states_(states),
        t0_(t0),
        t1_(t1),
        span_(t1 - t0),
        dir_(t1 - t0 > 0 ? 1.0 : -1.0),
        opt_(opt),
        obs_(obs),
        v0_(v0),
        tangent_(tangent),
        lanes_(L_) {
    const std::size_t coefficients = 6 * L_ * (detail::TaylorSeries::kMaxOrder + 1);
    workspace.assign((detail::kTaylorLaneConstants + 6 * 3 + 1 + 6 + 2) * L_ + 2 * coefficients,
                     0.0);
    consts_ = workspace.data();
    x_ = consts_ + detail::kTaylorLaneConstants * L_;
    h_ = x_ + 6 * L_;
    v_ = h_ + L_;
    v_trial_ = v_ + 6 * L_;
    series_ = v_trial_ + 6 * L_;
    tangent_series_ = series_ + coefficients;
    norms_ = tangent_series_ + coefficients;
    tangent_norms_ = norms_ + 3 * L_;
    steps_ = tangent_norms_ + 3 * L_;
    tangent_steps_ = steps_ + L_;
    outcomes_.resize(states.size());
  }

  std::vector<Outcome> run() {
    for (std::size_t l = 0; l < L_; ++l) refill(l);
    for (std::size_t l = 0; l < L_; ++l) {
      if (!lanes_[l].active) copy_lane(0, l);  // finite numbers in the idle lanes
    }
    while (std::any_of(lanes_.begin(), lanes_.end(), [](const LaneRun& r) { return r.active; })) {
      kernel_.expand(consts_, x_, e_.order(), series_);
      // The state's own step: every step without a tangent vector; with one, only a lane's first
      // (the tangent stepper's later steps follow from the state's and the vector's norms).
      if (!tangent_ || std::any_of(lanes_.begin(), lanes_.end(), [](const LaneRun& r) {
            return r.active && r.next == LaneRun::Next::initial;
          })) {
        kernel_.norms(series_, nullptr, e_.order(), norms_);
        kernel_.steps(norms_, e_.order(), e_.abs_tol(), e_.rel_tol(), steps_);
      }
      if (tangent_) {
        kernel_.expand_tangent(consts_, series_, v_, e_.order(), tangent_series_);
        kernel_.norms(series_, tangent_series_, e_.order(), tangent_norms_);
        kernel_.steps(tangent_norms_, e_.order(), e_.abs_tol(), e_.rel_tol(), tangent_steps_);
      }
      bool any = false;
      for (std::size_t l = 0; l < L_; ++l) {
        h_[l] = 0.0;
        lanes_[l].stepping = false;
        if (lanes_[l].active) any = decide(l) || any;
      }
      if (!any) continue;
      unsigned lanes = 0;
      for (std::size_t l = 0; l < L_; ++l) lanes |= lanes_[l].stepping ? 1u << l : 0u;
      if (tangent_) {
        kernel_.sum(tangent_series_, e_.order(), h_, v_trial_);
        for (std::size_t l = 0; l < L_; ++l) {
          if (lanes_[l].stepping && !tangent_trial(l).allFinite()) lanes &= ~(1u << l);
        }
      }
      const unsigned written = kernel_.advance(series_, e_.order(), h_, lanes, x_);
      for (std::size_t l = 0; l < L_; ++l) {
        if (lanes_[l].stepping) accept(l, (written >> l & 1u) != 0);
      }
    }
    return std::move(outcomes_);
  }

 private:
  double coefficient(int n, int c, std::size_t l, const double* series = nullptr) const {
    return (
        series ? series
               : series_)[(6 * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)) * L_ + l];
  }

  // The max norm of the coefficient n of a series of the lane (pair_norm).
  double lane_norm(int n, std::size_t l, const double* series) const {
    const Lanes m{coefficient(n, 0, l, series), coefficient(n, 1, l, series),
                  coefficient(n, 2, l, series), 0.0};
    const Lanes g{coefficient(n, 3, l, series), coefficient(n, 4, l, series),
                  coefficient(n, 5, l, series), 0.0};
    return detail::taylor_lanes::pair_norm(m, g);
  }

  // taylor_step of the lane's series; with `with_tangent`, taylor_tangent_step of the state's and
  // the vector's series together.
  // Where the norms p − 1 and p are finite and nonzero, the kernel's step (steps_,
  // tangent_steps_: regular_step, as step_from_norms takes it there); elsewhere step_from_norms
  // with the norms of orders 0, p − 1 and p from the kernel (norms_, tangent_norms_), the others
  // (needed only where both of the last two coefficients vanish) from lane_norm.
  double lane_step(std::size_t l, bool with_tangent = false) const {
    const int p = e_.order();
    const double* pre = with_tangent ? tangent_norms_ : norms_;
    if (detail::taylor_lanes::regular_norm(pre[L_ + l]) &&
        detail::taylor_lanes::regular_norm(pre[2 * L_ + l])) {
      return (with_tangent ? tangent_steps_ : steps_)[l];
    }
    auto norm = [&](int n) {
      if (n == 0 || n >= p - 1) return pre[(n == 0 ? 0 : n == p ? 2 : 1) * L_ + l];
      const double r = lane_norm(n, l, series_);
      return with_tangent ? detail::taylor_lanes::nan_max(r, lane_norm(n, l, tangent_series_)) : r;
    };
    return detail::taylor_lanes::step_from_norms(e_.order(), norm, e_.abs_tol(), e_.rel_tol());
  }

  // The lane's series summed at h (taylor_state, TaylorStepper::dense_state).
  State lane_state(std::size_t l, double h) const {
    std::array<Lanes, detail::TaylorSeries::kMaxOrder + 1> m, g;
    for (int n = 0; n <= e_.order(); ++n) {
      const auto i = static_cast<std::size_t>(n);
      m[i] = {coefficient(n, 0, l), coefficient(n, 1, l), coefficient(n, 2, l), 0.0};
      g[i] = {coefficient(n, 3, l), coefficient(n, 4, l), coefficient(n, 5, l), 0.0};
    }
    return detail::taylor_lanes::sum_series(m.data(), g.data(), e_.order(), h);
  }

  State lane_of(const double* a, std::size_t l) const {
    return {Vec3(a[l], a[L_ + l], a[2 * L_ + l]),
            Vec3(a[3 * L_ + l], a[4 * L_ + l], a[5 * L_ + l])};
  }

  void copy_lane(std::size_t from, std::size_t to) {
    for (std::size_t c = 0; c < detail::kTaylorLaneConstants; ++c) {
      consts_[c * L_ + to] = consts_[c * L_ + from];
    }
    for (std::size_t c = 0; c < 6; ++c) {
      x_[c * L_ + to] = x_[c * L_ + from];
      v_[c * L_ + to] = v_[c * L_ + from];
    }
  }

  TangentVector tangent_trial(std::size_t l) const {
    TangentVector v;
    for (std::size_t c = 0; c < 6; ++c) v[static_cast<Eigen::Index>(c)] = v_trial_[c * L_ + l];
    return v;
  }

  // The sampling observer and the step observer of the driver, at the state x after an accepted
  // step from t_old (or at t0, with t_old = t).
  void notify(std::size_t l, double t_old, const State& x) {
    LaneRun& r = lanes_[l];
    if (obs_.times != nullptr && obs_.sample) {
      const OutputTimes& times = *obs_.times;
      for (; r.sample < times.size() && dir_ * (times[r.sample] - r.t) <= 0; ++r.sample) {
        const double tk = times[r.sample];
        obs_.sample(r.point, r.sample, tk, tk == r.t ? x : lane_state(l, tk - t_old));
      }
    }
    if (obs_.step) obs_.step(r.point, r.t, x);
  }

  // Puts the next trajectory waiting into lane l (or leaves it idle).
  void refill(std::size_t l) {
    LaneRun& r = lanes_[l];
    r.active = false;
    while (next_ < states_.size()) {
      const std::size_t p = next_++;
      r = LaneRun{};
      r.point = p;
      r.t = t0_;
      r.out.t = t0_;
      r.out.state = states_[p];
      if (!tangent_) notify(l, t0_, states_[p]);
      if (span_ == 0.0) {
        outcomes_[p] = r.out;
        continue;
      }
      const detail::TaylorModel m(models_.size() == 1 ? models_[0] : models_[p]);
      const std::array<const Lanes*, 5> rows{&m.inv_i, &m.k, &m.b, &m.d_spin, &m.d_field};
      for (std::size_t q = 0; q < rows.size(); ++q) {
        for (std::size_t c = 0; c < 3; ++c) consts_[(3 * q + c) * L_ + l] = (*rows[q])[c];
      }
      const State& x = states_[p];
      for (std::size_t c = 0; c < 3; ++c) {
        x_[c * L_ + l] = x.m[static_cast<Eigen::Index>(c)];
        x_[(3 + c) * L_ + l] = x.gamma[static_cast<Eigen::Index>(c)];
      }
      if (tangent_) {
        const TangentVector& v = v0_.size() == 1 ? v0_[0] : v0_[p];
        for (std::size_t c = 0; c < 6; ++c) v_[c * L_ + l] = v[static_cast<Eigen::Index>(c)];
      }
      r.active = true;
      return;
    }
  }

  // The lane's outcome, its state the lane's (the last accepted trial, or the start).
  void finish(std::size_t l) {
    lanes_[l].out.state = lane_of(x_, l);
    outcomes_[lanes_[l].point] = lanes_[l].out;
    refill(l);
  }

  // The top of the driver's loop and try_step up to the sum of the series; true when the lane
  // steps (its h set).
  bool decide(std::size_t l) {
    LaneRun& r = lanes_[l];
    if (r.next == LaneRun::Next::initial) {
      r.dt = dir_ * (opt_.initial_step > 0 ? opt_.initial_step : lane_step(l));
    } else if (r.next == LaneRun::Next::after_step && !tangent_) {
      const double step = lane_step(l);
      r.dt = r.h < 0 ? -step : step;
    }
    if (r.out.steps + r.out.rejected >= opt_.max_steps) {
      r.out.status = Status::step_limit;
      finish(l);
      return false;
    }
    r.last = false;
    if (dir_ * (r.t + r.dt - t1_) >= 0) {
      r.dt = t1_ - r.t;
      r.last = true;
    }
    const double scale = std::max(std::abs(r.t), std::abs(span_));
    if (!(std::abs(r.dt) >= opt_.min_step_factor * scale)) {
      r.out.status = Status::step_size_underflow;
      finish(l);
      return false;
    }
    r.dt_tried = r.dt;
    const double h_max = lane_step(l, tangent_ != nullptr);
    r.h_max = h_max;
    if (!(h_max > 0.0)) {  // NaN: the series is not finite (try_step's rejection)
      r.dt *= kNonFiniteShrink;
      if (!std::isfinite(r.dt)) r.dt = kNonFiniteShrink * r.dt_tried;
      ++r.out.rejected;
      r.next = LaneRun::Next::retry;
      return false;
    }
    r.h = std::abs(r.dt) <= h_max ? r.dt : (r.dt < 0 ? -h_max : h_max);
    h_[l] = r.h;
    r.stepping = true;
    return true;
  }

  // The rest of try_step and of the driver's loop once the kernel has written the lane's trial
  // state over its state where it is finite (`written`; the tangent vector's trial in v_trial_,
  // where the state was not written unless the vector is finite too).
  void accept(std::size_t l, bool written) {
    LaneRun& r = lanes_[l];
    const double t_trial = r.t + r.h;
    if (tangent_)
      r.dt = r.h < 0 ? -r.h_max : r.h_max;  // the tangent stepper's: the step at the start
    if (!written) {                         // the state or the vector is not finite
      r.dt = kNonFiniteShrink * r.dt_tried;
      ++r.out.rejected;
      r.next = LaneRun::Next::retry;
      return;
    }
    const double t_old = r.t;
    r.t = r.last ? t1_ : t_trial;
    ++r.out.steps;
    r.out.t = r.t;
    r.out.last_step = r.dt_tried;
    if (tangent_) {
      TangentVector v = tangent_trial(l);
      (*tangent_)(r.point, r.t, lane_of(x_, l), v);
      for (std::size_t c = 0; c < 6; ++c) v_[c * L_ + l] = v[static_cast<Eigen::Index>(c)];
    } else if (obs_.step || (obs_.times != nullptr && obs_.sample)) {
      notify(l, t_old, lane_of(x_, l));
    }
    r.next = LaneRun::Next::after_step;
    if (!(dir_ * (t1_ - r.t) > 0)) finish(l);
  }

  const TaylorEnsemble& e_;
  TaylorLaneKernel kernel_;
  std::size_t L_;
  std::span<const QuadraticModel> models_;
  std::span<const State> states_;
  double t0_, t1_, span_, dir_;
  const IntegrateOptions& opt_;
  const TaylorEnsembleObserver& obs_;
  std::span<const TangentVector> v0_;
  const TaylorTangentObserver* tangent_;
  std::vector<LaneRun> lanes_;
  std::vector<Outcome> outcomes_;
  std::size_t next_ = 0;
  double *consts_ = nullptr, *x_ = nullptr, *h_ = nullptr, *series_ = nullptr;
  double *v_ = nullptr, *v_trial_ = nullptr, *tangent_series_ = nullptr;
  double *norms_ = nullptr, *tangent_norms_ = nullptr, *steps_ = nullptr, *tangent_steps_ = nullptr;
};

}  // namespace newtop::detail::taylor_ensemble_run
