// Fuzz harness: the sweep file reader (sweep::read_sweep, sweep::load_sweep): the bytes as a sweep
// file next to its base scenarios (sweep_bases.hpp: two fixed-point, two orbit scenarios). An
// accepted file has known, distinct quantities, distinct axis keys, non-empty axes of finite
// values (of equal lengths for a zip) and at most 10⁸ points; a sweep of a few points is then
// loaded whole (every point's scenario built and checked), and each point's scenario must build
// again.

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "harness.hpp"
#include "newtop/sweep/sweep.hpp"
#include "sweep_bases.hpp"

namespace {

using namespace newtop;

/// Sweeps of at most this many points are loaded whole: building every point's scenario is the
/// costly part, and a few points reach every branch of it.
constexpr std::size_t kMaxPointsLoaded = 4;

void require(bool ok) {
  if (!ok) std::abort();
}

void check_file(const sweep::SweepFile& s) {
  const auto& known = sweep::known_quantities();
  for (std::size_t i = 0; i < s.quantities.size(); ++i) {
    require(std::find(known.begin(), known.end(), s.quantities[i]) != known.end());
    for (std::size_t j = 0; j < i; ++j) require(s.quantities[j] != s.quantities[i]);
  }
  double points = 1;
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    const sweep::Axis& a = s.axes[k];
    require(!a.values.empty());
    for (const double v : a.values) require(std::isfinite(v));
    for (std::size_t j = 0; j < k; ++j) require(s.axes[j].key != a.key);
    if (s.combine == sweep::Combine::zip) require(a.values.size() == s.axes[0].values.size());
    points *= static_cast<double>(a.values.size());
  }
  require(s.combine == sweep::Combine::zip || points <= 1e8);
  require(sweep::point_count(s) >= 1);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::TempFile file(fuzz::bytes(data, size), ".toml", "sweep");
  static const fuzz::FolderRemovedAtExit bases = [&] {
    const std::filesystem::path dir = std::filesystem::path(file.path()).parent_path();
    fuzz::write_sweep_bases(dir);
    return fuzz::FolderRemovedAtExit{dir};
  }();
  (void)bases;
  fuzz::expect_result_or_input_error([&] {
    const sweep::SweepFile read = sweep::read_sweep(file.path());
    check_file(read);
    if (sweep::point_count(read) > kMaxPointsLoaded) return;
    const sweep::SweepFile s = sweep::load_sweep(file.path());
    check_file(s);
    require(!s.input_files.empty() && s.input_files.front() == file.path());
    try {  // checked by load_sweep: no point may be refused now
      for (std::size_t i = 0; i < sweep::point_count(s); ++i) {
        require(sweep::point_values(s, i).size() == s.axes.size());
        if (s.model == sweep::BaseModel::fixed_point) {
          sweep::point_scenario(s, i);
        } else {
          sweep::orbit_point_scenario(s, i);
        }
      }
    } catch (const InputError&) {
      std::abort();
    }
  });
  return 0;
}
