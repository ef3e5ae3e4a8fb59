// Chaos indicators from the tangent map: MEGNO → 2 on quasi-periodic tori of the integrable cases
// and → 0 at stable permanent rotations, λ_max ~ ln t / t there; a chaotic orbit with λ_max > 0
// independent of the step and equal to the two-trajectory estimate, ⟨Y⟩ ≈ λ_max t/2; the spectrum
// in ± pairs with a zero total.

#include <gtest/gtest.h>

#include <cmath>

#include "newtop/phase/chaos_run.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_chaos {
namespace {

using test::kEps;

MethodSettings fixed(const std::string& name, double h) {
  MethodSettings m;
  m.name = name;
  m.step = h;
  return m;
}

template <Field F>
phase::ChaosSample indicators(const BasicModel<F>& model, const State& x0, double T,
                              const MethodSettings& m, bool spectrum = false) {
  return phase::chaos(model, x0, {.method = m, .t_end = T, .spectrum = spectrum}).indicators;
}

QuadraticModel euler_poinsot() {
  return {Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()), QuadraticField{}};
}
QuadraticModel lagrange_top() {
  return {Body::from_principal(Vec3(1.0, 1.0, 0.6), 1.0, Vec3(0.0, 0.0, 0.3)),
          QuadraticField::uniform(1.0)};
}

// On a quasi-periodic torus |δ| grows linearly, Y → 2 and ⟨Y⟩ = 2 + O(ln T/T): the transient of
// the first periods (measured |⟨Y⟩ − 2| = 0.015, 0.007 and 0.023 at T = 2000 for Brun,
// Euler–Poinsot and Lagrange) decays like ln T/T, 0.004 here, times the constant of that transient;
// 0.15 allows a constant of 40. A chaotic orbit's ⟨Y⟩ grows without bound, a periodic one's goes to
// 0.
TEST(Megno, TendsToTwoOnToriOfTheIntegrableCases) {
  const MethodSettings m = fixed("splitting6", 0.02);
  const QuadraticModel brun = test::brun_model();
  const State x = test::generic_state(brun);
  for (const QuadraticModel& model : {brun, euler_poinsot(), lagrange_top()}) {
    const State x0 = state_from_omega(model.body, Vec3(0.5, 1.1, -0.4), x.gamma);
    const phase::ChaosSample c = indicators(model, x0, 2000.0, m);
    EXPECT_NEAR(c.megno, 2.0, 0.15) << model.body.inertia().transpose();
  }
}

// λ_max of a regular orbit is a finite-time artefact, ln|δ|/t with |δ| ∝ t: it decays like
// ln t/t. From T = 200 to 2000 the ratio is (ln 2000/2000)/(ln 200/200) = 0.143; within a factor
// 2 (the constant of |δ| ∝ t also enters). A chaotic orbit keeps its λ (ratio near 1).
TEST(Megno, LyapunovDecaysLikeLogTOverTOnATorus) {
  const QuadraticModel model = test::brun_model();
  const State x0 = test::generic_state(model);
  const MethodSettings m = fixed("splitting6", 0.02);
  const double l1 = indicators(model, x0, 200.0, m).lyapunov_max;
  const double l2 = indicators(model, x0, 2000.0, m).lyapunov_max;
  const double expected = (std::log(2000.0) / 2000.0) / (std::log(200.0) / 200.0);
  EXPECT_GT(l2 / l1, expected / 2);
  EXPECT_LT(l2 / l1, expected * 2);
}

// A stable permanent rotation is a fixed point of the reduced motion whose linearisation is
// elliptic: tangent vectors stay bounded, Y → 0 and ⟨Y⟩ = O(1/T) (measured 3e-4 at T = 1000).
// Here the heavy body hanging below O (r0 along the largest axis, pointing down), at rest and
// spinning about that axis; 0.05 is far below the 2 of any torus.
TEST(Megno, TendsToZeroAtAStablePermanentRotation) {
  const QuadraticModel model{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0, 0, 0.4)),
                             QuadraticField::uniform(9.81)};
  for (double spin : {0.0, 1.0}) {
    const State x0{Vec3(0, 0, 2.2 * spin), -Vec3::UnitZ()};
    const phase::ChaosSample c = indicators(model, x0, 1000.0, fixed("splitting6", 0.01));
    EXPECT_LT(std::abs(c.megno), 0.05) << spin;
  }
}

