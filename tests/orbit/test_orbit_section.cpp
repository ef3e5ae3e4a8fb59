// Poincaré sections on an orbit (docs/section.md "Orbit scenarios", docs/orbit.md §10): crossings
// on the surface to round-off, the Casimirs kept there, the planar pitch motion against its own
// first integral and its libration period, the same section at half the step, the elliptic orbit
// against a second method.

#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "newtop/model/model.hpp"
#include "newtop/orbit/orbit_section.hpp"
#include "newtop/phase/section_run.hpp"
#include "orbit_problems.hpp"

namespace newtop {
namespace test_orbit_section {
namespace {

using test::kOrbitEps;

// A crossing lies on g = 0 to the rounding of g: a few ε of the size of g's terms, plus |g′| times
// the last bit of the located τ (TOMS748 stops at adjacent doubles): measured up to 4.3ε (an
// elliptic splitting8 crossing, whose bits moved when the orbit's rotations took the engine's
// sin/cos series), so 8ε.
constexpr double kOnSurface = 8 * kOrbitEps;

MethodSettings splitting(const char* name, double h) {
  MethodSettings m;
  m.name = name;
  m.step = h;
  return m;
}

struct Section {
  std::vector<OrbitCrossing> crossings;
  OrbitSectionDrift drift;
  phase::SectionRun run;
};

template <class M>
Section section(const MethodSettings& method, const M& model, const char* surface,
                const OrbitState& x0, double a, double b, std::int64_t n = 1000) {
  const phase::SurfaceFunction g(phase::parse_surface(surface), model.body(), true);
  Section s;
  s.run = orbit_section(method, model, g, {phase::Direction::up, n, false}, 0, x0, a, b,
                        100'000'000, s.crossings, s.drift);
  for (const OrbitCrossing& c : s.crossings) {
    EXPECT_LE(std::abs(g(c.x)), kOnSurface * g.scale(c.x)) << surface << " at t = " << c.t;
  }
  return s;
}

const Vec3 kMoments(1.0, 1.6, 2.1);  // A, B in the orbit plane, C about the orbit normal

/// The planar pitch state of docs/orbit.md §4: n = e_z, γ = (cos θ, −sin θ, 0), ω_z = ω0 + θ̇.
OrbitState pitch_state(double theta, double rate, double w0) {
  return {kMoments.z() * (w0 + rate) * Vec3::UnitZ(), Vec3(std::cos(theta), -std::sin(theta), 0),
          Vec3::UnitZ()};
}

// Planar pitch on a circular orbit of rate ω0 (e = 0 in Beletsky's equation, ν = ω0 t):
// θ̈ + 3kω0² sin θ cos θ = 0, k = (B − A)/C, whose first integral (θ̇ times the equation)
// E = ½θ̇² + (3/2)kω0² sin²θ gives at every crossing of γ2 = −sin θ = −s (θ decreasing: g = γ2 + s
// goes up) the rate θ̇ = −√(2E − 3kω0² s²). With φ = 2θ it is the pendulum φ̈ = −3kω0² sin φ,
// whose libration from θmax has the period T = 4K(sin θmax)/(ω0√(3k)) (K the complete elliptic
// integral of the first kind, modulus sin(φmax/2) = sin θmax): the crossings recur every T.
TEST(OrbitSection, PlanarPitchCrossingsKeepThePitchIntegralAndRecurWithTheLibrationPeriod) {
  const double w0 = 1.3, k = (kMoments.y() - kMoments.x()) / kMoments.z();
  const double theta_max = 0.5, s = 0.3;
  const CircularOrbitModel model(Body::from_principal(kMoments, 1.0, Vec3::Zero()),
                                 CircularOrbit::from_rate(w0));
  const double E = 1.5 * k * w0 * w0 * std::sin(theta_max) * std::sin(theta_max);
  const double rate = -std::sqrt(2 * E - 3 * k * w0 * w0 * s * s);
  const double T = 4 * boost::math::ellint_1(std::sin(theta_max)) / (w0 * std::sqrt(3 * k));
  // splitting6 at ω0h = 0.013 over 12 librations (6.7e3 steps): the global error is of order
  // (ω0h)⁶ ω0t ≈ 4e-10 (measured 2e-14 on the rate and 4e-14 on the intervals: the constant is
  // small); 1e-9 fails for any error of the equations or of the location (a wrong sign of k or of
  // the orbital rotation, a crossing one step off: O(h) = 1e-2).
  constexpr double kPitchAccuracy = 1e-9;
  const Section sec = section(splitting("splitting6", 0.01), model, "gamma2 = -0.3",
                              pitch_state(theta_max, 0.0, w0), 0.0, 12.0 * T);
  ASSERT_EQ(sec.crossings.size(), 12u);
  for (std::size_t i = 0; i < sec.crossings.size(); ++i) {
    const OrbitCrossing& c = sec.crossings[i];
    const double pitch_rate = omega(model.body(), c.x).z() - w0;
    EXPECT_NEAR(pitch_rate, rate, kPitchAccuracy) << i;
    EXPECT_NEAR(std::abs(c.x.normal.z()), 1.0, 1e-15);  // the motion stays planar
    if (i > 0) {
      EXPECT_NEAR(c.t - sec.crossings[i - 1].t, T, kPitchAccuracy) << i;
    }
    // The Casimirs at the crossings: every sub-flow keeps them, a landing step too: round-off
    // of N = 6.7e3 steps of a few rotations, bounded by 64ε√N = 1.2e-12 (measured 5e-15).
    EXPECT_LT(casimir_error(c.x), 64 * kOrbitEps * std::sqrt(6.7e3)) << i;
  }
  EXPECT_LT(sec.drift.gamma_gamma, 64 * kOrbitEps * std::sqrt(6.7e3));
  EXPECT_TRUE(sec.drift.has_jacobi);
}

// A tumbling gyrostat on a circular orbit, on a surface that mixes the orbit normal and γ. The
// crossings converge with the method's order: splitting4's differences between h, h/2 and h/4
// shrink by 2⁴ = 16 (measured 15.995; the bracket 12–20 fails for an order 3 or 5). A landing off
// the method's own solution (e.g. by a lower-order step) is caught by the zero-rate test below.
// The Casimirs n·n and γ·n: round-off of N ≤ 6e3 steps, 64ε√N = 1.1e-12 (measured 3e-14).
TEST(OrbitSection, SameSectionWhenTheStepIsHalved) {
  const Body body = test::orbit_body();
  const CircularOrbitModel model(body, CircularOrbit::from_rate(0.8));
  const OrbitState x0 = test::tumbling_state(body);
  const char* surface = "normal1 - 0.3*gamma2 = 0.1";
  std::vector<Section> runs;
  for (const double h : {0.04, 0.02, 0.01}) {
    runs.push_back(section(splitting("splitting4", h), model, surface, x0, 0.0, 60.0, 8));
    EXPECT_TRUE(runs.back().run.by_crossings);
    EXPECT_LT(runs.back().drift.normal_normal, 64 * kOrbitEps * std::sqrt(6e3));
    EXPECT_LT(runs.back().drift.gamma_normal, 64 * kOrbitEps * std::sqrt(6e3));
  }
  ASSERT_EQ(runs[0].crossings.size(), 8u);
  auto distance = [&](const Section& a, const Section& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.crossings.size(); ++i) {
      d = std::max({d, std::abs(a.crossings[i].t - b.crossings[i].t),
                    test::max_distance(a.crossings[i].x, b.crossings[i].x)});
    }
    return d;
  };
  const double ratio = distance(runs[0], runs[1]) / distance(runs[1], runs[2]);
  EXPECT_GT(ratio, 12.0);
  EXPECT_LT(ratio, 20.0);
}

// An elliptic orbit (independent variable ν): the splitting's crossings against those of rkf78's
// own one-step map (a second method, located the same way), which must agree to the accuracy of
// both: splitting8 at Δν = 0.01 and rkf78 at 1e-13 over 4 orbits are each ~1e-11 (measured
// difference 4e-12); 1e-9 fails for a crossing off the methods' solutions (O(h) = 1e-2).
TEST(OrbitSection, EllipticCrossingsAgreeBetweenTwoMethods) {
  const Body body = test::orbit_body();
  const EllipticOrbitModel model(body, EllipticOrbit::from_mean_motion(1.0, 0.2, 0.3));
  const OrbitState x0 = test::tumbling_state(body);
  MethodSettings rkf;
  rkf.name = "rkf78";
  rkf.abs_tol = rkf.rel_tol = 1e-13;
  const char* surface = "omega1 + normal3 = 0.2";
  const Section a = section(splitting("splitting8", 0.01), model, surface, x0, 0.3, 25.0);
  const Section b = section(rkf, model, surface, x0, 0.3, 25.0);
  ASSERT_GE(a.crossings.size(), 4u);
  ASSERT_EQ(a.crossings.size(), b.crossings.size());
  for (std::size_t i = 0; i < a.crossings.size(); ++i) {
    EXPECT_NEAR(a.crossings[i].t, b.crossings[i].t, 1e-9) << i;
    EXPECT_LT(test::max_distance(a.crossings[i].x, b.crossings[i].x), 1e-9) << i;
  }
  EXPECT_FALSE(a.drift.has_jacobi);
  EXPECT_LT(a.drift.gamma_normal, 64 * kOrbitEps * std::sqrt(2.5e3));  // measured 1.7e-14
}

// At ω0 = 0 (λ fixed) the orbit model is the fixed-centre model of docs/model.md §4 and its
// splitting the same composition of the same sub-flows
// (OrbitLimits.ZeroRateSplittingIsTheFixedCentreSplitting): the orbit section and the body section
// of `newtop section` must give the same crossings, up to the round-off that separates the two
// steppers (1e-12 over T = 5, there): 1e-11 over T = 30 (measured 3e-14 over four crossings).
TEST(OrbitSection, ZeroRateSectionIsTheFixedCentreSection) {
  constexpr double kLambda = 1.7, kSameSection = 1e-11;
  const Body body = test::orbit_body();
  const CircularOrbitModel model(body, CircularOrbit::forced(0.0, kLambda));
  const QuadraticModel fixed{body, QuadraticField::coulomb(0.0, kLambda)};
  const OrbitState x0 = test::tumbling_state(body);
  const char* surface = "gamma1 - 0.5*omega1 = 0.1";
  const MethodSettings method = splitting("splitting4", 0.01);
  const Section orbit = section(method, model, surface, x0, 0.0, 30.0);
  std::vector<phase::Crossing> crossings;
  phase::IntegralsDrift drift;
  phase::section_orbit(method, fixed, phase::SurfaceFunction(phase::parse_surface(surface), body),
                       {phase::Direction::up, 1000, false}, 0, State{x0.m, x0.gamma}, 0.0, 30.0,
                       IntegrateOptions{}, crossings, drift);
  ASSERT_GE(crossings.size(), 3u);
  ASSERT_EQ(orbit.crossings.size(), crossings.size());
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    EXPECT_NEAR(orbit.crossings[i].t, crossings[i].t, kSameSection) << i;
    EXPECT_LT((orbit.crossings[i].x.m - crossings[i].x.m).cwiseAbs().maxCoeff(), kSameSection);
    EXPECT_LT((orbit.crossings[i].x.gamma - crossings[i].x.gamma).cwiseAbs().maxCoeff(),
              kSameSection);
  }
}

// The orbital-frame coordinates: the planar pitch state's 3-2-1 yaw is Beletsky's θ and its
// relative rate θ̇; a state built from given angles gives them back.
TEST(OrbitSection, OrbitalFrameCoordinatesAreTheScenarioAngles) {
  const Body body = Body::from_principal(kMoments, 1.0, Vec3::Zero());
  const OrbitFrameCoords c = orbit_frame_coords(body, pitch_state(0.4, -0.2, 1.1), 1.1);
  EXPECT_NEAR(c.euler_321[0], 0.4, 1e-15);
  EXPECT_NEAR(c.euler_321[1], 0.0, 1e-15);
  EXPECT_NEAR(c.omega_relative.z(), -0.2, 1e-15);
  const Vec3 angles(0.3, -0.2, 0.7), w_rel(0.1, 0.2, -0.3);
  const Mat3 R =
      (Eigen::AngleAxisd(angles[0], Vec3::UnitZ()) * Eigen::AngleAxisd(angles[1], Vec3::UnitY()) *
       Eigen::AngleAxisd(angles[2], Vec3::UnitX()))
          .toRotationMatrix();
  const OrbitState x = state_from_relative(body, R.transpose(), w_rel, 0.9);
  const OrbitFrameCoords d = orbit_frame_coords(body, x, 0.9);
  EXPECT_LT((d.euler_321 - angles).norm(), 1e-14);
  EXPECT_LT((d.omega_relative - w_rel).norm(), 1e-14);
}

TEST(OrbitSection, NormalComponentsParseAndAreRefusedOnABody) {
  const phase::Surface s = phase::parse_surface("normal1 - 2*normal3 + gamma2 = 0.5");
  EXPECT_EQ(s.a_normal, Vec3(1, 0, -2));
  EXPECT_TRUE(s.has_normal());
  EXPECT_FALSE(s.of_gamma_only());
  EXPECT_EQ(phase::gamma_plane_axis(phase::parse_surface("gamma3 + 0*normal1 = 0")), 2);
  const Body body = Body::from_principal(kMoments, 1.0, Vec3::Zero());
  EXPECT_THROW(phase::SurfaceFunction(s, body), InputError);
  EXPECT_THROW(phase::require_body_surface(s), InputError);
  EXPECT_THROW(phase::parse_surface("normal4 = 0"), InputError);
  EXPECT_THROW(phase::parse_surface("normal1 + normal1 = 0"), InputError);
}

// The request form on an orbit: the crossings of the positional run, a status, and on an ellipse
// the span in time carried to anomalies.
TEST(OrbitSection, RequestFormAgreesWithThePositionalRunAndSaysNoCrossing) {
  const CircularOrbitModel model(Body::from_principal(kMoments, 1.0, Vec3::Zero()),
                                 CircularOrbit::from_rate(1.0));
  const OrbitState x0 = pitch_state(0.3, 0.0, 1.0);
  MethodSettings m;
  m.name = "splitting6";
  m.step = 0.01;
  phase::SectionRequest q;
  q.method = m;
  q.surface = phase::parse_surface("gamma2 = 0");
  q.t_end = 20.0;
  const OrbitSectionResult r = orbit_section(model, x0, q);
  const Section s = section(m, model, "gamma2 = 0", x0, 0.0, 20.0);
  ASSERT_FALSE(r.crossings.empty());
  EXPECT_EQ(r.status, phase::SectionStatus::t_end);
  ASSERT_EQ(r.crossings.size(), s.crossings.size());
  for (std::size_t i = 0; i < r.crossings.size(); ++i)
    EXPECT_EQ(r.crossings[i].t, s.crossings[i].t);
  q.surface = phase::parse_surface("normal3 = 0.5");  // n stays e_z: never met
  EXPECT_EQ(orbit_section(model, x0, q).status, phase::SectionStatus::no_crossing);
  q.t_end.reset();
  EXPECT_THROW(orbit_section(model, x0, q), InputError);
}

}  // namespace
}  // namespace test_orbit_section
}  // namespace newtop
