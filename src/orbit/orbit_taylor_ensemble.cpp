// The orbit's Taylor ensemble (newtop/orbit/orbit_taylor_ensemble.hpp): the checks of a batch and
// its run through one block of lanes. The kernel forms the series of every lane at once
// (orbit_taylor_kernel.hpp); each lane's step rule, sum, acceptance and end are decided by the
// scalar stepper's functions (orbit_taylor_step, orbit_taylor_sum) and the adaptive driver's loop
// (driver.hpp, run_adaptive), decision for decision. Compiled with -ffp-contract=off.

#include "newtop/orbit/orbit_taylor_ensemble.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_taylor.hpp"
#include "orbit_taylor_kernel.hpp"

namespace newtop {

namespace {

static_assert(detail::orbit_taylor_simd::K == detail::OrbitTaylorSeries::kMaxOrder + 1);

detail::OrbitTaylorLaneKernel kernel_of(SimdPath path) {
  switch (path) {
#if defined(__x86_64__) && defined(__GNUC__)
    case SimdPath::avx2:
      return detail::orbit_taylor_lane_kernel_avx2();
    case SimdPath::avx512:
      return detail::orbit_taylor_lane_kernel_avx512();
#endif
    default:
      return detail::orbit_taylor_lane_kernel_portable();
  }
}

/// The driver's variables (run_adaptive) of the trajectory in a lane; `next`: where the lane's dt
/// comes from once the series at its point is formed (the first trial step, try_step's last line
/// after an accepted step, or unchanged after a rejected trial).
struct LaneRun {
  enum class Next { initial, after_step, retry };
  std::size_t point = 0;
  bool active = false;
  Next next = Next::initial;
  double t = 0, dt = 0, h = 0;
  OrbitOutcome out;
};

template <class M>
class BatchRun {
 public:
  BatchRun(const detail::OrbitTaylorLaneKernel& kernel, int order, double abs_tol, double rel_tol,
           std::span<const M> models, std::span<const OrbitState> states, double t0, double t1,
           const IntegrateOptions& opt, const OrbitEnsembleObserver& obs,
           std::vector<double>& workspace, const OrbitChaosObserver* chaos = nullptr)
      : kernel_(kernel),
        L_(static_cast<std::size_t>(kernel.lanes)),
        order_(order),
        abs_tol_(abs_tol),
        rel_tol_(rel_tol),
        models_(models),
        states_(states),
        t0_(t0),
        t1_(t1),
        span_(t1 - t0),
        dir_(t1 - t0 > 0 ? 1.0 : -1.0),
        opt_(opt),
        obs_(obs),
        chaos_(chaos),
        lanes_(L_),
        outcomes_(states.size()) {
    const std::size_t coefficients = 9 * static_cast<std::size_t>(order + 1) * L_;
    workspace.assign((detail::kOrbitLaneRows + 9 + 9) * L_ + 2 * coefficients, 0.0);
    consts_ = workspace.data();
    x_ = consts_ + detail::kOrbitLaneRows * L_;
    v_ = x_ + 9 * L_;
    series_ = v_ + 9 * L_;
    tangent_ = series_ + coefficients;
  }

  std::vector<OrbitOutcome> run() {
    for (std::size_t l = 0; l < L_; ++l) refill(l);
    while (std::any_of(lanes_.begin(), lanes_.end(), [](const LaneRun& r) { return r.active; })) {
      for (std::size_t l = 0; l < L_; ++l) {
        if (!lanes_[l].active) copy_lane(first_active(), l);  // finite numbers in idle lanes
      }
      if constexpr (std::is_same_v<M, EllipticOrbitModel>) {
        for (std::size_t l = 0; l < L_; ++l) {
          consts_[detail::kOrbitCos * L_ + l] = std::cos(lanes_[l].t);
          consts_[detail::kOrbitSin * L_ + l] = std::sin(lanes_[l].t);
        }
        kernel_.expand_elliptic(consts_, x_, order_, series_);
        if (chaos_) kernel_.expand_tangent_elliptic(consts_, series_, v_, order_, tangent_);
      } else {
        kernel_.expand_circular(consts_, x_, order_, series_);
        if (chaos_) kernel_.expand_tangent_circular(consts_, series_, v_, order_, tangent_);
      }
      for (std::size_t l = 0; l < L_; ++l) {
        if (lanes_[l].active) step(l);
      }
    }
    return std::move(outcomes_);
  }