// A generic heavy body (r0 off every axis, λ > 0): chaotic. λ_max above 2 ln T/T (twice what a
// regular orbit shows at T), the same with half the step (the orbit is the same one until
// rounding separates the runs, after ln(1/ε)/λ ≈ 400 > T: 1% of λ), equal to Benettin's
// two-trajectory estimate (d0 = 1e-8, renormalised every 10 steps: its nonlinearity is d0 e^{λτ},
// far below 1%), and ⟨Y⟩ ≈ λ T/2 (within 30%: Y grows like λ t only once the transient is
// forgotten).
TEST(Chaos, GenericHeavyBodyIsChaotic) {
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  const double T = 200.0;
  const phase::ChaosSample a = indicators(model, x0, T, fixed("splitting6", 0.02));
  const phase::ChaosSample b = indicators(model, x0, T, fixed("splitting6", 0.01));
  EXPECT_GT(a.lyapunov_max, 2 * std::log(T) / T);
  EXPECT_NEAR(a.lyapunov_max, b.lyapunov_max, 0.01 * a.lyapunov_max);
  const double two = phase::two_trajectory_lyapunov(fixed("splitting6", 0.02), model, x0, 0.0, T);
  EXPECT_NEAR(a.lyapunov_max, two, 0.01 * a.lyapunov_max);
  EXPECT_NEAR(a.megno, a.lyapunov_max * T / 2, 0.3 * a.lyapunov_max * T / 2);
  EXPECT_GE(a.fli, a.lyapunov_max * T * (1 - 1e-12));  // the max of ln|δ| includes its last value
  // The spin split of the free body (its own tangent map: the spin's derivative by the left
  // Jacobian of SO(3)) gives the same exponent and MEGNO (another map of the same flow).
  MethodSettings spin = fixed("splitting6", 0.02);
  spin.ordering = default_ordering(composition_table("splitting6"));
  spin.ordering->free_body = FreeBodySplit::spin;
  const phase::ChaosSample sp = indicators(model, x0, T, spin);
  EXPECT_NEAR(sp.lyapunov_max, a.lyapunov_max, 0.01 * a.lyapunov_max);
  EXPECT_NEAR(sp.megno, a.megno, 0.01 * a.megno);
  // The variational equations of RK4, of the adaptive pairs and of Taylor's method give the same
  // exponent (second methods).
  const phase::ChaosSample r = indicators(model, x0, T, fixed("rk4", 0.01));
  EXPECT_NEAR(r.lyapunov_max, a.lyapunov_max, 0.01 * a.lyapunov_max);
  for (const char* pair : {"rkf78", "dopri5", "dop853", "taylor"}) {
    MethodSettings m;
    m.name = pair;
    m.abs_tol = m.rel_tol = 1e-11;
    const phase::ChaosSample p = indicators(model, x0, T, m);
    EXPECT_NEAR(p.lyapunov_max, a.lyapunov_max, 0.01 * a.lyapunov_max) << pair;
    EXPECT_NEAR(p.megno, a.megno, 0.01 * a.megno) << pair;
  }
}

// The spectrum on 6 vectors: the splitting map is symplectic on each leaf (exponents in ± pairs,
// the two Casimir directions give zeros) and volume-preserving in R⁶ (det = 1 for every sub-flow:
// the total is rounding, 64 ε per log |R_ii| per step). The finite-time error of this run's
// exponents is measured by the two that are exactly zero in the limit: the pairs must cancel within
// 2 (|λ3| + |λ4|) (measured 9e-4, 7e-4, 3e-4 against 2.2e-3), and those two must be small beside
// λ_max (2%; measured 0.7%).
TEST(Chaos, SpectrumComesInPairsWithZeroTotal) {
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  const double T = 1000.0, h = 0.02;
  const std::int64_t n = fixed_step_count(0.0, T, h);
  const phase::ChaosResult r =
      phase::chaos(model, x0, {.method = fixed("splitting6", h), .t_end = T, .spectrum = true});
  const auto& sp = *r.indicators.spectrum;
  double total = 0;
  for (double v : sp) total += v;
  const double tol = 2 * (std::abs(sp[2]) + std::abs(sp[3]));
  EXPECT_GT(sp[0], 0.05);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(sp[i] + sp[5 - i], 0.0, tol) << i;
  EXPECT_LT(std::abs(sp[2]) + std::abs(sp[3]), 0.02 * sp[0]);
  EXPECT_NEAR(total, 0.0, 64 * kEps * 6 * static_cast<double>(n) / T);
  EXPECT_DOUBLE_EQ(sp[0], r.indicators.lyapunov_max);
}

