#include "newtop/orbit/orbit_reports.hpp"

#include <string>

#include "newtop/orbit/orbit_equilibria.hpp"

namespace newtop {

RelativeStabilityReport relative_stability(const CircularOrbitModel& model,
                                           const RelativeStabilityRequest& request) {
  if (request.equilibrium.has_value() == request.state.has_value()) {
    throw InputError(request.equilibrium_name + ", " + request.state_name +
                     ": expected exactly one of them, found " +
                     (request.state ? "both" : "neither"));
  }
  OrbitState s;
  if (request.equilibrium) {
    // The K-th (1-based) of find_relative_equilibria's list, at rest in the orbital frame.
    const RelativeEquilibriumSet set = find_relative_equilibria(model);
    const int n = static_cast<int>(set.equilibria.size());
    const int k = *request.equilibrium;
    if (k < 1 || k > n) {
      throw InputError(request.equilibrium_name + ": expected 1 to " + std::to_string(n) +
                       " (the relative equilibria as equilibria lists them), found " +
                       std::to_string(k));
    }
    const RelativeEquilibrium& e = set.equilibria[static_cast<std::size_t>(k - 1)];
    s = relative_rest_state(model, e.gamma, e.normal);
  } else {
    s = *request.state;
  }
  const double res = fixed_point_residual(model, s);
  if (!(res <= kRelativeEquilibriumTolerance)) {
    throw InputError(request.state_name +
                     ": expected a relative equilibrium (relative residual of d(m, gamma, "
                     "normal)/dt <= " +
                     format_number(kRelativeEquilibriumTolerance) + "), found residual " +
                     format_number(res) + "; see the list of equilibria");
  }
  return {relative_equilibrium_stability(model, s), s, omega(model.body(), s),
          jacobi_integral(model, s), res};
}

DebraDelpDiagram debra_delp_diagram(const RatioRange& k_R, const RatioRange& k_Y) {
  DebraDelpDiagram d;
  d.points = debra_delp_scan(k_R.lo, k_R.hi, k_R.n, k_Y.lo, k_Y.hi, k_Y.n);
  for (const DebraDelpPoint& p : d.points) {
    ++d.counts[static_cast<std::size_t>(p.computed)];
    d.disagreements_with_closed_form += !p.boundary && p.computed != p.closed_form;
  }
  return d;
}

}  // namespace newtop
