#pragma once
// Shared by the ensemble tests: which SIMD paths this CPU runs, whether the scalar stepper may
// have been contracted into fused multiply-adds, and random starts of a body.

#include <random>
#include <vector>

#include "newtop/integrate/ensemble.hpp"

namespace newtop::test {

// The bit-identity guarantee needs a scalar stepper compiled without fused multiply-adds; a build
// for a CPU with FMA (e.g. -march=native) lets the compiler contract a·b + c in it, and the
// ensemble then agrees to round-off only.
#if defined(__FMA__)
inline constexpr bool kScalarMayContract = true;
#else
inline constexpr bool kScalarMayContract = false;
#endif

inline std::vector<SimdPath> available_paths() {
  std::vector<SimdPath> p;
  for (SimdPath s : {SimdPath::portable, SimdPath::avx2, SimdPath::avx512}) {
    if (simd_path_available(s)) p.push_back(s);
  }
  return p;
}

/// A random start of the body: ω in a box of half-width w_max, γ uniform on the sphere (drawn in
/// a fixed order, so that every compiler draws the same states).
inline State random_start(const Body& body, double w_max, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g;
  Vec3 w, n;
  for (int i = 0; i < 3; ++i) w[i] = w_max * u(rng);
  for (int i = 0; i < 3; ++i) n[i] = g(rng);
  return state_from_omega(body, w, n.normalized());
}

}  // namespace newtop::test
