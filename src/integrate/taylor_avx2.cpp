// Taylor's recurrences of the state in 4-lane AVX2 vectors (taylor_recurrences.hpp). Compiled with
// -mavx2 -mfma -ffp-contract=off (CMakeLists.txt); run only where the processor has AVX2 and FMA
// (taylor.cpp).

#include "taylor_recurrences.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
namespace newtop::detail {

void taylor_expand_avx2(const TaylorModel& p, int order, TaylorSeries& s) {
  taylor_lanes::expand_lanes<taylor_lanes::V4, taylor_lanes::V4Fma>(p, order, s);
}

}  // namespace newtop::detail
#endif
