// The orbit analyses as results: the stability of a numbered relative equilibrium against the
// closed-form DeBra–Delp factors at the same orientation, the refusals every caller shares, and
// the diagram's counts against the closed-form regions counted independently.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "newtop/orbit/orbit_equilibria.hpp"
#include "newtop/orbit/orbit_reports.hpp"
#include "orbit_problems.hpp"

namespace newtop {
namespace test_orbit_reports {
namespace {

using test::kOrbitEps;

// As in test_debra_delp.cpp: the coefficients of the characteristic polynomial carry the
// eigensolver's backward error, ≤ 16 · 6 · 6⁶ ε for |J| ≤ 6 in units of ω0.
constexpr double kCharacteristicTolerance = 16 * 6 * 46656 * kOrbitEps;

std::string what(const RelativeStabilityRequest& request, const CircularOrbitModel& model) {
  try {
    relative_stability(model, request);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(OrbitReports, NumberedEquilibriumHasTheClosedFormSpectrum) {
  const double k_R = 0.4, k_Y = 0.2;  // the Lagrange region
  const Body body = Body::from_principal(inertia_from_ratios(k_R, k_Y), 1.0, Vec3::Zero());
  const CircularOrbitModel model(body, CircularOrbit::from_rate(1.0));
  const RelativeEquilibriumSet set = find_relative_equilibria(model);
  // The orientation of the diagram: γ = e_z (yaw along the radius), n = e_y (pitch along the
  // normal); find it in the list and ask for it by its number.
  int k = 0;
  for (std::size_t i = 0; i < set.equilibria.size(); ++i) {
    const auto& e = set.equilibria[i];
    if ((e.gamma - Vec3::UnitZ()).norm() < 1e-12 && (e.normal - Vec3::UnitY()).norm() < 1e-12) {
      k = static_cast<int>(i) + 1;
    }
  }
  ASSERT_GT(k, 0);
  const RelativeStabilityReport r = relative_stability(model, {k, std::nullopt});
  EXPECT_LE(r.residual, kRelativeEquilibriumTolerance);
  EXPECT_EQ(r.spectrum.verdict, OrbitStability::lyapunov);
  // s⁶ + c4 s⁴ + c2 s² + c0 against the product of the closed-form factors in σ = s².
  const Eigen::Vector4d sigma = debra_delp_characteristic(k_R, k_Y);
  for (int p = 0; p < 4; ++p) {
    EXPECT_NEAR(r.spectrum.characteristic[2 * p], sigma[p], kCharacteristicTolerance) << p;
  }
  // The same state given directly gives the same report.
  const RelativeStabilityReport s = relative_stability(model, {std::nullopt, r.state});
  EXPECT_EQ(s.spectrum.characteristic, r.spectrum.characteristic);
}

TEST(OrbitReports, RefusalsNameTheField) {
  const Body body = Body::from_principal(inertia_from_ratios(0.4, 0.2), 1.0, Vec3::Zero());
  const CircularOrbitModel model(body, CircularOrbit::from_rate(1.0));
  const OrbitState tilted{Vec3::Zero(), Vec3(0.6, 0.0, 0.8), Vec3::UnitY()};
  EXPECT_EQ(what({}, model).rfind("equilibrium, state: expected exactly one", 0), 0u);
  EXPECT_EQ(what({1, tilted}, model).rfind("equilibrium, state: expected exactly one", 0), 0u);
  EXPECT_EQ(what({25, std::nullopt}, model).rfind("equilibrium: expected 1 to 24", 0), 0u);
  EXPECT_EQ(what({0, std::nullopt, "--equilibrium"}, model).rfind("--equilibrium: expected", 0),
            0u);
  EXPECT_EQ(what({std::nullopt, tilted, "equilibrium", "[initial]"}, model)
                .rfind("[initial]: expected a relative equilibrium", 0),
            0u);
}

TEST(OrbitReports, DiagramCountsTheClosedFormRegions) {
  const RatioRange k_R{-0.95, 0.95, 21}, k_Y{-0.9, 0.9, 19};
  const DebraDelpDiagram d = debra_delp_diagram(k_R, k_Y);
  ASSERT_EQ(d.points.size(), 21u * 19u);
  int closed[3] = {0, 0, 0}, off_boundary = 0;
  for (const auto& p : d.points) {
    if (p.boundary) continue;
    ++off_boundary;
    ++closed[static_cast<int>(debra_delp_closed_form(p.k_R, p.k_Y))];
  }
  // Off the boundaries the computed regions are the closed form's: the counts agree there.
  int computed[3] = {0, 0, 0};
  for (const auto& p : d.points) {
    if (!p.boundary) ++computed[static_cast<int>(p.computed)];
  }
  for (int i = 0; i < 3; ++i) EXPECT_EQ(computed[i], closed[i]) << i;
  // The diagram's counts: the closed form's off the boundaries plus the boundary points' own.
  int on_boundary[3] = {0, 0, 0};
  for (const auto& p : d.points) {
    if (p.boundary) ++on_boundary[static_cast<int>(p.computed)];
  }
  for (int i = 0; i < 3; ++i) EXPECT_EQ(d.counts[i], closed[i] + on_boundary[i]) << i;
  EXPECT_EQ(d.disagreements_with_closed_form, 0);
  EXPECT_EQ(d.counts[0] + d.counts[1] + d.counts[2], 21 * 19);
  EXPECT_GT(off_boundary, 0);
  EXPECT_GT(closed[0], 0);
  EXPECT_GT(closed[1], 0);
  EXPECT_GT(closed[2], 0);
  EXPECT_THROW(debra_delp_diagram({-0.5, 1.2, 5}, k_Y), InputError);
}

}  // namespace
}  // namespace test_orbit_reports
}  // namespace newtop
