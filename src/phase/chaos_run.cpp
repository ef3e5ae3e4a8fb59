// The chaos indicators on a Model: the templates of chaos_run.hpp compiled once for every field.

#include "newtop/phase/chaos_run.hpp"

#include "newtop/exact/model_fields.hpp"
#include "newtop/model/state_checks.hpp"

namespace newtop::phase {

ChaosResult chaos_run(const MethodSettings& method, const Model& model, const State& x0, double t0,
                      double t1, IntegrateOptions options, bool spectrum,
                      const std::function<void(const ChaosSample&)>& history, std::int64_t every,
                      const std::function<void(double)>& on_step) {
  validate(x0);
  return visit_model(model, [&](const auto& m) {
    return chaos_run(method, m, x0, t0, t1, options, spectrum, history, every, on_step);
  });
}

double two_trajectory_lyapunov(const MethodSettings& method, const Model& model, const State& x0,
                               double t0, double t1, double d0, int renorm) {
  validate(x0);
  return visit_model(model, [&](const auto& m) {
    return two_trajectory_lyapunov(method, m, x0, t0, t1, d0, renorm);
  });
}

}  // namespace newtop::phase
