#pragma once
/// \file
/// Chaos indicators from the tangent map of the integrator (docs/chaos.md): the maximal Lyapunov
/// exponent, the spectrum (Benettin's QR method on 6 vectors), MEGNO ⟨Y⟩ (Cincotta–Simó) and the
/// fast Lyapunov indicator. The tangent run is driven like a fixed-step run of the driver (n equal
/// steps landing on t1); the indicators are an observer of it, called after every step with the
/// time, the state and the tangent vectors, which it renormalises. Declarations only; the tangent
/// runs on a BasicModel<F> are templates in chaos_run.hpp. The entry point is
/// chaos(model, x0, ChaosRequest) -> ChaosResult.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/integrate/outcome.hpp"
#include "newtop/model/model.hpp"
#include "newtop/phase/tangent_vectors.hpp"

namespace newtop::phase {

/// The indicators at a time (the history of a run). On a backward run (t < t0) every t − t0 below
/// reads |t − t0|, the time elapsed along the run: they are the indicators of the backward flow.
struct ChaosSample {
  double t = 0;
  double lyapunov_max = 0;  ///< ln|δ(t)|/(t − t0), δ the first tangent vector, |δ(t0)| = 1
  double megno_y = 0;       ///< Y(t) = (2/(t − t0)) ∫ (s − t0) d ln|δ(s)|
  double megno = 0;         ///< ⟨Y⟩(t), the running time average of Y
  double fli = 0;           ///< FLI(t) = max_{s ≤ t} ln|δ(s)|
  /// Σ ln|R_ii| / (t − t0) in Benettin's column order (descending only as t → ∞: at a finite
  /// time exponents near zero may come in any order).
  std::optional<std::array<double, 6>> spectrum;
};

/// The observer: renormalises the tangent vectors after every step (QR when there are several)
/// and accumulates the indicators. One vector (spectrum off) or six (on).
class ChaosIndicators {
 public:
  ChaosIndicators(double t0, int vectors);
  /// After a step from the previous time to t: renormalises V (renormalise_tangent) and
  /// accumulates.
  void operator()(double t, Tangent& V);
  /// After a step from the previous time to t whose tangent vectors grew by the factors
  /// exp(log_growth[i]) (|δ| of the one vector, or Benettin's |R_ii|; only the first is read with
  /// one vector): the accumulation alone, for tangent vectors renormalised by their own stepper.
  void accumulate(double t, const std::array<double, 6>& log_growth);
  ChaosSample sample() const;

 private:
  double t0_, t_prev_;
  int n_;
  double log_norm_ = 0;  // ln|δ| of the first vector, unrenormalised
  double s_ = 0;         // ∫ (s − t0) d ln|δ|
  double y_prev_ = 0, mean_integral_ = 0, fli_ = 0;
  std::array<double, 6> log_r_{};
};

/// Renormalises the tangent vectors: one vector to unit length, six by Benettin's QR (V = QR,
/// V ← Q with the signs that make R_ii > 0); returns ln|δ| (one vector) or ln|R_ii|.
std::array<double, 6> renormalise_tangent(Tangent& V);

/// The first tangent vector (1, 1, 1, 1, 1, 1)/√6, or the identity for the spectrum.
Tangent initial_tangent(int vectors);

struct ChaosResult {
  Outcome outcome;
  ChaosSample indicators;
};

/// Everything a chaos run of one start needs (docs/chaos.md).
struct ChaosRequest {
  /// A method with a tangent map (check_tangent_method): a splitting composition of the axes or
  /// spin split with its step, rk4 with its step, or an adaptive method with its tolerances.
  MethodSettings method{};
  double t0 = 0.0;
  /// The end of the run (≠ t0; below t0: the indicators of the backward flow).
  double t_end = 0.0;
  /// The full spectrum (Benettin's QR on 6 vectors) besides λ_max, MEGNO and the FLI (one vector).
  bool spectrum = false;
  IntegrateOptions options{};  ///< max_steps, min_step_factor (the step is the method's)
  /// Receives the indicators after every step, or every k-th step with history_rows (and the
  /// last sample in any case).
  std::function<void(const ChaosSample&)> history{};
  /// At most this many samples of a fixed-step run of n steps: one every ⌈n / history_rows⌉ steps
  /// (and the last). 0: every step. An adaptive run is sampled at every accepted step.
  std::int64_t history_rows = 0;
  /// Called after every step with the time (throws to stop the run).
  std::function<void(double)> on_step{};
};

/// Throws InputError for a request no run can use, before any work: a method without a tangent
/// map or with a bad step or tolerance, non-finite times, a run of no length (t_end = t0), options
/// no run can use, history_rows < 0.
void check_chaos_request(const ChaosRequest& request);

/// The number of steps between two history samples of the request's run (history_rows).
std::int64_t history_interval(const ChaosRequest& request);

/// The indicators of the trajectory from (request.t0, x0) to request.t_end (InputError for a state
/// or request that is not valid, before any work). Compiled once for every field; chaos_run.hpp
/// holds the template on a BasicModel<F>.
ChaosResult chaos(const Model& model, const State& x0, const ChaosRequest& request);

/// Benettin's two-trajectory estimate of λ_max (chaos_run.hpp), compiled once for every field.
double two_trajectory_lyapunov(const MethodSettings& method, const Model& model, const State& x0,
                               double t0, double t1, double d0 = 1e-8, int renorm = 10);

}  // namespace newtop::phase
