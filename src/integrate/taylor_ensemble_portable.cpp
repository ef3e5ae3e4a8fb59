// The Taylor ensemble's kernel for any CPU: pairs of doubles (SSE2 on x86-64, plain code
// elsewhere). Compiled with -ffp-contract=off (CMakeLists.txt).

#include <cmath>

#include "taylor_ensemble_kernel.hpp"

namespace newtop::detail {
namespace {

using V = double __attribute__((vector_size(16)));
constexpr int kLanes = 2;

// a·b + c rounded once, lane by lane (std::fma: the processor's instruction where it has one, the
// C library's exact emulation elsewhere).
struct Fma {
  static V fma(V a, V b, V c) { return V{std::fma(a[0], b[0], c[0]), std::fma(a[1], b[1], c[1])}; }
};

void expand(const double* consts, const double* x, int order, double* series) {
  taylor_ensemble_simd::expand<V, kLanes, Fma>(consts, x, order, series);
}
void sum(const double* series, int order, const double* h, double* out) {
  taylor_ensemble_simd::sum<V, kLanes>(series, order, h, out);
}
unsigned advance(const double* series, int order, const double* h, unsigned lanes, double* x) {
  return taylor_ensemble_simd::advance<V, kLanes>(series, order, h, lanes, x);
}

void expand_tangent(const double* consts, const double* series, const double* v, int order,
                    double* tangent) {
  taylor_ensemble_simd::expand_tangent<V, kLanes, Fma>(consts, series, v, order, tangent);
}

void norms(const double* series, const double* tangent, int order, double* out) {
  taylor_ensemble_simd::norms<V, kLanes>(series, tangent, order, out);
}

void steps(const double* norms, int order, double abs_tol, double rel_tol, double* out) {
  taylor_ensemble_simd::steps<V, kLanes>(norms, order, abs_tol, rel_tol, out);
}

}  // namespace

TaylorLaneKernel taylor_lane_kernel_portable() {
  return {kLanes, expand, sum, advance, expand_tangent, norms, steps};
}

}  // namespace newtop::detail
