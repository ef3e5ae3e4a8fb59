#pragma once
// Shared by the ensemble tests: which SIMD paths this CPU runs, whether the scalar stepper may
// have been contracted into fused multiply-adds, random starts of a body, and random models.

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

// Random models of the quadratic field: moments in [0.5, 2.5] satisfying the triangle
// inequalities (one in four with two moments equal: a tie in the sort by moment), any mass, r0,
// field (g, λ) of either sign, and a gyrostatic moment whose components are zero or not at random
// (so the spin split's reference axis has k ≠ 0 in some models and k = 0 in others). `gyrostat`
// false: k = 0 (the near-integrable tables need it).
inline std::vector<QuadraticModel> random_models(std::size_t n, bool gyrostat, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<QuadraticModel> models;
  while (models.size() < n) {
    Vec3 I, r0, k = Vec3::Zero();
    for (int i = 0; i < 3; ++i) I[i] = 0.5 + 2.0 * u(rng);
    if (u(rng) < 0.25) I[1] = I[0];
    if (I[0] + I[1] < I[2] || I[1] + I[2] < I[0] || I[0] + I[2] < I[1]) continue;
    for (int i = 0; i < 3; ++i) r0[i] = u(rng) - 0.5;
    for (int i = 0; i < 3; ++i) {
      const double v = 0.6 * u(rng) - 0.3;
      if (gyrostat && u(rng) < 0.5) k[i] = v;
    }
    const double mass = 0.5 + 1.5 * u(rng);
    const double g = 4.0 * u(rng) - 2.0;
    const double lambda = 2.0 * u(rng) - 1.0;
    models.push_back({Body::from_principal(I, mass, r0, k), QuadraticField::coulomb(g, lambda)});
  }
  return models;
}

}  // namespace newtop::test
