// The Taylor ensemble's kernel for AVX-512: eight doubles per register. Compiled with -mavx512f
// -ffp-contract=off (CMakeLists.txt); run only where the CPU has AVX-512F (taylor_ensemble.cpp).

#include "taylor_ensemble_wide.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

namespace newtop::detail {
namespace {

using V = double __attribute__((vector_size(64)));
constexpr int kLanes = 8;

// a·b + c rounded once, lane by lane.
struct Fma {
  static V fma(V a, V b, V c) { return _mm512_fmadd_pd(a, b, c); }
};

void expand(const double* consts, const double* x, int order, double* series) {
  taylor_ensemble_simd::expand_wide<V, kLanes, Fma>(consts, x, order, series);
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

TaylorLaneKernel taylor_lane_kernel_avx512() {
  return {kLanes, expand, sum, advance, expand_tangent, norms, steps};
}

}  // namespace newtop::detail
#endif
