// Relative equilibria on a circular orbit: the 24 orientations of a triaxial body, and a
// gyrostat's count from the polynomial route against an independent multistart Newton search on
// SO(3) (Sarychev & Gutnik: between 8 and 24).

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <random>
#include <set>

#include "newtop/orbit/orbit_equilibria.hpp"
#include "orbit_problems.hpp"

namespace newtop {
namespace test_orbit_equilibria {
namespace {

using test::kOrbitEps;

// A relative equilibrium built from exact principal axes: the residual is round-off on O(1)
// terms.
constexpr double kExactFixedPoint = 64 * kOrbitEps;

TEST(RelativeEquilibria, TriaxialBodyHasTheTwentyFourAlignedOrientations) {
  const Body body = test::orbit_body(Vec3::Zero());
  const CircularOrbitModel model(body, CircularOrbit::from_rate(0.8));
  const RelativeEquilibriumSet set = find_relative_equilibria(model);
  ASSERT_EQ(set.equilibria.size(), 24u);
  EXPECT_EQ(set.unverified, 0);
  std::set<std::pair<int, int>> seen;  // (signed axis of γ, signed axis of n)
  for (const auto& e : set.equilibria) {
    int ag = -1, an = -1;
    for (int i = 0; i < 3; ++i) {
      if (std::abs(std::abs(e.gamma[i]) - 1.0) <= kExactFixedPoint) ag = i;
      if (std::abs(std::abs(e.normal[i]) - 1.0) <= kExactFixedPoint) an = i;
    }
    ASSERT_GE(ag, 0);
    ASSERT_GE(an, 0);
    EXPECT_NE(ag, an);
    seen.insert({e.gamma[ag] > 0 ? ag + 1 : -ag - 1, e.normal[an] > 0 ? an + 1 : -an - 1});
    // Each is a fixed point of the equations, by the residual of the full vector field.
    EXPECT_LT(fixed_point_residual(model, relative_rest_state(model, e.gamma, e.normal)),
              kExactFixedPoint);
  }
  EXPECT_EQ(seen.size(), 24u);
  // Four are Lyapunov stable, the Lagrange orientation: least moment along the radius, largest
  // along the orbit normal (A = 1 < B = 1.6 < C = 2.1).
  EXPECT_EQ(set.lyapunov, 4);
  for (const auto& e : set.equilibria) {
    if (e.stability.verdict != OrbitStability::lyapunov) continue;
    EXPECT_NEAR(std::abs(e.gamma.x()), 1.0, kExactFixedPoint);
    EXPECT_NEAR(std::abs(e.normal.z()), 1.0, kExactFixedPoint);
  }
}

/// Independent search: Newton's method on the rotation (orbital frame → body, columns e_r, e_t,
/// e_n) from random starts, the residual being ṁ of the full vector field at rest in the orbital
/// frame, Jacobian by central differences, steps halved until the residual decreases.
std::vector<Mat3> multistart(const CircularOrbitModel& model, int starts, std::mt19937& rng) {
  auto residual = [&](const Mat3& S) {
    return rhs(model, relative_rest_state(model, S.col(0), S.col(2))).m;
  };
  auto turn = [](const Mat3& S, const Vec3& v) {
    return Mat3(S * Eigen::AngleAxisd(v.norm(), v.norm() > 0 ? v.normalized() : Vec3::UnitX())
                        .toRotationMatrix());
  };
  const double scale = model.orbit().lambda_ * model.body().inertia().maxCoeff();
  std::normal_distribution<double> normal;
  std::vector<Mat3> found;
  for (int k = 0; k < starts; ++k) {
    Mat3 S = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
                 .normalized()
                 .toRotationMatrix();
    Vec3 r = residual(S);
    for (int it = 0; it < 60 && r.norm() > 1e-14 * scale; ++it) {
      Mat3 J;
      for (int j = 0; j < 3; ++j) {
        const Vec3 d = 1e-7 * Vec3::Unit(j);
        J.col(j) = (residual(turn(S, d)) - residual(turn(S, -d))) / 2e-7;
      }
      Vec3 step = -J.fullPivLu().solve(r);
      for (int half = 0; half < 20; ++half, step *= 0.5) {
        const Mat3 T = turn(S, step);
        if (residual(T).norm() < r.norm()) {
          S = T;
          break;
        }
      }
      r = residual(S);
    }
    if (r.norm() > 1e-12 * scale) continue;
    const bool seen = std::any_of(found.begin(), found.end(), [&](const Mat3& F) {
      return (F.col(0) - S.col(0)).cwiseAbs().maxCoeff() < 1e-6 &&
             (F.col(2) - S.col(2)).cwiseAbs().maxCoeff() < 1e-6;
    });
    if (!seen) found.push_back(S);
  }
  return found;
}

// The relative size of the resultant's Chebyshev coefficients above degree 12 when it is the
// exact interpolant: round-off of the 25 samples, each a product of values accurate to ~1e-14.
constexpr double kResultantTail = 1e-9;

// The polynomial route's candidates before the Newton polish on SO(3): simple roots come out to
// ~1e-12, double roots (two equilibria about to be born) to ~√ε ≈ 1.5e-8; 1e-6 leaves room and
// still fails for a wrong route that the polish would otherwise repair.
constexpr double kRouteAccuracy = 1e-6;
double max_polish = 0.0;

void expect_counts_agree(const Body& body, std::mt19937& rng, std::set<std::size_t>& counts) {
  const CircularOrbitModel model(body, CircularOrbit::from_rate(1.0));
  const RelativeEquilibriumSet set = find_relative_equilibria(model);
  const std::vector<Mat3> ms = multistart(model, 1500, rng);
  const auto n = set.equilibria.size();
  EXPECT_EQ(n, ms.size()) << "I = " << format_vector(body.inertia())
                          << ", k = " << format_vector(body.gyrostat());
  EXPECT_EQ(set.unverified, 0);
  EXPECT_GE(n, 8u);
  EXPECT_LE(n, 24u);
  EXPECT_LT(set.resultant_tail, kResultantTail);
  // Every multistart solution is in the list.
  for (const Mat3& S : ms) {
    const bool listed =
        std::any_of(set.equilibria.begin(), set.equilibria.end(), [&](const auto& e) {
          return (e.gamma - S.col(0)).cwiseAbs().maxCoeff() < 1e-6 &&
                 (e.normal - S.col(2)).cwiseAbs().maxCoeff() < 1e-6;
        });
    EXPECT_TRUE(listed) << "missed γ = " << format_vector(S.col(0))
                        << ", n = " << format_vector(S.col(2));
  }
  for (const auto& e : set.equilibria) {
    EXPECT_LT(e.residual, 1e-12);
  }
  max_polish = std::max(max_polish, set.polish_distance);
  EXPECT_LT(set.polish_distance, kRouteAccuracy);
  counts.insert(n);
}

TEST(RelativeEquilibria, GyrostatCountMatchesMultistartSearch) {
  std::mt19937 rng(20240516);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> normal;
  std::set<std::size_t> counts;
  for (int trial = 0; trial < 24; ++trial) {
    Vec3 I;
    do {
      I = Vec3(0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng));
    } while (I.maxCoeff() > I.sum() - I.maxCoeff());
    const double size = std::pow(10.0, -1.5 + 2.5 * u(rng));  // |k| from 0.03 to 10
    const Vec3 k = size * Vec3(normal(rng), normal(rng), normal(rng));
    expect_counts_agree(Body::from_principal(I, 1.0, Vec3::Zero(), k), rng, counts);
  }
  std::string list;
  for (auto c : counts) list += std::to_string(c) + " ";
  RecordProperty("counts", list);
  RecordProperty("max_polish_distance", format_number(max_polish));
  EXPECT_GE(counts.size(), 3u) << "counts seen: " << list;  // the sample spans several regimes
}

TEST(RelativeEquilibria, GyrostatWithVanishingComponents) {
  std::mt19937 rng(7);
  std::set<std::size_t> counts;
  const Vec3 I(1.0, 1.6, 2.1);
  for (const Vec3& k :
       {Vec3(0.3, 0.0, 0.0), Vec3(0.0, 0.9, 0.0), Vec3(0.0, 0.0, 2.5), Vec3(0.2, -0.3, 0.0),
        Vec3(0.0, 1.1, 0.7), Vec3(1.5, 0.0, -2.0), Vec3(0.05, 0.0, 0.0)}) {
    expect_counts_agree(Body::from_principal(I, 1.0, Vec3::Zero(), k), rng, counts);
  }
}

TEST(RelativeEquilibria, RejectsSymmetricBodiesAndNonRotatingOrbits) {
  const Body sym = Body::from_principal(Vec3(1.0, 1.0, 1.5), 1.0, Vec3::Zero());
  EXPECT_THROW(find_relative_equilibria(CircularOrbitModel(sym, CircularOrbit::from_rate(1.0))),
               InputError);
  const Body body = test::orbit_body();
  EXPECT_THROW(find_relative_equilibria(CircularOrbitModel(body, CircularOrbit::forced(0.0, 3.0))),
               InputError);
}

}  // namespace
}  // namespace test_orbit_equilibria
}  // namespace newtop
