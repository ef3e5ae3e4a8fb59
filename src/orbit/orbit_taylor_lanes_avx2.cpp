// The orbit's Taylor ensemble kernel (orbit_taylor_kernel.hpp) for avx2: four doubles per register.
// Compiled with -mavx2 -ffp-contract=off (CMakeLists.txt); run only where the CPU has it
// (orbit_taylor_ensemble.cpp).

#include "orbit_taylor_kernel.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
namespace newtop::detail {
namespace {

using V = double __attribute__((vector_size(32)));
constexpr int kLanes = 4;

void expand_circular(const double* consts, const double* x, int order, double* series) {
  orbit_taylor_simd::expand_circular<V, kLanes>(consts, x, order, series);
}
void expand_elliptic(const double* consts, const double* x, int order, double* series) {
  orbit_taylor_simd::expand_elliptic<V, kLanes>(consts, x, order, series);
}
void expand_tangent_circular(const double* consts, const double* series, const double* v, int order,
                             double* tangent) {
  orbit_taylor_simd::expand_tangent_circular<V, kLanes>(consts, series, v, order, tangent);
}
void expand_tangent_elliptic(const double* consts, const double* series, const double* v, int order,
                             double* tangent) {
  orbit_taylor_simd::expand_tangent_elliptic<V, kLanes>(consts, series, v, order, tangent);
}

}  // namespace

OrbitTaylorLaneKernel orbit_taylor_lane_kernel_avx2() {
  return {kLanes, expand_circular, expand_elliptic, expand_tangent_circular,
          expand_tangent_elliptic};
}

}  // namespace newtop::detail
#endif
