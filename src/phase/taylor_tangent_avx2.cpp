// Taylor's recurrences of the tangent vectors in 4-lane AVX2 vectors (taylor_tangent_lanes.hpp).
// Compiled with -mavx2 -mfma -ffp-contract=off (CMakeLists.txt); run only where the processor has
// AVX2 and FMA (taylor_tangent.cpp).

#include "taylor_tangent_lanes.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
namespace newtop::detail {

void taylor_expand_tangent_avx2(const TaylorModel& p, const TaylorSeries& s,
                                TaylorTangentSeries& ts) {
  taylor_lanes::expand_tangent_lanes<taylor_lanes::V4, taylor_lanes::V4Fma>(p, s, ts);
}

}  // namespace newtop::detail
#endif
