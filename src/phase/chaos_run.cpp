// The chaos indicators on a Model: the templates of chaos_run.hpp compiled once for every field.

#include "newtop/phase/chaos_run.hpp"

#include <algorithm>
#include <string>

#include "newtop/exact/model_fields.hpp"
#include "newtop/model/state_checks.hpp"

namespace newtop::phase {

void check_chaos_request(const ChaosRequest& r) {
  check_tangent_method(r.method);
  check_time_span(r.t0, r.t_end);
  if (r.t_end == r.t0) {
    throw InputError("t_end: expected a time different from t0 = " + format_number(r.t0) +
                     ", found " + format_number(r.t_end) + " (a run of no length)");
  }
  check_options(r.options);
  if (r.history_rows < 0) {
    throw InputError("history_rows: expected a count >= 0, found " +
                     std::to_string(r.history_rows));
  }
}

std::int64_t history_interval(const ChaosRequest& r) {
  if (r.history_rows == 0 || method_info(r.method.name).kind == MethodKind::adaptive) return 1;
  const std::int64_t steps = fixed_step_count(r.t0, r.t_end, r.method.step);
  return std::max<std::int64_t>(1, (steps + r.history_rows - 1) / r.history_rows);
}

ChaosResult chaos(const Model& model, const State& x0, const ChaosRequest& request) {
  check_chaos_request(request);
  validate(x0);
  return visit_model(model, [&](const auto& m) { return chaos(m, x0, request); });
}

double two_trajectory_lyapunov(const MethodSettings& method, const Model& model, const State& x0,
                               double t0, double t1, double d0, int renorm) {
  validate(x0);
  return visit_model(model, [&](const auto& m) {
    return two_trajectory_lyapunov(method, m, x0, t0, t1, d0, renorm);
  });
}

}  // namespace newtop::phase
