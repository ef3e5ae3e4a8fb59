// The orbit's Taylor ensemble kernel (orbit_taylor_kernel.hpp) for portable: pairs of doubles (SSE2
// on x86-64, plain code elsewhere). Compiled with -ffp-contract=off (CMakeLists.txt).

#include "orbit_taylor_kernel.hpp"

namespace newtop::detail {
namespace {

using V = double __attribute__((vector_size(16)));
constexpr int kLanes = 2;

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

OrbitTaylorLaneKernel orbit_taylor_lane_kernel_portable() {
  return {kLanes, expand_circular, expand_elliptic, expand_tangent_circular,
          expand_tangent_elliptic};
}

}  // namespace newtop::detail
