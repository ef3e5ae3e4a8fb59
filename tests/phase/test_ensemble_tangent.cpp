// The ensemble tangent stepper against TangentSplittingStepper (the state bit for bit, the tangent
// vectors to a derived round-off bound) and against itself under other groupings of the points.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "newtop/phase/ensemble_tangent.hpp"
#include "support/ensemble.hpp"
#include "support/problems.hpp"

namespace newtop::phase {
namespace test_ensemble_tangent {
namespace {

using test::kEps;

using test::available_paths;
using test::kScalarMayContract;

struct Points {
  std::vector<State> x;
  std::vector<Tangent> V;
};

// Random states of the generic gyrostat (ω in a box of half-width w_max, γ on the sphere) with
// `columns` random tangent vectors each.
Points random_points(const QuadraticModel& model, std::size_t n, double w_max, int columns,
                     unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points p;
  for (std::size_t i = 0; i < n; ++i) {
    p.x.push_back(test::random_start(model.body, w_max, rng));
    Tangent V(6, columns);
    for (int r = 0; r < 6; ++r) {
      for (int c = 0; c < columns; ++c) V(r, c) = u(rng);
    }
    p.V.push_back(V);
  }
  return p;
}

bool same_bits(const State& a, const State& b) {
  for (int i = 0; i < 3; ++i) {
    if (std::bit_cast<std::uint64_t>(a.m[i]) != std::bit_cast<std::uint64_t>(b.m[i]) ||
        std::bit_cast<std::uint64_t>(a.gamma[i]) != std::bit_cast<std::uint64_t>(b.gamma[i])) {
      return false;
    }
  }
  return true;
}

bool same_bits(const Tangent& a, const Tangent& b) {
  if (a.cols() != b.cols()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a(i)) != std::bit_cast<std::uint64_t>(b(i))) return false;
  }
  return true;
}

constexpr int kSteps = 40;

// The kick's increment t (∂L/∂γ) δγ is a sum of six products per component, rounded in two
// different orders by the two steppers: they differ by at most ~8 roundings of the largest term,
// 8 ε t |∂L/∂γ| |δγ| ≤ 8 ε |δx| (t |∂L/∂γ| < 1 at these steps). The tangent map carries each
// difference on linearly, growing it at most as it grows the tangent vectors (G, measured on the
// scalar run), so after N steps of K kicks the relative difference is below 8 ε N K G.
double tangent_bound(std::size_t kicks, double growth) {
  return 8 * kEps * kSteps * static_cast<double>(kicks) * std::max(growth, 1.0);
}

void expect_scalar_agreement(double h, double w_max) {
  if (kScalarMayContract) GTEST_SKIP() << "the scalar stepper may use fused multiply-adds here";
  const QuadraticModel model = test::generic_model(Vec3(0.1, -0.2, 0.05));
  for (const char* name : {"splitting2", "splitting4", "splitting6"}) {
    const CompositionTable& table = composition_table(name);
    for (bool outside : {false, true}) {
      SplitOrdering o = default_ordering(table);
      o.kick_outside = outside;
      o.axes = outside ? std::array<int, 3>{1, 0, 2} : std::array<int, 3>{2, 0, 1};
      const std::vector<double> b = splitting_coefficients(table, o).b;
      const auto kicks = static_cast<std::size_t>(
          std::count_if(b.begin(), b.end(), [](double x) { return x != 0.0; }));
      const Points p0 = random_points(model, 37, w_max, 6, 2024);
      Points ref = p0;
      double growth = 1.0;
      for (std::size_t i = 0; i < ref.x.size(); ++i) {
        TangentSplittingStepper s(table, o);
        for (int k = 0; k < kSteps; ++k) s.step(model, ref.x[i], ref.V[i], h);
        growth = std::max(growth, ref.V[i].norm() / p0.V[i].norm());
      }
      const double bound = tangent_bound(kicks, growth);
      for (SimdPath path : available_paths()) {
        const std::string what = std::string(name) +
                                 (outside ? " kick outside " : " kick inside ") +
                                 std::string(simd_path_name(path));
        EnsembleTangentStepper e(table, o, path);
        EnsembleState x(p0.x);
        std::vector<Tangent> V = p0.V;
        e.advance(model, x, V, h, kSteps);
        double worst = 0;
        for (std::size_t i = 0; i < p0.x.size(); ++i) {
          ASSERT_TRUE(same_bits(x[i], ref.x[i])) << what << " point " << i;
          worst = std::max(
              worst, (V[i] - ref.V[i]).cwiseAbs().maxCoeff() / ref.V[i].cwiseAbs().maxCoeff());
        }
        EXPECT_LT(worst, bound) << what;
        EXPECT_GT(worst, 0.0) << what << ": the kick's rounding differs; equal bits are unexpected";
      }
    }
  }
}

TEST(EnsembleTangent, StateBitIdenticalTangentToRoundOffShortSeries) {
  expect_scalar_agreement(0.01, 2.0);
}

TEST(EnsembleTangent, StateBitIdenticalTangentToRoundOffWhereLanesLeaveTheSeries) {
  expect_scalar_agreement(0.1, 3.0);  // rotation angles up to ~0.6
}

// With one tangent vector (MEGNO, λ_max) the scalar kick forms (∂L/∂γ) δγ without the matrix
// (moment_derivative: δγ × ∂V/∂γ + γ × λIδγ), the same products and sums as the ensemble's kick in
// another order of commutative operations: the tangent vector is bit-identical too (the sweep's
// MEGNO maps rely on it).
TEST(EnsembleTangent, OneTangentVectorBitIdentical) {
  if (kScalarMayContract) GTEST_SKIP() << "the scalar stepper may use fused multiply-adds here";
  const QuadraticModel model = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const Points p0 = random_points(model, 37, 3.0, 1, 77);
  for (const char* name : {"splitting2", "splitting4", "splitting6", "splitting8"}) {
    const CompositionTable& table = composition_table(name);
    for (bool outside : {false, true}) {
      SplitOrdering o = default_ordering(table);
      o.kick_outside = outside;
      Points ref = p0;
      for (std::size_t i = 0; i < ref.x.size(); ++i) {
        TangentSplittingStepper s(table, o);
        for (int k = 0; k < kSteps; ++k) s.step(model, ref.x[i], ref.V[i], 0.1);
      }
      for (SimdPath path : available_paths()) {
        EnsembleTangentStepper e(table, o, path);
        EnsembleState x(p0.x);
        std::vector<Tangent> V = p0.V;
        e.advance(model, x, V, 0.1, kSteps);
        for (std::size_t i = 0; i < p0.x.size(); ++i) {
          ASSERT_TRUE(same_bits(x[i], ref.x[i]) && same_bits(V[i], ref.V[i]))
              << name << (outside ? " kick outside " : " kick inside ") << simd_path_name(path)
              << " point " << i;
        }
      }
    }
  }
}

// A model per point (random bodies and fields, the axes in every order of size): each point with
// one tangent vector bit-identical to TangentSplittingStepper on its own model, on every path;
// the same points reversed give the same bits.
TEST(EnsembleTangent, ModelPerLaneBitIdenticalWithOneVector) {
  if (kScalarMayContract) GTEST_SKIP() << "the scalar stepper may use fused multiply-adds here";
  const std::vector<QuadraticModel> models = test::random_models(41, true, 321);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points p0;
  for (const QuadraticModel& m : models) {
    p0.x.push_back(test::random_start(m.body, 3.0, rng));
    Tangent V(6, 1);
    for (int r = 0; r < 6; ++r) V(r, 0) = u(rng);
    p0.V.push_back(V);
  }
  for (const char* name : {"splitting2", "splitting6"}) {
    const CompositionTable& table = composition_table(name);
    const SplitOrdering o = default_ordering(table);
    Points ref = p0;
    for (std::size_t i = 0; i < ref.x.size(); ++i) {
      TangentSplittingStepper s(table, o);
      for (int k = 0; k < kSteps; ++k) s.step(models[i], ref.x[i], ref.V[i], 0.1);
    }
    const EnsembleModels lanes(models, o);
    ASSERT_GT(lanes.groups(), 1u) << "the models should span several orders of the axes";
    for (SimdPath path : available_paths()) {
      EnsembleTangentStepper e(table, o, path);
      EnsembleState x(p0.x);
      std::vector<Tangent> V = p0.V;
      e.advance(lanes, x, V, 0.1, kSteps);
      for (std::size_t i = 0; i < p0.x.size(); ++i) {
        ASSERT_TRUE(same_bits(x[i], ref.x[i]) && same_bits(V[i], ref.V[i]))
            << name << " " << simd_path_name(path) << " point " << i;
      }
      std::vector<QuadraticModel> rm(models.rbegin(), models.rend());
      std::vector<State> rx(p0.x.rbegin(), p0.x.rend());
      std::vector<Tangent> rv(p0.V.rbegin(), p0.V.rend());
      EnsembleState xr(rx);
      e.advance(EnsembleModels(rm, o), xr, rv, 0.1, kSteps);
      for (std::size_t i = 0; i < p0.x.size(); ++i) {
        const std::size_t k = p0.x.size() - 1 - i;
        ASSERT_TRUE(same_bits(xr[k], ref.x[i]) && same_bits(rv[k], ref.V[i]))
            << name << " " << simd_path_name(path) << " reversed " << i;
      }
    }
  }
}

TEST(EnsembleTangent, IndependentOfLanesAndGrouping) {
  const QuadraticModel model = test::generic_model(Vec3(0.1, -0.2, 0.05));
  const Points p0 = random_points(model, 23, 2.5, 2, 5);
  const CompositionTable& table = composition_table("splitting4");
  EnsembleTangentStepper base(table, default_ordering(table), SimdPath::portable);
  EnsembleState ref(p0.x);
  std::vector<Tangent> refV = p0.V;
  base.advance(model, ref, refV, 0.05, 20);
  for (SimdPath path : available_paths()) {
    EnsembleTangentStepper e(table, default_ordering(table), path);
    for (std::size_t first : {std::size_t(0), std::size_t(3)}) {
      for (std::size_t n : {std::size_t(1), std::size_t(5), std::size_t(9), std::size_t(17)}) {
        ASSERT_LE(first + n, p0.x.size());
        EnsembleState x;
        std::vector<Tangent> V;
        for (std::size_t k = first + n; k-- > first;) {  // reversed
          x.push_back(p0.x[k]);
          V.push_back(p0.V[k]);
        }
        e.advance(model, x, V, 0.05, 20);
        for (std::size_t k = 0; k < n; ++k) {
          const std::size_t i = first + n - 1 - k;
          ASSERT_TRUE(same_bits(x[k], ref[i]) && same_bits(V[k], refV[i]))
              << simd_path_name(path) << " size " << n << " from " << first << " point " << i;
        }
      }
    }
  }
}

TEST(EnsembleTangent, RefusesTheSpinSplitAndMismatchedTangents) {
  const CompositionTable& table = composition_table("splitting2");
  SplitOrdering spin = default_ordering(table);
  spin.free_body = FreeBodySplit::spin;
  EXPECT_THROW(EnsembleTangentStepper(table, spin), InputError);
  EnsembleTangentStepper e(table, default_ordering(table));
  const QuadraticModel model = test::generic_model();
  EnsembleState x(std::vector<State>(2, test::generic_state(model)));
  std::vector<Tangent> V{Tangent::Identity(6, 6), Tangent::Identity(6, 3)};
  EXPECT_THROW(e.advance(model, x, V, 0.01, 1), InputError);
  V.pop_back();
  EXPECT_THROW(e.advance(model, x, V, 0.01, 1), InputError);
}

}  // namespace
}  // namespace test_ensemble_tangent
}  // namespace newtop::phase
