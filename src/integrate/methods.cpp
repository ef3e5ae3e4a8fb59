#include <cmath>
#include <vector>

#include "newtop/core/types.hpp"
#include "newtop/integrate/composition_tables.hpp"
#include "newtop/integrate/method_settings.hpp"

namespace newtop {
namespace {

std::vector<MethodInfo> make_methods() {
  std::vector<MethodInfo> m;
  for (const auto& t : composition_tables()) {
    m.push_back({t.name, MethodKind::splitting, t.order, "Lie–Poisson splitting, exact sub-flows"});
  }
  m.push_back({"rk4", MethodKind::fixed_rk, 4, "classical Runge–Kutta, fixed step (Boost.Odeint)"});
  m.push_back({"dopri5", MethodKind::adaptive, 5, "Dormand–Prince 5(4), adaptive (Boost.Odeint)"});
  m.push_back({"rkf78", MethodKind::adaptive, 8, "Fehlberg 7(8), adaptive (Boost.Odeint)"});
  m.push_back({"dop853", MethodKind::adaptive, 8,
               "Dormand–Prince 8(5,3), adaptive, dense output of order 7"});
  m.push_back({"taylor", MethodKind::adaptive, 0,
               "Taylor series, adaptive step, order from the tolerance (quadratic field only)"});
  return m;
}

}  // namespace

std::span<const MethodInfo> methods() {
  static const std::vector<MethodInfo> m = make_methods();
  return m;
}

const MethodInfo& method_info(std::string_view name) {
  for (const auto& m : methods()) {
    if (m.name == name) return m;
  }
  std::string known;
  for (const auto& m : methods()) known += (known.empty() ? "" : ", ") + std::string(m.name);
  throw InputError("method: expected one of " + known + ", found '" + std::string(name) + "'");
}

FreeBodySplit free_body_split(std::string_view name, std::string_view field) {
  if (name == "axes") return FreeBodySplit::axes;
  if (name == "spin") return FreeBodySplit::spin;
  if (name == "exact") return FreeBodySplit::exact;
  throw InputError(std::string(field) + ": expected \"axes\", \"spin\" or \"exact\", found \"" +
                   std::string(name) + "\"");
}

std::string_view to_string(FreeBodySplit split) {
  switch (split) {
    case FreeBodySplit::axes:
      return "axes";
    case FreeBodySplit::spin:
      return "spin";
    case FreeBodySplit::exact:
      return "exact";
  }
  return "axes";
}

FreeBodySplit free_body_split(const MethodSettings& settings) {
  if (settings.ordering) return settings.ordering->free_body;
  return default_ordering(composition_table(settings.name)).free_body;
}

void validate(const MethodSettings& s) {
  const MethodInfo& info = method_info(s.name);
  if (info.kind == MethodKind::adaptive) {
    if (!(std::isfinite(s.abs_tol) && s.abs_tol > 0) ||
        !(std::isfinite(s.rel_tol) && s.rel_tol > 0)) {
      throw InputError("tol: expected finite tolerances > 0 for method " + std::string(s.name) +
                       ", found abs " + format_number(s.abs_tol) + ", rel " +
                       format_number(s.rel_tol));
    }
  } else if (!(std::isfinite(s.step) && s.step > 0)) {
    throw InputError("step: expected a finite step > 0 for method " + std::string(s.name) +
                     ", found " + format_number(s.step));
  }
}

}  // namespace newtop
