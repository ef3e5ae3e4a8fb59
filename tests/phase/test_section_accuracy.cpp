// Poincaré sections to the method's accuracy: Brun's fourth integral at every crossing, the
// convergence of the crossings with the step at the method's order, the seeded orbits of a phase
// portrait on their levels, and the conventions of the Andoyer–Deprit variables.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "newtop/model/model.hpp"
#include "newtop/phase/section_run.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_section_accuracy {
namespace {

using phase::Crossing;
using phase::Direction;
using test::kEps;

std::vector<Crossing> crossings(const QuadraticModel& model, const State& x0,
                                const std::string& surface, const MethodSettings& method,
                                double t_end, Direction dir = Direction::both,
                                bool start_on_surface = false) {
  const phase::SurfaceFunction g(phase::parse_surface(surface), model.body);
  const phase::SectionSettings settings{dir, 100000, start_on_surface};
  std::vector<Crossing> out;
  phase::IntegralsDrift drift;
  phase::section_orbit(method, model, g, settings, 0, x0, 0.0, t_end, IntegrateOptions{}, out,
                       drift);
  return out;
}

MethodSettings fixed(const std::string& name, double h) {
  MethodSettings m;
  m.name = name;
  m.step = h;
  return m;
}

// Brun's case (docs/model.md §5): I4 = |Iω|² − λABC γ·I⁻¹γ is an integral, so the section's points
// lie on its level curves. Every crossing keeps I4 to the method's accuracy: within twice the
// largest deviation of I4 along the accepted steps of the same run (the method's own error there),
// plus the rounding of I4 (64 ε of its terms). A crossing found by any cruder landing (the step's
// end, or an interpolation of order below the method's) leaves that band.
TEST(SectionAccuracy, BrunIntegralHoldsAtEveryCrossing) {
  const QuadraticModel model = test::brun_model();
  const State x0 = test::generic_state(model);
  const double i0 = brun(model, x0);
  for (const MethodSettings& m :
       {fixed("splitting4", 0.02), fixed("splitting6", 0.05), fixed("rk4", 0.01)}) {
    double step_dev = 0.0;
    auto obs = [&](double, const State& x) {
      step_dev = std::max(step_dev, std::abs(brun(model, x) - i0));
    };
    run_method(m, model, x0, 0.0, 200.0, IntegrateOptions{}, obs);
    const Vec3 I = model.body.inertia();
    const double scale = (I.cwiseProduct(omega(model.body, x0))).squaredNorm() +
                         std::abs(model.field.lambda_) * I.prod() * I.cwiseInverse().sum();
    const std::vector<Crossing> cs = crossings(model, x0, "gamma3 = 0.3", m, 200.0);
    ASSERT_GE(cs.size(), 20u) << m.name;
    for (const Crossing& c : cs) {
      EXPECT_LE(std::abs(brun(model, c.x) - i0), 2 * step_dev + 64 * kEps * scale)
          << m.name << " t = " << c.t << " step deviation " << step_dev;
    }
  }
}

/// Largest difference of matching crossings (times and states) of two runs.
double section_distance(const std::vector<Crossing>& a, const std::vector<Crossing>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    d = std::max({d, std::abs(a[i].t - b[i].t), test::distance(a[i].x, b[i].x)});
  }
  return d;
}

// The section does not depend on the step beyond the method's accuracy: the crossings of runs at
// h, h/2 and h/4 converge at the method's order p, d(h, h/2)/d(h/2, h/4) = 2^p (within a factor 2
// for the higher-order terms). A location cruder than the method (the step's end: error O(h))
// gives the ratio 2.
TEST(SectionAccuracy, CrossingsConvergeAtTheMethodsOrder) {
  const QuadraticModel model = test::generic_model();
  const State x0 = test::generic_state(model);
  struct Case {
    const char* name;
    double h;
    int order;
  };
  for (const Case& c : {Case{"splitting4", 0.04, 4}, Case{"rk4", 0.04, 4},
                        Case{"splitting6", 0.1, 6}, Case{"splitting2", 0.02, 2}}) {
    const auto s1 = crossings(model, x0, "gamma1 + 0.5*gamma2 = 0.1", fixed(c.name, c.h), 20.0);
    const auto s2 = crossings(model, x0, "gamma1 + 0.5*gamma2 = 0.1", fixed(c.name, c.h / 2), 20.0);
    const auto s4 = crossings(model, x0, "gamma1 + 0.5*gamma2 = 0.1", fixed(c.name, c.h / 4), 20.0);
    ASSERT_GE(s1.size(), 6u);
    const double d1 = section_distance(s1, s2), d2 = section_distance(s2, s4);
    const double expected = std::ldexp(1.0, c.order);
    EXPECT_GT(d1 / d2, expected / 2) << c.name << ": " << d1 << " " << d2;
    EXPECT_LT(d1 / d2, expected * 2) << c.name << ": " << d1 << " " << d2;
  }
}

