// Fuzz harness: the orbit scenario reader (TOML text with [orbit] -> io::OrbitScenario). An
// accepted scenario has a finite initial state with unit γ and n, γ ⊥ n, a finite orbit rate and a
// finite right-hand side at its start.

#include <cmath>
#include <cstdlib>

#include "harness.hpp"
#include "newtop/io/orbit_scenario.hpp"

namespace {

// γ and n are unit and orthogonal to 1e-12 as read, or exactly so when built from a rotation
// (quaternion, euler_321): a few ulp of rounding in the products.
constexpr double kUnitTolerance = 1e-11;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace newtop;
  const std::string text = fuzz::bytes(data, size);
  fuzz::expect_result_or_input_error([&] {
    const io::OrbitScenario s = io::parse_orbit_scenario(text, "fuzz.toml");
    const OrbitState& x = s.initial;
    const bool finite = x.m.allFinite() && x.gamma.allFinite() && x.normal.allFinite() &&
                        std::isfinite(s.rate_at_start());
    if (!finite) std::abort();
    if (std::abs(x.gamma.norm() - 1.0) > kUnitTolerance ||
        std::abs(x.normal.norm() - 1.0) > kUnitTolerance ||
        std::abs(x.gamma.dot(x.normal)) > kUnitTolerance) {
      std::abort();
    }
    OrbitState d;
    if (const auto* c = std::get_if<CircularOrbit>(&s.orbit)) {
      d = rhs(CircularOrbitModel(s.body, *c), x);
    } else {
      const auto& e = std::get<EllipticOrbit>(s.orbit);
      d = rhs(EllipticOrbitModel(s.body, e), x, e.true_anomaly0);
    }
    if (!d.m.allFinite() || !d.gamma.allFinite() || !d.normal.allFinite()) std::abort();
  });
  return 0;
}