 private:
  std::size_t first_active() const {
    for (std::size_t l = 0; l < L_; ++l) {
      if (lanes_[l].active) return l;
    }
    return 0;
  }

  void copy_lane(std::size_t from, std::size_t to) {
    for (std::size_t q = 0; q < detail::kOrbitLaneRows; ++q)
      consts_[q * L_ + to] = consts_[q * L_ + from];
    for (std::size_t c = 0; c < 9; ++c) {
      x_[c * L_ + to] = x_[c * L_ + from];
      v_[c * L_ + to] = v_[c * L_ + from];
    }
    lanes_[to].t = lanes_[from].t;
  }

  void set_state(std::size_t l, const OrbitState& x) {
    for (Eigen::Index c = 0; c < 3; ++c) {
      const auto i = static_cast<std::size_t>(c);
      x_[i * L_ + l] = x.m[c];
      x_[(3 + i) * L_ + l] = x.gamma[c];
      x_[(6 + i) * L_ + l] = x.normal[c];
    }
  }
  void set_vector(std::size_t l, const OrbitVector& v) {
    for (std::size_t c = 0; c < 9; ++c) v_[c * L_ + l] = v[static_cast<Eigen::Index>(c)];
  }

  void set_model(std::size_t l, const M& model) {
    const Vec3 &I = model.body().inertia(), &k = model.body().gyrostat();
    for (Eigen::Index c = 0; c < 3; ++c) {
      const auto i = static_cast<std::size_t>(c);
      consts_[(detail::kOrbitInertia + i) * L_ + l] = I[c];
      consts_[(detail::kOrbitGyrostat + i) * L_ + l] = k[c];
    }
    if constexpr (std::is_same_v<M, EllipticOrbitModel>) {  // orbit_taylor_expand's constants
      const double e = model.orbit().eccentricity, n = model.orbit().mean_motion;
      const double q = std::pow(1.0 - e * e, 1.5);
      consts_[detail::kOrbitEccentricity * L_ + l] = e;
      consts_[detail::kOrbitSigma * L_ + l] = q / n;
      consts_[detail::kOrbitSigmaLambda * L_ + l] = 3.0 * n / q;
    } else {
      consts_[detail::kOrbitRate * L_ + l] = model.orbit().rate;
      consts_[detail::kOrbitLambda * L_ + l] = model.orbit().lambda_;
    }
  }

  // Puts the next trajectory waiting into lane l (or leaves it idle): start_outcome and the
  // observer at t0, as run_adaptive.
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
      if (obs_ && !chaos_) obs_(p, t0_, states_[p]);
      if (span_ == 0.0) {
        outcomes_[p] = r.out;
        continue;
      }
      set_model(l, models_.size() == 1 ? models_[0] : models_[p]);
      set_state(l, states_[p]);
      if (chaos_) set_vector(l, detail::orbit_chaos_start(states_[p]));
      r.active = true;
      return;
    }
  }

  void finish(std::size_t l) {
    outcomes_[lanes_[l].point] = lanes_[l].out;
    refill(l);
  }

  // The lane's series as the scalar stepper holds it (and its tangent vector's).
  void lane_series(std::size_t l, detail::OrbitTaylorSeries& s) const {
    s.order = order_;
    for (int k = 0; k <= order_; ++k) {
      for (std::size_t c = 0; c < 9; ++c) {
        s.x[static_cast<std::size_t>(k)][c] =
            series_[(9 * static_cast<std::size_t>(k) + c) * L_ + l];
      }
    }
  }
  void lane_tangent(std::size_t l, detail::OrbitTangentSeries& ts) const {
    ts.order = order_;
    ts.columns = 1;
    for (int k = 0; k <= order_; ++k) {
      for (std::size_t c = 0; c < 9; ++c) {
        ts.v[0][static_cast<std::size_t>(k)][c] =
            tangent_[(9 * static_cast<std::size_t>(k) + c) * L_ + l];
      }
    }
  }