// The seeded orbits of a phase portrait: on the surface, on the energy and area levels (to the
// rounding of the energy's terms), crossing in the kept direction; none where the level misses.
TEST(SectionAccuracy, SeedsLieOnTheSurfaceAndTheLevels) {
  const QuadraticModel qm = test::brun_model();
  const Model model(qm);
  const phase::Surface surface = phase::parse_surface("gamma3 = 0.2");
  const phase::SurfaceFunction g(surface, qm.body);
  const State x0 = test::generic_state(qm);
  const phase::Levels levels{energy(qm, x0), area(x0)};
  for (Direction dir : {Direction::up, Direction::down}) {
    const std::vector<State> seeds = phase::seed_orbits(model, surface, levels, 12, dir);
    ASSERT_EQ(seeds.size(), 12u);
    for (const State& s : seeds) {
      EXPECT_LE(std::abs(g(s)), 4 * kEps);
      EXPECT_NEAR(geometric(s), 1.0, 4 * kEps);
      EXPECT_NEAR(area(s), levels.area, 16 * kEps * s.m.norm());
      const double terms = 0.5 * s.m.squaredNorm() * qm.body.inertia().cwiseInverse().maxCoeff() +
                           std::abs(qm.field.lambda_) * qm.body.inertia().maxCoeff();
      EXPECT_NEAR(energy(qm, s), levels.energy, 32 * kEps * terms);
      const double rate = g.b_gamma.dot(rhs(qm, s).gamma);
      EXPECT_GT(dir == Direction::up ? rate : -rate, 0.0);
    }
  }
  const phase::Levels below{-10.0, levels.area};
  EXPECT_TRUE(phase::seed_orbits(model, surface, below, 12, Direction::up).empty());
  const phase::Surface outside = phase::parse_surface("gamma3 = 1.5");
  EXPECT_TRUE(phase::seed_orbits(model, outside, levels, 12, Direction::up).empty());
  EXPECT_THROW(phase::seed_orbits(model, surface, levels, 0, Direction::up), InputError);
}

// Surfaces with a momentum term: the seeds lie on the surface, the sphere and the levels to the
// rounding of their terms, cross in the kept direction, and are K distinct points.
TEST(SectionAccuracy, SeedsOnSurfacesOfTheMomentum) {
  const QuadraticModel qm = test::generic_model(Vec3(0.1, -0.2, 0.3));
  const Model model(qm);
  const State x0 = test::generic_state(qm);
  const phase::Levels levels{energy(qm, x0), area(x0)};
  for (const char* text : {"omega1 = 0", "m2 + 0.3*gamma1 = 0.1", "omega3 - gamma3 = 0.2"}) {
    const phase::Surface surface = phase::parse_surface(text);
    const phase::SurfaceFunction g(surface, qm.body);
    for (Direction dir : {Direction::up, Direction::down}) {
      const std::vector<State> seeds = phase::seed_orbits(model, surface, levels, 10, dir);
      ASSERT_EQ(seeds.size(), 10u) << text;
      for (std::size_t i = 0; i < seeds.size(); ++i) {
        const State& s = seeds[i];
        EXPECT_LE(std::abs(g(s)), 8 * kEps * g.scale(s)) << text;
        EXPECT_NEAR(geometric(s), 1.0, 4 * kEps) << text;
        EXPECT_NEAR(area(s), levels.area, 16 * kEps * s.m.norm()) << text;
        const double terms = 0.5 * s.m.squaredNorm() * qm.body.inertia().cwiseInverse().maxCoeff() +
                             std::abs(potential(qm, s.gamma)) +
                             std::abs(qm.field.lambda_) * qm.body.inertia().maxCoeff();
        EXPECT_NEAR(energy(qm, s), levels.energy, 64 * kEps * terms) << text;
        const State d = rhs(qm, s);
        const double rate = g.b_m.dot(d.m) + g.b_gamma.dot(d.gamma);
        EXPECT_GT(dir == Direction::up ? rate : -rate, 0.0) << text;
        if (i > 0) {
          EXPECT_GT((s.gamma - seeds[i - 1].gamma).norm(), 1e-3) << text;
        }
      }
    }
  }
  // A level below the minimum of the energy on the surface is empty.
  const phase::Levels below{-1e3, levels.area};
  EXPECT_TRUE(
      phase::seed_orbits(model, phase::parse_surface("omega1 = 0"), below, 10, Direction::up)
          .empty());
}

