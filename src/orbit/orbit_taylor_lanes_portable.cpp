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

}  // namespace

OrbitTaylorLaneKernel orbit_taylor_lane_kernel_portable() {
  return {kLanes, expand_circular, expand_elliptic};
}

}  // namespace newtop::detail