// The history: at most history_rows samples of a fixed-step run, one every ⌈n / rows⌉ steps and
// the last; every step without a limit; the indicators' last sample is the result.
TEST(Chaos, HistorySamplesTheRun) {
  const QuadraticModel model = test::generic_model();
  std::vector<phase::ChaosSample> history;
  phase::ChaosRequest request{.method = fixed("splitting4", 0.1), .t_end = 10.0};
  request.history = [&](const phase::ChaosSample& s) { history.push_back(s); };
  request.history_rows = 3;  // 100 steps: every 34th, then the last
  const phase::ChaosResult r = phase::chaos(model, test::generic_state(model), request);
  ASSERT_EQ(history.size(), 3u);  // steps 34, 68 and the last (100)
  EXPECT_DOUBLE_EQ(history[0].t, 3.4);
  EXPECT_DOUBLE_EQ(history[1].t, 6.8);
  EXPECT_EQ(history.back().t, 10.0);
  EXPECT_EQ(history.back().megno, r.indicators.megno);
  history.clear();
  request.history_rows = 0;
  phase::chaos(model, test::generic_state(model), request);
  EXPECT_EQ(history.size(), 100u);
}

// The request is checked before any work, with the command line's words: a run of no length, a
// method without a tangent map, a negative history limit; the state on a Model.
TEST(Chaos, RequestIsCheckedBeforeAnyWork) {
  const Model model(test::generic_model());
  const State x0 = test::generic_state(test::generic_model());
  auto refusal = [&](const phase::ChaosRequest& r, const State& x) {
    try {
      phase::chaos(model, x, r);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const MethodSettings m = fixed("splitting6", 0.01);
  EXPECT_EQ(refusal({.method = m, .t0 = 2.0, .t_end = 2.0}, x0),
            "t_end: expected a time different from t0 = 2, found 2 (a run of no length)");
  EXPECT_EQ(refusal({.method = m, .t_end = 1.0, .history_rows = -1}, x0),
            "history_rows: expected a count >= 0, found -1");
  EXPECT_EQ(refusal({.method = fixed("splitting6", 0.0), .t_end = 1.0}, x0).rfind("step: ", 0), 0u);
  EXPECT_EQ(refusal({.t_end = 1.0}, x0).rfind("step: ", 0), 0u);  // no method given
  EXPECT_EQ(refusal({.method = m, .t_end = 1.0}, State{x0.m, 2.0 * x0.gamma}).rfind("gamma: ", 0),
            0u);
  EXPECT_EQ(refusal({.method = m, .t_end = 1.0}, x0), "accepted");
}

// The backward flow: without a gyrostat the equations are reversible, R(m, γ) = (−m, γ) maps the
// flow to its inverse, Φ_{−t}(x) = R Φ_t(R x), so the tangent map of the run from x0 over [0, −T]
// is R DΦ_T(R x0) R and its QR factors have the same |R_ii| as the forward run's from R x0 over
// [0, T]. The indicators of both runs agree up to round-off amplified by the flow: ε e^{λT} with
// λ T ≈ 0.15 · 60 = 9 here, ~2e-12 relative on the tangent vectors, well inside 1e-8. A backward
// run that reported zeros (the time it did not run) or the forward flow's exponents with the wrong
// sign fails by O(λ) ~ 0.1.
TEST(Chaos, BackwardRunGivesTheIndicatorsOfTheBackwardFlow) {
  constexpr double kSame = 1e-8;
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  const State rx0{-x0.m, x0.gamma};
  const double T = 60.0;
  const MethodSettings m = fixed("splitting6", 0.02);
  const phase::ChaosResult back =
      phase::chaos(model, x0, {.method = m, .t_end = -T, .spectrum = true});
  const phase::ChaosResult fwd =
      phase::chaos(model, rx0, {.method = m, .t_end = T, .spectrum = true});
  ASSERT_EQ(back.outcome.status, Status::finished);
  ASSERT_EQ(back.outcome.t, -T);
  const phase::ChaosSample& b = back.indicators;
  const phase::ChaosSample& f = fwd.indicators;
  ASSERT_TRUE(std::isfinite(b.lyapunov_max) && std::isfinite(b.megno) && std::isfinite(b.fli));
  EXPECT_GT(b.lyapunov_max, 0.02);  // a chaotic orbit: not the zeros of a run that did not happen
  EXPECT_NEAR(b.lyapunov_max, f.lyapunov_max, kSame);
  EXPECT_NEAR(b.megno, f.megno, kSame * std::max(1.0, std::abs(f.megno)));
  EXPECT_NEAR(b.fli, f.fli, kSame * std::max(1.0, std::abs(f.fli)));
  ASSERT_TRUE(b.spectrum && f.spectrum);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR((*b.spectrum)[i], (*f.spectrum)[i], kSame) << i;
}

}  // namespace
}  // namespace test_chaos
}  // namespace newtop