  // One pass of run_adaptive's loop for the lane, with OrbitTaylorStepper::try_step on the series
  // formed at the lane's point (with a tangent vector, orbit_chaos's stepper: the step rule over
  // the state and the vector, dt after a step the step at its start, the vector renormalised on
  // the leaf before the driver's check that the trial is finite).
  void step(std::size_t l) {
    LaneRun& r = lanes_[l];
    detail::OrbitTaylorSeries& s = lane_series_;
    detail::OrbitTangentSeries& ts = lane_tangent_;
    lane_series(l, s);
    if (chaos_) lane_tangent(l, ts);
    const double step = chaos_ ? detail::orbit_tangent_step(s, ts, abs_tol_, rel_tol_)
                               : detail::orbit_taylor_step(s, abs_tol_, rel_tol_);
    if (r.next == LaneRun::Next::initial) {
      r.dt = dir_ * (opt_.initial_step > 0 ? opt_.initial_step : step);
    } else if (r.next == LaneRun::Next::after_step && !chaos_) {
      r.dt = r.h < 0 ? -step : step;
    }
    if (r.out.steps + r.out.rejected >= opt_.max_steps) {
      r.out.status = Status::step_limit;
      return finish(l);
    }
    bool last = false;
    if (dir_ * (r.t + r.dt - t1_) >= 0) {
      r.dt = t1_ - r.t;
      last = true;
    }
    const double scale = std::max(std::abs(r.t), std::abs(span_));
    if (!(std::abs(r.dt) >= opt_.min_step_factor * scale)) {
      r.out.status = Status::step_size_underflow;
      return finish(l);
    }
    const double dt_tried = r.dt;
    r.next = LaneRun::Next::retry;
    if (!(step > 0.0)) {  // NaN: the series is not finite (try_step's rejection)
      r.dt *= kNonFiniteShrink;
      if (!std::isfinite(r.dt)) r.dt = kNonFiniteShrink * dt_tried;
      ++r.out.rejected;
      return;
    }
    const double h = std::abs(r.dt) <= step ? r.dt : (r.dt < 0 ? -step : step);
    const OrbitState trial = detail::orbit_taylor_sum(s, h);
    OrbitVector v;
    double growth = 0.0;
    if (chaos_) {
      const std::array<double, 9> y = detail::orbit_tangent_sum(ts, 0, h);
      v = Eigen::Map<const OrbitVector>(y.data());
      growth = detail::orbit_leaf_renormalise(trial, v);
    }
    if (!is_finite(trial) || (chaos_ && !v.allFinite())) {
      r.dt = kNonFiniteShrink * dt_tried;
      ++r.out.rejected;
      return;
    }
    if (chaos_) r.dt = h < 0 ? -step : step;
    r.h = h;
    r.t = last ? t1_ : r.t + h;
    ++r.out.steps;
    r.out.t = r.t;
    r.out.state = trial;
    r.out.last_step = dt_tried;
    set_state(l, trial);
    if (chaos_) {
      set_vector(l, v);
      if (*chaos_) (*chaos_)(r.point, r.t, trial, growth);
    } else if (obs_) {
      obs_(r.point, r.t, trial);
    }
    r.next = LaneRun::Next::after_step;
    if (!(dir_ * (t1_ - r.t) > 0)) finish(l);
  }

