// The orbit's Taylor ensemble (newtop/orbit/orbit_taylor_ensemble.hpp) against its guarantee: each
// trajectory's outcome and observed steps are those of the adaptive driver running
// OrbitTaylorStepper on it alone, bit for bit, on every instruction set, for any batch size, on
// circles and ellipses, a model per lane or one for all, forwards and backwards, and where runs end
// early (the step limit); the chaos runs against orbit_chaos's; bad input refused before any work.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "newtop/orbit/orbit_chaos.hpp"
#include "newtop/orbit/orbit_taylor.hpp"
#include "newtop/orbit/orbit_taylor_ensemble.hpp"
#include "orbit_problems.hpp"
#include "support/ensemble.hpp"

namespace newtop {
namespace test_orbit_taylor_ensemble {
namespace {

struct Seen {
  std::size_t point;
  double t;
  OrbitState x;
  bool operator==(const Seen&) const = default;
};

// Bodies of their own (a sweep over the body) and tumbling starts of their own.
std::vector<Body> bodies(std::size_t n) {
  std::vector<Body> b;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 0.05 * static_cast<double>(i);
    b.push_back(Body::from_principal(Vec3(1.0 + s, 1.6, 2.1 - s), 1.0, Vec3::Zero(),
                                     Vec3(0.1, -0.2 + s, 0.3)));
  }
  return b;
}

std::vector<OrbitState> starts(const std::vector<Body>& b) {
  std::vector<OrbitState> x;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double s = 0.1 * static_cast<double>(i);
    x.push_back(test::tumbling_state(b[i], Vec3(0.3 - s, -0.5, 0.9 + 0.5 * s)));
  }
  return x;
}

template <class M>
void expect_scalar_bits(const OrbitTaylorEnsemble& proto, const std::vector<M>& models,
                        const std::vector<OrbitState>& x, double a, double b,
                        const IntegrateOptions& opt, double tol) {
  for (SimdPath path : test::available_paths()) {
    OrbitTaylorEnsemble e(tol, tol, path, proto.order());
    std::vector<Seen> seen;
    const std::vector<OrbitOutcome> out =
        e.integrate(models, x, a, b, opt, [&](std::size_t p, double t, const OrbitState& y) {
          seen.push_back({p, t, y});
        });
    ASSERT_EQ(out.size(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const std::string where =
          std::string(simd_path_name(path)) + ", trajectory " + std::to_string(i);
      OrbitTaylorStepper s(tol, tol, proto.order());
      std::vector<Seen> mine;
      const M& model = models.size() == 1 ? models[0] : models[i];
      const OrbitOutcome r =
          integrate(s, model, x[i], a, b, opt, [&](double t, const OrbitState& y) {
            mine.push_back({i, t, y});
          });
      std::vector<Seen> theirs;
      for (const Seen& q : seen) {
        if (q.point == i) theirs.push_back(q);
      }
      EXPECT_EQ(out[i].status, r.status) << where;
      EXPECT_EQ(out[i].t, r.t) << where;
      EXPECT_EQ(out[i].state, r.state) << where;  // bit for bit
      EXPECT_EQ(out[i].steps, r.steps) << where;
      EXPECT_EQ(out[i].rejected, r.rejected) << where;
      EXPECT_EQ(out[i].last_step, r.last_step) << where;
      EXPECT_TRUE(theirs == mine) << where << ": " << theirs.size() << " observed steps against "
                                  << mine.size();
    }
  }
}

TEST(OrbitTaylorEnsemble, CircleIsTheScalarRunsBitsForEveryBatchSize) {
  const std::vector<Body> b = bodies(11);
  const std::vector<OrbitState> x = starts(b);
  std::vector<CircularOrbitModel> models;
  for (const Body& body : b)
    models.emplace_back(body, CircularOrbit::from_rate(0.7 + 0.01 * body.inertia()[0]));
  for (double tol : {1e-8, 1e-12}) {
    const OrbitTaylorEnsemble e(tol, tol);
    IntegrateOptions opt;
    expect_scalar_bits(e, models, x, 0.0, 30.0, opt, tol);  // the stepper's first step
    opt.initial_step = 30.0 / 1000.0;                       // run_orbit_method's
    expect_scalar_bits(e, models, x, 0.0, 30.0, opt, tol);
    expect_scalar_bits(e, std::vector<CircularOrbitModel>{models[3]}, x, 5.0, -20.0, opt,
                       tol);  // one model, backwards
  }
}

TEST(OrbitTaylorEnsemble, EllipseIsTheScalarRunsBitsForEveryBatchSize) {
  const std::vector<Body> b = bodies(9);
  const std::vector<OrbitState> x = starts(b);
  std::vector<EllipticOrbitModel> models;
  for (std::size_t i = 0; i < b.size(); ++i) {
    models.emplace_back(b[i],
                        EllipticOrbit::from_mean_motion(0.7, 0.05 * static_cast<double>(i), 0.4));
  }
  const double tol = 1e-10;
  const OrbitTaylorEnsemble e(tol, tol);
  IntegrateOptions opt;
  opt.initial_step = 0.01;
  expect_scalar_bits(e, models, x, 0.4, 0.4 + 12.0, opt, tol);
  expect_scalar_bits(e, std::vector<EllipticOrbitModel>{models[5]}, x, 1.0, -6.0, opt, tol);
}

TEST(OrbitTaylorEnsemble, RunsThatStopEarlyAreTheScalarRunsBits) {
  const std::vector<Body> b = bodies(7);
  const std::vector<OrbitState> x = starts(b);
  std::vector<CircularOrbitModel> models;
  for (const Body& body : b) models.emplace_back(body, CircularOrbit::from_rate(0.7));
  IntegrateOptions opt;
  opt.max_steps = 9;  // every run ends in step_limit, some lanes at other steps than others
  const OrbitTaylorEnsemble e(1e-9, 1e-9);
  expect_scalar_bits(e, models, x, 0.0, 40.0, opt, 1e-9);
  const std::vector<OrbitOutcome> out =
      OrbitTaylorEnsemble(1e-9, 1e-9).integrate(models, x, 0.0, 40.0, opt);
  for (const OrbitOutcome& o : out) EXPECT_EQ(o.status, Status::step_limit);
}

// The chaos runs: each trajectory's outcome and indicators (MEGNO, λ_max, FLI accumulated from the
// observed renormalisations) are orbit_chaos's with method taylor, bit for bit.
template <class M, class Time>
void expect_chaos_bits(const std::vector<M>& models, const std::vector<OrbitState>& x, double a,
                       double b, double t0, double t1, Time&& time) {
  const double tol = 1e-10;
  for (SimdPath path : test::available_paths()) {
    OrbitTaylorEnsemble e(tol, tol, path);
    IntegrateOptions opt;  // orbit_chaos's
    opt.initial_step = std::abs(b - a) / 1000.0;
    std::vector<phase::ChaosIndicators> ind(x.size(), phase::ChaosIndicators(t0, 1));
    const std::vector<OrbitOutcome> out = e.integrate_chaos(
        models, x, a, b, opt, [&](std::size_t p, double v, const OrbitState&, double g) {
          ind[p].accumulate(time(models[p], v), {g, 0, 0, 0, 0, 0});
        });
    for (std::size_t i = 0; i < x.size(); ++i) {
      const std::string where =
          std::string(simd_path_name(path)) + ", trajectory " + std::to_string(i);
      OrbitChaosSettings st;
      st.method = MethodSettings("taylor", 0.0, tol, tol);
      st.t0 = t0;
      st.t1 = t1;
      const OrbitChaosResult r = orbit_chaos(models[i], x[i], st);
      const phase::ChaosSample c = ind[i].sample();
      EXPECT_EQ(out[i].status, r.outcome.status) << where;
      EXPECT_EQ(out[i].t, r.outcome.t) << where;
      EXPECT_EQ(out[i].state, r.outcome.state) << where;
      EXPECT_EQ(out[i].steps, r.outcome.steps) << where;
      EXPECT_EQ(out[i].rejected, r.outcome.rejected) << where;
      EXPECT_EQ(c.megno, r.indicators.megno) << where;
      EXPECT_EQ(c.lyapunov_max, r.indicators.lyapunov_max) << where;
      EXPECT_EQ(c.fli, r.indicators.fli) << where;
      EXPECT_GT(r.outcome.steps, 20) << where;
    }
  }
}

TEST(OrbitTaylorEnsemble, ChaosRunsAreOrbitChaosBits) {
  const std::vector<Body> b = bodies(6);
  const std::vector<OrbitState> x = starts(b);
  std::vector<CircularOrbitModel> circles;
  std::vector<EllipticOrbitModel> ellipses;
  for (const Body& body : b) {
    circles.emplace_back(body, CircularOrbit::from_rate(0.7));
    ellipses.emplace_back(body, EllipticOrbit::from_mean_motion(0.7, 0.2, 0.4));
  }
  expect_chaos_bits(circles, x, 1.0, 31.0, 1.0, 31.0,
                    [](const CircularOrbitModel&, double t) { return t; });
  const EllipticOrbit& o = ellipses[0].orbit();
  const double nu1 = true_anomaly_at(o, 20.0);
  expect_chaos_bits(ellipses, x, o.true_anomaly0, nu1, 0.0, 20.0,
                    [](const EllipticOrbitModel& m, double nu) {
                      return elapsed_time(m.orbit(), m.orbit().true_anomaly0, nu);
                    });
}

TEST(OrbitTaylorEnsemble, RefusesBadInputBeforeAnyWork) {
  const std::vector<Body> b = bodies(3);
  const std::vector<OrbitState> x = starts(b);
  std::vector<CircularOrbitModel> two;
  for (int i = 0; i < 2; ++i) two.emplace_back(b[0], CircularOrbit::from_rate(0.7));
  OrbitTaylorEnsemble e(1e-9, 1e-9);
  int calls = 0;
  auto count = [&](std::size_t, double, const OrbitState&) { ++calls; };
  EXPECT_THROW(e.integrate(two, x, 0.0, 1.0, {}, count), InputError);  // 2 models, 3 states
  const std::vector<CircularOrbitModel> one{two[0]};
  std::vector<OrbitState> bad = x;
  bad[2].gamma[1] = std::nan("");
  EXPECT_THROW(e.integrate(one, bad, 0.0, 1.0, {}, count), InputError);
  EXPECT_THROW(e.integrate(one, x, 0.0, std::numeric_limits<double>::infinity(), {}, count),
               InputError);
  EXPECT_EQ(calls, 0);
  EXPECT_THROW(OrbitTaylorEnsemble(0.0, 1e-9), InputError);
  EXPECT_TRUE(e.integrate(one, std::vector<OrbitState>{}, 0.0, 1.0).empty());
}

}  // namespace
}  // namespace test_orbit_taylor_ensemble
}  // namespace newtop
