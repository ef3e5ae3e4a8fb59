// Fuzz harness: the option lists of the command line (newtop/io/option_lists.hpp). The first byte
// chooses the option, the rest is its text; each accepted list must keep the promises its
// documentation makes (finite values, counts within their bounds, a unit --gamma).

#include <cmath>
#include <cstdlib>

#include "harness.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/io/option_lists.hpp"

namespace {

using namespace newtop;

void require(bool ok) {
  if (!ok) std::abort();
}

// |γ| = 1 after normalizing three finite numbers, to a few ulp.
constexpr double kUnitTolerance = 1e-15;

void check_range(const io::Range& r) {
  require(std::isfinite(r.lo) && std::isfinite(r.hi) && r.n >= 1 && r.n <= kMaxScanPoints);
  require(std::isfinite(r.at(0)) && std::isfinite(r.at(r.n - 1)));
}

void one(unsigned choice, const std::string& text) {
  switch (choice % 8) {
    case 0: {
      const std::vector<double> t = io::parse_times("--times", text);
      require(!t.empty());
      for (const double x : t) require(std::isfinite(x));
      break;
    }
    case 1: {
      const Vec3 g = io::parse_gamma(text);
      require(g.allFinite() && std::abs(g.norm() - 1.0) <= kUnitTolerance);
      break;
    }
    case 2: {
      const io::RadiusScan s = io::parse_radius_scan(text);
      require(std::isfinite(s.R1) && std::isfinite(s.R2) && s.R1 > 0 && s.R2 > s.R1);
      require(s.n >= 2 && s.n <= kMaxScanPoints);
      break;
    }
    case 3:
      check_range(io::parse_range("--scan-omega", text, false));
      break;
    case 4: {
      const auto [r1, r2] = io::parse_grid(text);
      check_range(r1);
      check_range(r2);
      require(static_cast<long long>(r1.n) * r2.n <= io::kMaxGridPoints);
      break;
    }
    case 5:
      for (const SpinOrbitResonance& r : io::parse_resonances(text)) {
        require(r.p >= 0 && r.q >= 1 && r.q <= 12 && r.periods >= 1);
      }
      break;
    case 6: {
      const io::SpinScan s = io::parse_spin(text);
      require(std::isfinite(s.lo) && std::isfinite(s.hi) && s.lo <= s.hi);
      require(s.n >= 1 && s.n <= 10000);
      break;
    }
    default: {
      const auto [r, y] = io::parse_ratio_scan(text);
      for (const io::RatioAxis& a : {r, y}) {
        require(std::abs(a.lo) < 1 && std::abs(a.hi) < 1 && a.n >= 1);
      }
      require(static_cast<long long>(r.n) * y.n <= io::kMaxGridPoints);
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text = newtop::fuzz::bytes(data + 1, size - 1);
  newtop::fuzz::expect_result_or_input_error([&] { one(data[0], text); });
  return 0;
}
