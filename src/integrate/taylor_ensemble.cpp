// The Taylor ensemble (newtop/integrate/taylor_ensemble.hpp): the checks of a batch and its run
// through one block of lanes (taylor_ensemble_run.hpp), with or without a tangent vector per
// trajectory. Compiled with -ffp-contract=off (CMakeLists.txt).

#include "newtop/integrate/taylor_ensemble.hpp"

#include <string>

#include "taylor_ensemble_run.hpp"

namespace newtop {

using detail::taylor_ensemble_run::BatchRun;
using detail::taylor_ensemble_run::kernel_of;

namespace {

void check_models(std::span<const QuadraticModel> models, std::span<const State> states) {
  if (models.size() != 1 && models.size() != states.size()) {
    throw InputError("models: expected 1 or one per state (" + std::to_string(states.size()) +
                     "), found " + std::to_string(models.size()));
  }
}

// The driver's checks before any work (run_adaptive), for every trajectory.
void check_run(double t0, double t1, const IntegrateOptions& options,
               std::span<const State> states) {
  check_time_span(t0, t1);
  check_options(options);
  for (const State& x : states) check_state(x);
}

}  // namespace

TaylorEnsemble::TaylorEnsemble(double abs_tol, double rel_tol, SimdPath path, int order)
    : abs_tol_(abs_tol),
      rel_tol_(rel_tol),
      order_(TaylorStepper(abs_tol, rel_tol, order).order()),  // its checks and order rule
      path_(path) {
  if (!simd_path_available(path)) {
    throw InputError("simd: expected a path this build and CPU support (best: " +
                     std::string(simd_path_name(best_simd_path())) + "), found " +
                     std::string(simd_path_name(path)));
  }
}

std::size_t TaylorEnsemble::lanes() const {
  return static_cast<std::size_t>(kernel_of(path_).lanes);
}

std::vector<Outcome> TaylorEnsemble::integrate(std::span<const QuadraticModel> models,
                                               std::span<const State> states, double t0, double t1,
                                               const IntegrateOptions& options,
                                               const TaylorEnsembleObserver& observer) {
  check_models(models, states);
  check_run(t0, t1, options, states);
  if (states.empty()) return {};
  return BatchRun(*this, models, states, t0, t1, options, observer, workspace_).run();
}

std::vector<Outcome> TaylorEnsemble::integrate_tangent(std::span<const QuadraticModel> models,
                                                       std::span<const State> states,
                                                       std::span<const TangentVector> v0, double t0,
                                                       double t1, const IntegrateOptions& options,
                                                       const TaylorTangentObserver& observer) {
  check_models(models, states);
  if (v0.size() != 1 && v0.size() != states.size()) {
    throw InputError("tangent: expected 1 vector or one per state (" +
                     std::to_string(states.size()) + "), found " + std::to_string(v0.size()));
  }
  check_run(t0, t1, options, states);
  if (states.empty()) return {};
  const TaylorTangentObserver on_step =
      observer ? observer : [](std::size_t, double, const State&, TangentVector&) {};
  const TaylorEnsembleObserver none;
  return BatchRun(*this, models, states, t0, t1, options, none, workspace_, v0, &on_step).run();
}

}  // namespace newtop