  detail::OrbitTaylorLaneKernel kernel_;
  std::size_t L_;
  int order_;
  double abs_tol_, rel_tol_;
  std::span<const M> models_;
  std::span<const OrbitState> states_;
  double t0_, t1_, span_, dir_;
  const IntegrateOptions& opt_;
  const OrbitEnsembleObserver& obs_;
  const OrbitChaosObserver* chaos_;
  std::vector<LaneRun> lanes_;
  std::vector<OrbitOutcome> outcomes_;
  std::size_t next_ = 0;
  double *consts_ = nullptr, *x_ = nullptr, *v_ = nullptr, *series_ = nullptr, *tangent_ = nullptr;
  // One lane's series as the scalar stepper holds them (held here: the tangent's is 20 kB).
  detail::OrbitTaylorSeries lane_series_;
  detail::OrbitTangentSeries lane_tangent_;
};

template <class M>
std::vector<OrbitOutcome> run_batch(const OrbitTaylorEnsemble& e, std::span<const M> models,
                                    std::span<const OrbitState> states, double t0, double t1,
                                    const IntegrateOptions& options,
                                    const OrbitEnsembleObserver& observer, double abs_tol,
                                    double rel_tol, std::vector<double>& workspace,
                                    const OrbitChaosObserver* chaos = nullptr) {
  if (models.size() != 1 && models.size() != states.size()) {
    throw InputError("models: expected 1 or one per state (" + std::to_string(states.size()) +
                     "), found " + std::to_string(models.size()));
  }
  check_time_span(t0, t1);  // the driver's checks before any work, for every trajectory
  check_options(options);
  for (const OrbitState& x : states) check_state(x);
  if (states.empty()) return {};
  return BatchRun<M>(kernel_of(e.path()), e.order(), abs_tol, rel_tol, models, states, t0, t1,
                     options, observer, workspace, chaos)
      .run();
}

}  // namespace

OrbitTaylorEnsemble::OrbitTaylorEnsemble(double abs_tol, double rel_tol, SimdPath path, int order)
    : abs_tol_(abs_tol),
      rel_tol_(rel_tol),
      order_(OrbitTaylorStepper(abs_tol, rel_tol, order).order()),  // its checks and order rule
      path_(path) {
  if (!simd_path_available(path)) {
    throw InputError("simd: expected a path this build and CPU support (best: " +
                     std::string(simd_path_name(best_simd_path())) + "), found " +
                     std::string(simd_path_name(path)));
  }
}

std::size_t OrbitTaylorEnsemble::lanes() const {
  return static_cast<std::size_t>(kernel_of(path_).lanes);
}

std::vector<OrbitOutcome> OrbitTaylorEnsemble::integrate(std::span<const CircularOrbitModel> models,
                                                         std::span<const OrbitState> states,
                                                         double t0, double t1,
                                                         const IntegrateOptions& options,
                                                         const OrbitEnsembleObserver& observer) {
  return run_batch(*this, models, states, t0, t1, options, observer, abs_tol_, rel_tol_,
                   workspace_);
}

std::vector<OrbitOutcome> OrbitTaylorEnsemble::integrate(std::span<const EllipticOrbitModel> models,
                                                         std::span<const OrbitState> states,
                                                         double nu0, double nu1,
                                                         const IntegrateOptions& options,
                                                         const OrbitEnsembleObserver& observer) {
  return run_batch(*this, models, states, nu0, nu1, options, observer, abs_tol_, rel_tol_,
                   workspace_);
}

std::vector<OrbitOutcome> OrbitTaylorEnsemble::integrate_chaos(
    std::span<const CircularOrbitModel> models, std::span<const OrbitState> states, double t0,
    double t1, const IntegrateOptions& options, const OrbitChaosObserver& observer) {
  return run_batch(*this, models, states, t0, t1, options, {}, abs_tol_, rel_tol_, workspace_,
                   &observer);
}

std::vector<OrbitOutcome> OrbitTaylorEnsemble::integrate_chaos(
    std::span<const EllipticOrbitModel> models, std::span<const OrbitState> states, double nu0,
    double nu1, const IntegrateOptions& options, const OrbitChaosObserver& observer) {
  return run_batch(*this, models, states, nu0, nu1, options, {}, abs_tol_, rel_tol_, workspace_,
                   &observer);
}

}  // namespace newtop
