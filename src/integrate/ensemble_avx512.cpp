// The ensemble kernel for AVX-512: eight doubles per register, eight registers per block (eight
// independent dependency chains: 1.2e8 trajectory-steps/s for splitting2 against 0.5e8 with one
// and 0.86e8 with two, docs/performance.md). Compiled with -mavx512f -ffp-contract=off
// (CMakeLists.txt); run only where the CPU has AVX-512F (ensemble.cpp).

#include "ensemble_kernel.hpp"
#include "ensemble_tangent_kernel.hpp"

#ifdef NEWTOP_ENSEMBLE_X86
#include <immintrin.h>

namespace newtop::detail {
namespace {

struct Avx512 {
  typedef double V __attribute__((vector_size(64)));
  static constexpr int B = 8;
  static V splat(double x) { return V{x, x, x, x, x, x, x, x}; }
  static bool all_le(V a, V b) {
    return _mm512_cmp_pd_mask(__m512d(a), __m512d(b), _CMP_LE_OQ) == 0xFF;
  }
};

}  // namespace

void ensemble_run_avx512(const EnsembleTask& task) { ensemble_simd::run_blocks<Avx512>(task); }
std::size_t ensemble_block_avx512() { return 8 * Avx512::B; }
void ensemble_tangent_run_avx512(const EnsembleTangentTask& task) {
  ensemble_simd::run_tangent_blocks<Avx512>(task);
}

}  // namespace newtop::detail
#endif
