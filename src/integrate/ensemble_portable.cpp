// The ensemble kernel for any CPU: pairs of doubles (SSE2 on x86-64, plain code elsewhere), six
// pairs per block. Compiled with -ffp-contract=off (CMakeLists.txt).

#include "ensemble_kernel.hpp"
#include "ensemble_tangent_kernel.hpp"

namespace newtop::detail {
namespace {

struct Portable {
  typedef double V __attribute__((vector_size(16)));
  static constexpr int B = 6;
  static V splat(double x) { return V{x, x}; }
  static bool all_le(V a, V b) { return a[0] <= b[0] && a[1] <= b[1]; }
};

}  // namespace

void ensemble_run_portable(const EnsembleTask& task) { ensemble_simd::run_blocks<Portable>(task); }
std::size_t ensemble_block_portable() { return 2 * Portable::B; }
void ensemble_tangent_run_portable(const EnsembleTangentTask& task) {
  ensemble_simd::run_tangent_blocks<Portable>(task);
}

}  // namespace newtop::detail
