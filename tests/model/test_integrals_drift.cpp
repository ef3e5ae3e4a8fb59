// The one observer of the integrals' drift (IntegralsDrift, docs/model.md §5): max |I − I(x0)| of
// each integral against values worked out by hand, the merge of two runs, and the drift of a
// splitting run of Euler–Poinsot bounded by the Casimirs' round-off.

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/integrate/run.hpp"
#include "newtop/model/integrals.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_integrals_drift {
namespace {

using test::kEps;

// The hand-worked values below are sums and products of small binary fractions: exact.
constexpr double kExact = 0.0;

/// A sleeping-top body on the axis γ = e1 (no field): area = m1, energy = m1²/(2A).
QuadraticModel free_body() {
  return QuadraticModel{Body::from_principal(Vec3(2.0, 3.0, 4.0), 1.0, Vec3::Zero()),
                        QuadraticField::coulomb(0.0, 0.0)};
}

State along_e1(double m1) { return State{Vec3(m1, 0, 0), Vec3(1, 0, 0)}; }

TEST(IntegralsDrift, LargestDepartureFromTheFirstStateOfEachIntegral) {
  const Model model(free_body());
  IntegralsDrift d;
  for (const double m1 : {1.0, 2.0, 0.5, 1.5}) d.observe(model, along_e1(m1));
  ASSERT_TRUE(d.started);
  // area m1 − 1: max |2 − 1| = 1; energy m1²/4: max |4/4 − 1/4| = 3/4; |m| at most 2; γ unchanged.
  EXPECT_NEAR(d.max_drift.area, 1.0, kExact);
  EXPECT_NEAR(d.max_drift.energy, 0.75, kExact);
  EXPECT_NEAR(d.max_drift.geometric, 0.0, kExact);
  EXPECT_NEAR(d.max_m, 2.0, kExact);
  EXPECT_NEAR(d.initial.area, 1.0, kExact);
  // Brun's integral holds (r0 = 0, k = 0): |Iω|² = m1², max |4 − 1| = 3.
  ASSERT_TRUE(d.max_drift.brun.has_value());
  EXPECT_NEAR(*d.max_drift.brun, 3.0, kExact);
}

TEST(IntegralsDrift, MergeTakesTheLargerDriftOfEachRunAgainstItsOwnStart) {
  const Model model(free_body());
  IntegralsDrift a, b, none;
  a.observe(model, along_e1(1.0));
  a.observe(model, along_e1(1.25));  // area drift 1/4
  b.observe(model, along_e1(3.0));
  b.observe(model, along_e1(2.5));  // area drift 1/2, against 3 (not against a's start 1)
  a.merge(b);
  a.merge(none);  // a run that observed nothing changes nothing
  EXPECT_NEAR(a.max_drift.area, 0.5, kExact);
  EXPECT_NEAR(a.max_m, 3.0, kExact);
  none.merge(a);
  EXPECT_TRUE(none.started);
  EXPECT_NEAR(none.max_drift.area, 0.5, kExact);
}

TEST(IntegralsDrift, CasimirDriftIsRelativeToGammaGammaAndToTheLargestM) {
  const Model model(free_body());
  IntegralsDrift d;
  d.observe(model, along_e1(1.0));
  d.observe(model, along_e1(2.0));  // area drift 1 against max |m| = 2
  State off = along_e1(2.0);
  off.gamma = Vec3(1.0, 0.5, 0.0);  // γ·γ = 5/4: geometric drift 1/4 of γ0·γ0 = 1
  d.observe(IntegralValues{0.0, area(off), geometric(off), std::nullopt, std::nullopt});
  const CasimirDrift c = casimir_drift(d);
  EXPECT_NEAR(c.geometric, 0.25, kExact);
  EXPECT_NEAR(c.area, 0.5, kExact);
  EXPECT_TRUE(c.exceeded());
  EXPECT_FALSE((CasimirDrift{1e-9, 1e-9}.exceeded()));
  EXPECT_TRUE((CasimirDrift{std::nan(""), 0.0}.exceeded()));  // a NaN drift is never a pass
}

TEST(IntegralsDrift, SplittingRunKeepsTheCasimirsToRoundOff) {
  const QuadraticModel q = test::generic_model();
  const Model model(q);
  IntegralsDrift d;
  const State x0 = test::generic_state(q);
  d.observe(model, x0);
  const std::int64_t steps = 1000;
  MethodSettings method("splitting4", 0.01);
  run_method(method, model, x0, 0.0, steps * 0.01, IntegrateOptions{},
             [&](double, const State& x) { d.observe(model, x); });
  // γ·γ: each step's rotations change |γ|² by a few ε; a random walk over the run.
  const double casimir_bound = 64 * kEps * std::sqrt(static_cast<double>(steps));
  EXPECT_GT(d.max_m, 0.0);
  EXPECT_LT(d.max_drift.geometric, casimir_bound);
  EXPECT_LT(d.max_drift.area, casimir_bound * d.max_m);
  EXPECT_GT(d.max_drift.energy, 0.0);  // a splitting method's energy oscillates at O(h⁴)
}

}  // namespace
}  // namespace test_integrals_drift
}  // namespace newtop
