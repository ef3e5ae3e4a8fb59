// The stability diagram of a spin over two parameters (stability_grid.hpp).

#include "newtop/sweep/stability_grid.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "newtop/io/option_lists.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace newtop::sweep {
namespace {

void check_axis_values(const Axis& a) {
  check_spin_parameter("stability grid", a.key);
  if (a.values.empty()) {
    throw InputError("stability grid: " + a.key + ": expected at least one value, found none");
  }
  for (const double v : a.values) {
    if (!std::isfinite(v)) {
      throw InputError("stability grid: " + a.key + ": expected finite values, found " +
                       format_number(v));
    }
  }
}

}  // namespace

StabilityGrid stability_grid(const QuadraticModel& model, int axis, double omega, const Axis& first,
                             const Axis& second, int threads) {
  check_axis_values(first);
  check_axis_values(second);
  const std::size_t n1 = first.values.size(), n2 = second.values.size();
  if (static_cast<long double>(n1) * static_cast<long double>(n2) > io::kMaxGridPoints) {
    throw InputError("stability grid: expected at most " + std::to_string(io::kMaxGridPoints) +
                     " points, found " + std::to_string(n1) + "*" + std::to_string(n2));
  }
  StabilityGrid g{first.key, second.key, first.values, second.values, {}, {}};
  const auto count = static_cast<std::int64_t>(n1 * n2);
  g.max_real_part.assign(n1 * n2, std::numeric_limits<double>::quiet_NaN());
  g.verdict.assign(n1 * n2, GridVerdict::nonphysical);
  int workers = 1;
#ifdef _OPENMP
  workers = threads > 0 ? threads : omp_get_max_threads();
#endif
  (void)threads;
  // Each point from its own parameters, written at its own index: the same bits for any thread
  // count (the sweep engine's rule).
#pragma omp parallel for schedule(dynamic, 64) num_threads(workers)
  for (std::int64_t p = 0; p < count; ++p) {
    const auto idx = static_cast<std::size_t>(p);
    const std::optional<Spectrum> s = spin_stability_at(
        model, axis, omega,
        {{first.key, first.values[idx / n2]}, {second.key, second.values[idx % n2]}});
    if (!s) continue;
    g.max_real_part[idx] = s->max_real_part;
    g.verdict[idx] = s->linearly_stable ? GridVerdict::stable : GridVerdict::unstable;
  }
  return g;
}

}  // namespace newtop::sweep
