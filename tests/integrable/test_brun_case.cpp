// Brun's case on the level f = 0 solved by quadratures: the Abel–Jacobi sums along an independent
// numerical trajectory (rkf78 at 1e-14) are t and 0; the inverted solution matches that trajectory
// over several quasi-periods in three regimes; the torus frequencies from the period matrix match
// the mean angular rates measured on the trajectory; λ → 0 gives the Euler–Poinsot motion.

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "newtop/analysis/brun_case.hpp"
#include "newtop/analysis/euler_poinsot.hpp"
#include "newtop/integrate/methods.hpp"

namespace newtop {
namespace test_brun_case {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kReferenceTol = 1e-14;
// rkf78 at 1e-14 has a global error ~1e-12 over the spans below; the quadratures are good to a
// few ulps per period: the 1e-10 for the Abel sums and 1e-9 for the states leave margin.
constexpr double kAbelAgreement = 1e-10;
constexpr double kStateAgreement = 1e-9;
// Weighted Birkhoff average of dφ/dt over 400 slow turns (bump window, super-polynomial
// convergence once the window spans many periods of the slowest beat p ω1 − q ω2; the tori below
// have beats down to ~100 time units, ≲ 1/10 of the window): 1e-8 relative.
constexpr double kFrequencyAgreement = 1e-8;

struct Regime {
  const char* name;
  Vec3 inertia;
  double lambda;
  Vec3 m, gamma;  // m is projected on the plane normal to γ (the level f = 0)
};

QuadraticModel model_of(const Regime& r) {
  return {Body::from_principal(r.inertia, 1.0, Vec3::Zero()),
          QuadraticField::coulomb(0.0, r.lambda)};
}

State state_of(const Regime& r) {
  const Vec3 g = r.gamma.normalized();
  return {r.m - r.m.dot(g) * g, g};
}

/// Angles of the numerical motion, unwrapped by continuity (steps well below a period).
struct Track {
  std::vector<double> t;
  std::vector<std::array<double, 2>> phi;
  std::vector<State> x;
};

Track track(const QuadraticModel& model, const BrunCase& b, const State& x0, double t_end, int n) {
  Track tr;
  State x = x0;
  std::array<double, 2> prev = b.initial.phi;
  for (int i = 0; i <= n; ++i) {
    const double t = t_end * i / n;
    if (i > 0) {
      Fehlberg78Stepper s(kReferenceTol, kReferenceTol);
      x = integrate(s, model, x, tr.t.back(), t, {}).state;
    }
    const BrunAngles a = brun_angles(b.curve, x);
    std::array<double, 2> phi{};
    for (int s = 0; s < 2; ++s) {
      const double guess = prev[s] + b.frequency[s] * (i > 0 ? t - tr.t.back() : 0.0);
      phi[s] = a.phi[s] + kTwoPi * std::round((guess - a.phi[s]) / kTwoPi);
    }
    prev = phi;
    tr.t.push_back(t), tr.phi.push_back(phi), tr.x.push_back(x);
  }
  return tr;
}

/// Mean rate of φ_s: ∫ w(t/T) φ̇ dt / ∫ w(t/T) dt = −∫ w′(t/T) φ dt / (T ∫ w(t/T) dt), with the
/// bump w(τ) = exp(−1/(τ(1 − τ))) (trapezoidal rule: the integrands vanish to all orders at the
/// ends).
double birkhoff_rate(const Track& tr, int s) {
  const double T = tr.t.back();
  double num = 0, den = 0;
  for (std::size_t i = 1; i + 1 < tr.t.size(); ++i) {
    const double tau = tr.t[i] / T, q = tau * (1 - tau);
    const double w = std::exp(-1 / q), dw = w * (1 - 2 * tau) / (q * q);
    num -= dw * tr.phi[i][s] / T;
    den += w;
  }
  return num / den;
}

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

class BrunRegimes : public ::testing::TestWithParam<Regime> {};

TEST_P(BrunRegimes, AbelSumsStatesAndFrequenciesMatchTheNumericalMotion) {
  const Regime& r = GetParam();
  const QuadraticModel model = model_of(r);
  const State x0 = state_of(r);
  const BrunCase b = brun_case(model, x0);
  ASSERT_GT(b.frequency[0], 0.0);
  ASSERT_GT(b.frequency[1], 0.0);
  const double slow = kTwoPi / std::min(b.frequency[0], b.frequency[1]);
  const double fast = kTwoPi / std::max(b.frequency[0], b.frequency[1]);
  // Several quasi-periods; samples 40 per fast turn for the unwrapping.
  const double t_end = 4 * slow;
  const Track tr = track(model, b, x0, t_end, static_cast<int>(40 * t_end / fast));
  const double scale = std::max(1.0, x0.m.norm());
  double abel_err = 0, state_err = 0;
  for (std::size_t i = 0; i < tr.t.size(); i += 7) {
    const auto sums = brun_abel_sums(b, tr.phi[i]);
    abel_err = std::max({abel_err, std::abs(sums[0] - tr.t[i]), std::abs(sums[1]) * scale});
    const State a = brun_state(b, tr.t[i]);
    ASSERT_TRUE(a.m.allFinite() && a.gamma.allFinite());
    state_err = std::max({state_err, (a.m - tr.x[i].m).cwiseAbs().maxCoeff() / scale,
                          (a.gamma - tr.x[i].gamma).cwiseAbs().maxCoeff()});
  }
  EXPECT_LT(abel_err, kAbelAgreement) << r.name;
  EXPECT_LT(state_err, kStateAgreement) << r.name;
  RecordProperty("abel_error", sci(abel_err));
  RecordProperty("state_error", sci(state_err));

  // Frequencies: a longer run, 400 slow turns, 60 samples per fast turn (the passages near the
  // separatrix are sharp; 20 per turn left 1e-8 of trapezoidal error there).
  const Track longer = track(model, b, x0, 400 * slow, static_cast<int>(60 * 400 * slow / fast));
  for (int s = 0; s < 2; ++s) {
    const double measured = birkhoff_rate(longer, s);
    EXPECT_NEAR(measured, b.frequency[s], kFrequencyAgreement * b.frequency[s]) << r.name << s;
    RecordProperty("frequency_error_" + std::to_string(s),
                   sci(std::abs(measured / b.frequency[s] - 1)));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Levels, BrunRegimes,
    ::testing::Values(
        // λ > 0, γ near the least axis (the stable equilibrium): u1 and u2 both turn at roots
        // of N, both librate.
        Regime{"libration", {1.0, 1.6, 2.3}, 3.0, {0.05, 0.3, -0.25}, {0.95, 0.25, 0.2}},
        // Small λ, m near the separatrix of the free body (2hB ≈ |m|²): a root of N within
        // 1.1e-3 of e2 (u2 turns at ν, just above e2).
        Regime{"near_separatrix", {1.0, 1.5, 2.2}, 0.01, {0.8, 0.9, 0.9255}, {0.6, -0.7, 0.39}},
        // Brun's own field, λ = −N < 0.
        Regime{"negative_lambda", {1.0, 1.5, 2.2}, -0.8, {0.5, 1.65, -0.88}, {0.48, -0.6, 0.64}}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(BrunCase, ReproducesEulerPoinsotAsLambdaVanishes) {
  // The difference from the free body is first order in λ: dividing λ by ten divides it by ten
  // (to 20 %). Its size: the torque λ γ × Iγ, |.| ≤ λ(C − A)/2, moves m by ≤ λ(C − A)t/2 and γ,
  // turning at |ω|, by that times |ω|t/|m|: at λ = 1e-6 it stays below 1e-6 (C − A) t (1 + |ω|t).
  const Vec3 I(1.0, 2.0, 3.0);
  const Vec3 g = Vec3(0.0, 0.6, 0.8);
  const Vec3 m0 = I.cwiseProduct(Vec3(0.3, 0.4, 1.1));
  const State x0{m0 - m0.dot(g) * g, g};
  const QuadraticModel free{Body::from_principal(I, 1.0, Vec3::Zero()),
                            QuadraticField::coulomb(0, 0)};
  const EulerPoinsot ep = euler_poinsot(free.body, x0);
  auto distance = [&](double lambda) {
    const QuadraticModel model{free.body, QuadraticField::coulomb(0.0, lambda)};
    const BrunCase b = brun_case(model, x0);
    double d = 0;
    for (int i = 1; i <= 10; ++i) {
      const double t = 0.2 * i * ep.period;
      const State a = brun_state(b, t), e = free_body_state(ep, t);
      d = std::max(
          {d, (a.m - e.m).cwiseAbs().maxCoeff(), (a.gamma - e.gamma).cwiseAbs().maxCoeff()});
    }
    return d;
  };
  const double d4 = distance(1e-4), d5 = distance(1e-5), d6 = distance(1e-6);
  EXPECT_NEAR(d4 / d5, 10.0, 2.0);
  EXPECT_NEAR(d5 / d6, 10.0, 2.0);
  const double t_max = 2 * ep.period, w = (x0.m.cwiseQuotient(I)).norm();
  EXPECT_LT(d6, 1e-6 * (I.z() - I.x()) * t_max * (1 + w * t_max));
}

}  // namespace
}  // namespace test_brun_case
// Beyond 2^53 a phase has no digit of its angle left: the inversion refuses the time in one line
// naming `times` (an input error, before any work) instead of failing inside a bracket.
TEST(BrunCase, RefusesTimesBeyondDoublePrecisionOfThePhase) {
  const Vec3 I(1.0, 1.5, 2.2);
  const QuadraticModel model{Body::from_principal(I, 1.0, Vec3::Zero()),
                             QuadraticField::coulomb(0.0, 0.3)};
  const Vec3 g = Vec3(0.0, 0.6, 0.8);
  const Vec3 m0 = I.cwiseProduct(Vec3(0.3, 0.4, 1.1));
  const BrunCase b = brun_case(model, State{m0 - m0.dot(g) * g, g});  // on the level f = 0
  EXPECT_NO_THROW(brun_state(b, 1e6));
  try {
    brun_state(b, 1e17);
    ADD_FAILURE() << "t = 1e17 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("times: expected", 0), 0u) << e.what();
  }
  EXPECT_THROW(brun_check_time(b, std::nan("")), InputError);
}

}  // namespace newtop