// A seeded orbit starts on the surface: its start is its first crossing, and the next one is a
// full return later, not the same point found again (even when rounding puts the seed a bit on the
// side the crossing comes from).
TEST(SectionAccuracy, SeededOrbitStartsWithItsSeed) {
  const QuadraticModel qm = test::brun_model();
  const phase::Surface surface = phase::parse_surface("gamma3 = 0.2");
  const State x0 = test::generic_state(qm);
  const auto seeds =
      phase::seed_orbits(Model(qm), surface, {energy(qm, x0), area(x0)}, 3, Direction::up);
  ASSERT_EQ(seeds.size(), 3u);
  for (State s : seeds) {
    // On the surface to round-off but on its negative side: the sign change of the first step
    // is the seed itself, not a new crossing; so too on a backward run, whose first step ends
    // (in time) at the seed.
    s.gamma[2] = std::nextafter(0.2, 0.0);
    for (const double t_end : {100.0, -100.0}) {
      const auto cs =
          crossings(qm, s, "gamma3 = 0.2", fixed("splitting6", 0.02), t_end, Direction::up, true);
      ASSERT_GE(cs.size(), 2u);
      EXPECT_EQ(cs[0].t, 0.0);
      EXPECT_EQ(cs[0].x, s);
      EXPECT_GT(std::abs(cs[1].t), 0.5) << t_end;
      EXPECT_EQ(cs[1].t > 0, t_end > 0);
    }
  }
}

// Andoyer–Deprit: m1 = √(G² − L²) sin l, m2 = √(G² − L²) cos l, L = m3, G = |m|; turning γ about
// m by α turns the node γ × m by α, so g decreases by α.
TEST(SectionAccuracy, AndoyerDepritConventions) {
  const State x{Vec3(0.4, -1.1, 0.7), Vec3(0.48, -0.6, 0.64)};
  const phase::AndoyerDeprit ad = phase::andoyer_deprit(x);
  const double s = std::sqrt(ad.G * ad.G - ad.L * ad.L);
  EXPECT_NEAR(s * std::sin(ad.l), x.m[0], 4 * kEps * ad.G);
  EXPECT_NEAR(s * std::cos(ad.l), x.m[1], 4 * kEps * ad.G);
  EXPECT_EQ(ad.L, x.m[2]);
  EXPECT_NEAR(ad.H, x.m.dot(x.gamma), 4 * kEps * ad.G);
  for (double alpha : {0.3, -1.2, 2.5}) {
    State y = x;
    y.gamma = Eigen::AngleAxisd(alpha, x.m.normalized()) * x.gamma;
    const phase::AndoyerDeprit b = phase::andoyer_deprit(y);
    const double diff = std::remainder(b.g - (ad.g - alpha), 2 * std::numbers::pi);
    EXPECT_NEAR(diff, 0.0, 16 * kEps) << alpha;
    EXPECT_EQ(b.l, ad.l);  // l does not see γ
  }
}

}  // namespace
}  // namespace test_section_accuracy
}  // namespace newtop
