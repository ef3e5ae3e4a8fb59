// The ensemble kernel for AVX2: four doubles per register, six registers per block (the rotations
// are a chain of dependent operations; six independent chains keep the units busy: 1.1e8
// trajectory-steps/s for splitting2 against 0.6e8 with two, docs/performance.md). Compiled with
// -mavx2 -ffp-contract=off (CMakeLists.txt); run only where the CPU has AVX2 and FMA (ensemble.cpp:
// the Taylor ensemble's AVX2 kernel needs both, and the two paths share one test).

#include "ensemble_kernel.hpp"
#include "ensemble_tangent_kernel.hpp"

#ifdef NEWTOP_ENSEMBLE_X86
#include <immintrin.h>

namespace newtop::detail {
namespace {

struct Avx2 {
  typedef double V __attribute__((vector_size(32)));
  static constexpr int B = 6;
  static V splat(double x) { return V{x, x, x, x}; }
  static bool all_le(V a, V b) {
    return _mm256_movemask_pd(_mm256_cmp_pd(__m256d(a), __m256d(b), _CMP_LE_OQ)) == 0xF;
  }
};

}  // namespace

void ensemble_run_avx2(const EnsembleTask& task) { ensemble_simd::run_blocks<Avx2>(task); }
std::size_t ensemble_block_avx2() { return 4 * Avx2::B; }
void ensemble_tangent_run_avx2(const EnsembleTangentTask& task) {
  ensemble_simd::run_tangent_blocks<Avx2>(task);
}

}  // namespace newtop::detail
#endif
