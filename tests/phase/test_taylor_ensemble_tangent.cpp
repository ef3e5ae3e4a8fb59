// The chaos indicators of many starts through the Taylor ensemble's tangent runs
// (taylor_chaos_ensemble) against newtop chaos's scalar run of each point (phase::chaos with method
// taylor and one tangent vector): the same Outcome and the same MEGNO, λ_max and FLI,
// bit for bit, for batches of 1, 3, 8 and 17 points, a model per point, on every instruction set.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "newtop/phase/chaos.hpp"
#include "newtop/phase/chaos_ensemble.hpp"
#include "support/ensemble.hpp"

namespace newtop {
namespace test_taylor_ensemble_tangent {
namespace {

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(TaylorEnsembleTangent, IndicatorsAreChaosRunsBitsForEveryBatchSize) {
  if (test::kScalarMayContract)
    GTEST_SKIP() << "the scalar recurrences may use fused multiply-adds";
  constexpr double kTol = 1e-10, kT = 20.0;
  for (std::size_t n : {1, 3, 8, 17}) {
    const std::vector<QuadraticModel> models =
        test::random_models(n, true, static_cast<unsigned>(n));
    std::mt19937_64 rng(n + 1);
    std::vector<State> x;
    for (const QuadraticModel& m : models) x.push_back(test::random_start(m.body, 2.0, rng));
    for (SimdPath path : test::available_paths()) {
      const std::vector<phase::ChaosResult> got =
          phase::taylor_chaos_ensemble(models, x, 0.0, kT, kTol, kTol, {}, path);
      for (std::size_t i = 0; i < n; ++i) {
        const phase::ChaosResult ref =
            phase::chaos(Model(models[i]), x[i],
                         {.method = MethodSettings("taylor", 0.0, kTol, kTol), .t_end = kT});
        const std::string what = "n " + std::to_string(n) + ", " +
                                 std::string(simd_path_name(path)) + ", point " + std::to_string(i);
        ASSERT_EQ(got[i].outcome.status, ref.outcome.status) << what;
        EXPECT_EQ(got[i].outcome.steps, ref.outcome.steps) << what;
        EXPECT_TRUE(same_bits(got[i].outcome.state.m.x(), ref.outcome.state.m.x())) << what;
        EXPECT_TRUE(same_bits(got[i].outcome.state.gamma.z(), ref.outcome.state.gamma.z())) << what;
        EXPECT_TRUE(same_bits(got[i].indicators.megno, ref.indicators.megno))
            << what << ": " << got[i].indicators.megno << " vs " << ref.indicators.megno;
        EXPECT_TRUE(same_bits(got[i].indicators.lyapunov_max, ref.indicators.lyapunov_max)) << what;
        EXPECT_TRUE(same_bits(got[i].indicators.fli, ref.indicators.fli)) << what;
      }
    }
  }
}

}  // namespace
}  // namespace test_taylor_ensemble_tangent
}  // namespace newtop
