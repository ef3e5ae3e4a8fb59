// Poincaré sections: the surface grammar, crossings on the surface to round-off on the method's
// own solution, the fourth integral at every crossing of Brun's case, independence of the step
// to the method's accuracy, the seeded orbits of a phase portrait and the Andoyer–Deprit angles.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "newtop/exact/model_fields.hpp"
#include "newtop/model/model.hpp"
#include "newtop/phase/section_run.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_section {
namespace {

using phase::Crossing;
using phase::Direction;
using test::kEps;

struct SectionResult {
  std::vector<Crossing> crossings;
  phase::SectionRun run;
  phase::IntegralsDrift drift;
};

template <Field F>
SectionResult section(const BasicModel<F>& model, const State& x0, const std::string& surface,
                      MethodSettings method, double t_end, Direction dir = Direction::up,
                      std::int64_t max_crossings = 1000) {
  const phase::SurfaceFunction g(phase::parse_surface(surface), model.body);
  const phase::SectionSettings settings{dir, max_crossings, false};
  SectionResult r;
  r.run = phase::section_orbit(method, model, g, settings, 0, x0, 0.0, t_end, IntegrateOptions{},
                               r.crossings, r.drift);
  return r;
}

MethodSettings fixed(const std::string& name, double h) {
  MethodSettings m;
  m.name = name;
  m.step = h;
  return m;
}

MethodSettings adaptive(const std::string& name, double tol) {
  MethodSettings m;
  m.name = name;
  m.abs_tol = m.rel_tol = tol;
  return m;
}

TEST(SurfaceGrammar, ReadsAffineExpressions) {
  const phase::Surface s = phase::parse_surface("gamma1 + 0.5*gamma2 = 0.1");
  EXPECT_EQ(s.a_gamma, Vec3(1.0, 0.5, 0.0));
  EXPECT_TRUE(s.a_omega.isZero(0.0) && s.a_m.isZero(0.0));
  EXPECT_EQ(s.c, 0.1);
  const phase::Surface t = phase::parse_surface("  -omega1 - 2e-1 * m3 +gamma2=-3");
  EXPECT_EQ(t.a_omega, Vec3(-1.0, 0.0, 0.0));
  EXPECT_EQ(t.a_m, Vec3(0.0, 0.0, -0.2));
  EXPECT_EQ(t.a_gamma, Vec3(0.0, 1.0, 0.0));
  EXPECT_EQ(t.c, -3.0);
  EXPECT_EQ(phase::gamma_plane_axis(phase::parse_surface("gamma3 = 0")), 2);
  EXPECT_EQ(phase::gamma_plane_axis(s), -1);
}

TEST(SurfaceGrammar, RejectsMalformedExpressionsInOneLine) {
  for (const char* bad :
       {"", "gamma3", "gamma4 = 0", "0.5 gamma2 = 0", "gamma3 = 0 0", "gamma1 + gamma1 = 0",
        "0*gamma1 = 1", "gamma3 = x", "gamma3 =", "+-gamma3 = 0", "gamma3 == 0", "gamma3 = 1e400",
        "omega = 0", "gamma3 + 1 = 0", "2*3*gamma1 = 0", "gamma1 gamma2 = 0", "x = 0"}) {
    try {
      phase::parse_surface(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_EQ(msg.rfind("--surface: expected ", 0), 0u) << msg;
      EXPECT_NE(msg.find("found"), std::string::npos) << msg;
    }
  }
}

TEST(SurfaceGrammar, OmegaTermsBecomeAffineInM) {
  const QuadraticModel model = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const phase::SurfaceFunction g(phase::parse_surface("2*omega1 - omega3 + m2 + gamma3 = 0.4"),
                                 model.body);
  const State x = test::generic_state(model);
  const Vec3 w = omega(model.body, x);
  const double direct = 2 * w[0] - w[2] + x.m[1] + x.gamma[2] - 0.4;
  EXPECT_NEAR(g(x), direct, 8 * kEps * g.scale(x));
}

// Every crossing on the surface: |g| within a few roundings of g's terms, for each kind of method
// and for surfaces of γ, of ω and mixed. 4 ε: the rounding of the three products and sums of g
// (≤ 3 ε of its terms) plus the last bit of τ.
TEST(Section, CrossingsLieOnTheSurfaceToRoundOff) {
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  for (const char* surface : {"gamma3 = 0", "omega1 = 0.2", "gamma1 + 0.5*gamma2 - m3 = 0.1"}) {
    for (const MethodSettings& m :
         {fixed("splitting6", 0.02), fixed("splitting2", 0.01), fixed("rk4", 0.01),
          adaptive("rkf78", 1e-10), adaptive("dopri5", 1e-9), adaptive("dop853", 1e-10),
          adaptive("taylor", 1e-10)}) {
      const SectionResult r = section(model, x0, surface, m, 60.0, Direction::both);
      ASSERT_GE(r.crossings.size(), 4u) << surface << " " << m.name;
      const phase::SurfaceFunction g(phase::parse_surface(surface), model.body);
      for (const Crossing& c : r.crossings) {
        EXPECT_LE(std::abs(g(c.x)), 4 * kEps * g.scale(c.x))
            << surface << " " << m.name << " t = " << c.t;
      }
    }
  }
}

// The exact field of point masses: the same, with the kick of the exact moment.
TEST(Section, ExactFieldCrossingsOnTheSurface) {
  const auto points = std::make_shared<const MassModel>(PointMasses(
      {1.0, 0.7, 0.5, 0.9},
      {Vec3(0.3, 0.1, -0.2), Vec3(-0.4, 0.2, 0.1), Vec3(0.1, -0.5, 0.3), Vec3(0.0, 0.2, -0.4)}));
  const Model model = Model::exact(points, 2.0, 3.0 * max_radius(*points));
  const BasicModel<ExactField>& exact = exact_model(model);
  const State x0 = state_from_omega(exact.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
  const SectionResult r = section(exact, x0, "gamma2 = 0", fixed("splitting4", 0.01), 40.0);
  ASSERT_GE(r.crossings.size(), 2u);
  const phase::SurfaceFunction g(phase::parse_surface("gamma2 = 0"), exact.body);
  for (const Crossing& c : r.crossings) EXPECT_LE(std::abs(g(c.x)), 4 * kEps * g.scale(c.x));
}

// The kept direction: up crossings have dg/dt > 0, down ones < 0; both is their union.
TEST(Section, DirectionSelectsTheSignOfDgDt) {
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  const phase::SurfaceFunction g(phase::parse_surface("gamma3 = 0"), model.body);
  auto rate = [&](const State& x) {
    const State d = rhs(model, x);
    return g.b_m.dot(d.m) + g.b_gamma.dot(d.gamma);
  };
  const MethodSettings m = fixed("splitting6", 0.02);
  const SectionResult up = section(model, x0, "gamma3 = 0", m, 80.0, Direction::up);
  const SectionResult down = section(model, x0, "gamma3 = 0", m, 80.0, Direction::down);
  const SectionResult both = section(model, x0, "gamma3 = 0", m, 80.0, Direction::both);
  ASSERT_GE(up.crossings.size(), 3u);
  for (const Crossing& c : up.crossings) EXPECT_GT(rate(c.x), 0.0);
  for (const Crossing& c : down.crossings) EXPECT_LT(rate(c.x), 0.0);
  EXPECT_EQ(both.crossings.size(), up.crossings.size() + down.crossings.size());
}

TEST(Section, StopsAtTheCrossingCountOrAtTEnd) {
  const QuadraticModel model = test::brun_model();
  const State x0 = test::generic_state(model);
  const SectionResult few =
      section(model, x0, "gamma3 = 0", fixed("splitting6", 0.02), 1000.0, Direction::up, 3);
  EXPECT_EQ(few.crossings.size(), 3u);
  EXPECT_TRUE(few.run.by_crossings);
  EXPECT_LT(few.crossings.back().t, 1000.0);
  const SectionResult all = section(model, x0, "gamma3 = 0", fixed("splitting6", 0.02), 30.0);
  EXPECT_FALSE(all.run.by_crossings);
  EXPECT_EQ(all.run.outcome.t, 30.0);
}

// A section of the flow run backwards: the crossings of a backward run from x0 over [−T, 0] are
// those of the forward run from its end state x(−T) over the same span, in reverse order. With a
// symmetric splitting method a step of −h is the inverse of a step of h, so both runs visit the
// same grid points to round-off (64 ε √N over N = 2000 steps, ~6e-13 on |m|, |γ| ~ 1); each
// crossing is located in the same grid interval by the one-step maps from its two ends, which
// differ by the method's local error, C h^7 ~ 1e-12 at h = 0.02 with the model's derivatives of
// order one. 1e-9 bounds both with margin; a locator that dropped or misplaced a crossing (a
// bracket on the wrong side of the step, the direction taken along the run instead of in time)
// misses it by O(h) ~ 1e-2.
TEST(Section, BackwardRunGivesTheForwardCrossingsReversed) {
  constexpr double kSame = 1e-9;
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  const phase::SurfaceFunction g(phase::parse_surface("gamma3 = 0"), model.body);
  auto rate = [&](const State& x) {
    const State d = rhs(model, x);
    return g.b_m.dot(d.m) + g.b_gamma.dot(d.gamma);
  };
  const MethodSettings m = fixed("splitting6", 0.02);
  constexpr double kT = 40.0;
  const SectionResult back = section(model, x0, "gamma3 = 0", m, -kT, Direction::up);
  ASSERT_EQ(back.run.outcome.status, Status::finished);
  ASSERT_EQ(back.run.outcome.t, -kT);
  ASSERT_GE(back.crossings.size(), 3u);
  for (const Crossing& c : back.crossings) {
    EXPECT_GT(rate(c.x), 0.0);  // up: g increases with time, whichever way the run goes
    EXPECT_LT(c.t, 0.0);
  }
  std::vector<Crossing> fwd;
  phase::IntegralsDrift drift;
  const phase::SectionSettings settings{Direction::up, 1000, false};
  phase::section_orbit(m, model, g, settings, 0, back.run.outcome.state, -kT, 0.0,
                       IntegrateOptions{}, fwd, drift);
  ASSERT_EQ(fwd.size(), back.crossings.size());
  for (std::size_t i = 0; i < fwd.size(); ++i) {
    const Crossing& b = back.crossings[back.crossings.size() - 1 - i];
    ASSERT_TRUE(std::isfinite(b.t) && b.x.m.allFinite() && b.x.gamma.allFinite());
    EXPECT_NEAR(fwd[i].t, b.t, kSame) << "crossing " << i;
    EXPECT_LE((fwd[i].x.m - b.x.m).norm(), kSame) << "crossing " << i;
    EXPECT_LE((fwd[i].x.gamma - b.x.gamma).norm(), kSame) << "crossing " << i;
  }
}

}  // namespace
}  // namespace test_section
}  // namespace newtop

