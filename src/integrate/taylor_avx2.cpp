// Taylor's recurrences of the state in 4-lane AVX2 vectors (taylor_recurrences.hpp). Compiled with
// -mavx2 -mfma -ffp-contract=off (CMakeLists.txt); run only where the processor has AVX2 and FMA
// (taylor.cpp).

#include "taylor_recurrences.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

namespace newtop::detail {
namespace {

// a·b + c rounded once, lane by lane.
struct V4Fma {
  [[gnu::always_inline]] static taylor_lanes::V4 fma(const taylor_lanes::V4& a,
                                                     const taylor_lanes::V4& b,
                                                     const taylor_lanes::V4& c) {
    return _mm256_fmadd_pd(a, b, c);
  }
};

}  // namespace

void taylor_expand_avx2(const TaylorModel& p, int order, TaylorSeries& s) {
  taylor_lanes::expand_lanes<taylor_lanes::V4, V4Fma>(p, order, s);
}

}  // namespace newtop::detail
#endif
