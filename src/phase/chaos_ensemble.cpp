// The chaos indicators of many starts through the Taylor ensemble's tangent runs
// (newtop/phase/chaos_ensemble.hpp): the observer of phase::chaos (ChaosIndicators renormalising
// the vector after every step) per trajectory.

#include "newtop/phase/chaos_ensemble.hpp"

#include "newtop/integrate/taylor_ensemble.hpp"
#include "newtop/phase/tangent_vectors.hpp"

namespace newtop::phase {

std::vector<ChaosResult> taylor_chaos_ensemble(std::span<const QuadraticModel> models,
                                               std::span<const State> states, double t0, double t1,
                                               double abs_tol, double rel_tol,
                                               const IntegrateOptions& options, SimdPath path) {
  TaylorEnsemble ensemble(abs_tol, rel_tol, path);
  std::vector<ChaosIndicators> ind(states.size(), ChaosIndicators(t0, 1));
  const std::vector<TangentVector> v0{initial_tangent(1).col(0)};
  const std::vector<Outcome> out =
      ensemble.integrate_tangent(models, states, v0, t0, t1, options,
                                 [&](std::size_t p, double t, const State&, TangentVector& v) {
                                   Tangent V = v;
                                   ind[p](t, V);
                                   v = V.col(0);
                                 });
  std::vector<ChaosResult> r;
  r.reserve(out.size());
  for (std::size_t i = 0; i < out.size(); ++i) r.push_back({out[i], ind[i].sample()});
  return r;
}

}  // namespace newtop::phase
