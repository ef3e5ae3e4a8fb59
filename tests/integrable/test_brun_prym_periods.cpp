// Brun's case on f ≠ 0: the torus frequencies from the periods of the Prym differentials. The two
// basis periods of the torus close the flows of H and of Brun's integral (integrated here, over
// the doubled period as well as the one the library tested), and the strongest lines of the
// spectrum of γ1(t) on a numerical run are integer combinations of the frequencies.

// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <gtest/gtest.h>

#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <complex>
#include <ostream>
#include <vector>

#include "newtop/analysis/brun_level.hpp"
#include "newtop/analysis/brun_prym.hpp"
#include "newtop/analysis/brun_prym_periods.hpp"
#include "newtop/integrate/methods.hpp"

namespace newtop {
namespace test_brun_prym_periods {
namespace {

// A period of the torus returns the state to the flows' global error (rkf78 at 1e-13 over ≲ 30
// time units: ~1e-11); a non-period misses by O(1).
constexpr double kFlowTol = 1e-13;
constexpr double kReturn = 1e-9;
// The spectrum: γ1 sampled every 0.05 over T = 1500 with the C^∞ bump window (lines located to
// ~1e-9 once separated by ≫ 1/T), the peaks refined by golden section to 1e-11; a line is an
// integer combination n1 ω1 + n2 ω2, |n_i| ≤ 40, to 1e-6 (a random number: probability ~1e-4).
constexpr double kSampleStep = 0.05;
constexpr double kSpan = 1500.0;
constexpr double kLine = 1e-6;
constexpr int kMaxOrder = 40;

struct Level {
  const char* name;
  double lambda, f;
};

void PrintTo(const Level& l, std::ostream* os) { *os << l.name; }

QuadraticModel model_of(double lambda) {
  return {Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
          QuadraticField::coulomb(0.0, lambda)};
}

/// The start of examples/analytic_brun.toml moved to the level f (m → m + fγ).
State start(double f) {
  const Vec3 g(0.48, -0.6, 0.64);
  return {Vec3(0.5, 1.2, 0.75) + f * g.normalized(), g.normalized()};
}

double return_error(const QuadraticModel& model, const BrunCurve& k, const State& x0, double tau_h,
                    double tau_c) {
  Fehlberg78Stepper stepper(kFlowTol, kFlowTol);
  const State x = integrate(stepper, model, x0, 0.0, tau_h, {}).state;
  using Y = std::array<double, 6>;
  Y y{x.m[0], x.m[1], x.m[2], x.gamma[0], x.gamma[1], x.gamma[2]};
  const double sign = tau_c >= 0 ? 1.0 : -1.0;
  auto field = [&](const Y& a, Y& d, double) {
    const State r = brun_c_flow(k, State{Vec3(a[0], a[1], a[2]), Vec3(a[3], a[4], a[5])});
    for (int i = 0; i < 3; ++i) d[i] = sign * r.m[i], d[3 + i] = sign * r.gamma[i];
  };
  namespace ode = boost::numeric::odeint;
  ode::integrate_adaptive(ode::make_controlled<ode::runge_kutta_fehlberg78<Y>>(kFlowTol, kFlowTol),
                          field, y, 0.0, std::abs(tau_c), 1e-3);
  double err = 0;
  for (int i = 0; i < 3; ++i) {
    err = std::max({err, std::abs(y[i] - x0.m[i]), std::abs(y[3 + i] - x0.gamma[i])});
  }
  return err;
}

/// |Σ w(t/T) γ1(t) e^{−iνt}| / Σ w over the samples.
double amplitude(const std::vector<double>& s, double nu) {
  std::complex<double> a = 0;
  double norm = 0;
  const double n = static_cast<double>(s.size() - 1);
  for (std::size_t i = 1; i + 1 < s.size(); ++i) {
    const double tau = static_cast<double>(i) / n, w = std::exp(-1 / (tau * (1 - tau)));
    a += w * s[i] * std::exp(std::complex<double>(0, -nu * static_cast<double>(i) * kSampleStep));
    norm += w;
  }
  return std::abs(a) / norm;
}

/// The strongest lines in (0.05, 3]: grid maxima 0.03 apart, refined by golden section.
std::vector<double> lines(const std::vector<double>& s, int count) {
  std::vector<std::pair<double, double>> grid;
  for (double nu = 0.05; nu <= 3.0; nu += 0.002) grid.emplace_back(amplitude(s, nu), nu);
  std::sort(grid.rbegin(), grid.rend());
  std::vector<double> out;
  for (const auto& entry : grid) {
    const double nu = entry.second;
    if (static_cast<int>(out.size()) == count) break;
    if (std::any_of(out.begin(), out.end(), [&](double x) { return std::abs(x - nu) < 0.03; }))
      continue;
    double lo = nu - 0.002, hi = nu + 0.002;
    const double r = (std::sqrt(5.0) - 1) / 2;
    while (hi - lo > 1e-11) {
      const double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
      (amplitude(s, x1) > amplitude(s, x2) ? hi : lo) =
          amplitude(s, x1) > amplitude(s, x2) ? x2 : x1;
    }
    out.push_back(0.5 * (lo + hi));
  }
  return out;
}

class BrunPrymPeriods : public ::testing::TestWithParam<Level> {};

TEST_P(BrunPrymPeriods, TorusPeriodsCloseTheFlowsAndTheSpectrumIsInTheFrequencyModule) {
  const Level& l = GetParam();
  const QuadraticModel model = model_of(l.lambda);
  const State x0 = start(l.f);
  const BrunCurve k = brun_level(model, x0);
  const BrunPrymFrequencies fr = brun_prym_frequencies(model, x0);
  for (int c = 0; c < 2; ++c) {
    EXPECT_LT(return_error(model, k, x0, fr.torus_period[c][0], fr.torus_period[c][1]), kReturn)
        << l.name << " cycle " << c;
  }
  std::vector<double> s;
  State x = x0;
  for (int i = 0; i * kSampleStep <= kSpan; ++i) {
    s.push_back(x.gamma[0]);
    Fehlberg78Stepper st(1e-12, 1e-12);
    x = integrate(st, model, x, i * kSampleStep, (i + 1) * kSampleStep, {}).state;
  }
  for (double nu : lines(s, 3)) {
    double best = 1e300;
    for (int n1 = -kMaxOrder; n1 <= kMaxOrder; ++n1) {
      const double rest = nu - n1 * fr.frequency[0];
      const double n2 = std::round(rest / fr.frequency[1]);
      if (std::abs(n2) <= kMaxOrder) best = std::min(best, std::abs(rest - n2 * fr.frequency[1]));
    }
    EXPECT_LT(best, kLine) << l.name << ": line " << nu;
  }
}

INSTANTIATE_TEST_SUITE_P(Levels, BrunPrymPeriods,
                         ::testing::Values(Level{"lambda_negative", -0.8, 0.3},
                                           Level{"lambda_positive", 0.8, 0.6},
                                           Level{"large_area", 1.5, 1.0}),
                         [](const auto& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace test_brun_prym_periods
}  // namespace newtop