namespace newtop {
namespace test_section {
namespace {

// The request form (phase::section): the same crossings as the positional run, and a status that
// says why the run ended — crossings, t_end, or no crossing at all.
TEST(SectionRequest, SaysWhyTheRunEndedAndAgreesWithThePositionalRun) {
  const QuadraticModel model = test::brun_model();
  const State x0 = test::generic_state(model);
  phase::SectionRequest q;
  q.method = fixed("splitting6", 0.02);
  q.surface = phase::parse_surface("gamma3 = 5");  // |γ| = 1: never met
  q.t_end = 30.0;
  const phase::SectionResult none = phase::section(model, x0, q);
  EXPECT_EQ(none.status, phase::SectionStatus::no_crossing);
  EXPECT_TRUE(none.crossings.empty());
  EXPECT_EQ(none.outcome.status, Status::finished);

  q.surface = phase::parse_surface("gamma3 = 0");
  const phase::SectionResult all = phase::section(model, x0, q);
  const SectionResult positional = section(model, x0, "gamma3 = 0", q.method, 30.0);
  ASSERT_FALSE(all.crossings.empty());
  EXPECT_EQ(all.status, phase::SectionStatus::t_end);
  ASSERT_EQ(all.crossings.size(), positional.crossings.size());
  for (std::size_t i = 0; i < all.crossings.size(); ++i) {
    EXPECT_EQ(all.crossings[i].t, positional.crossings[i].t);
    EXPECT_EQ(all.crossings[i].x.gamma, positional.crossings[i].x.gamma);
  }

  q.max_crossings = 3;
  q.t_end.reset();  // no end: until the crossings
  const phase::SectionResult few = phase::section(model, x0, q);
  EXPECT_EQ(few.status, phase::SectionStatus::crossings);
  EXPECT_EQ(few.crossings.size(), 3u);
  EXPECT_STREQ(phase::to_string(few.status), "crossings");
}

}  // namespace
}  // namespace test_section
}  // namespace newtop
