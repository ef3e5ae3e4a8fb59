// Equilibria at rest in the exact and multipole fields (docs/model.md §7): the search on the sphere
// against a brute-force grid of V, the count rule, convergence to the quadratic model's equilibria
// far from the body, and the linearisation with the field's own moment Jacobian.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "bodies.hpp"
#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/analysis/stability.hpp"

namespace newtop {
namespace test_field_equilibria {
namespace {

constexpr double kPi = std::numbers::pi;

/// Local minima (−1) and maxima (+1) of V on a latitude–longitude grid of n × 2n cells: points
/// below (above) their 8 neighbours, the rows next to the poles left out.
struct GridExtremum {
  Vec3 gamma;
  int sign;
};
std::vector<GridExtremum> grid_extrema(const Model& m, int n) {
  auto at = [&](int i, int j) {
    const double th = kPi * (i + 0.5) / n, ph = kPi * j / n;
    return Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
  };
  std::vector<std::vector<double>> V(n, std::vector<double>(2 * n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) V[i][j] = potential(m, at(i, j));
  std::vector<GridExtremum> out;
  for (int i = 1; i + 1 < n; ++i) {
    for (int j = 0; j < 2 * n; ++j) {
      bool lower = true, higher = true;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          if (di == 0 && dj == 0) continue;
          const double v = V[i + di][(j + dj + 2 * n) % (2 * n)];
          lower = lower && V[i][j] < v;
          higher = higher && V[i][j] > v;
        }
      }
      if (lower || higher) out.push_back({at(i, j), lower ? -1 : 1});
    }
  }
  return out;
}

double nearest(const std::vector<Equilibrium>& eq, const Vec3& g, EquilibriumType type) {
  double d = 10.0;
  for (const Equilibrium& e : eq) {
    if (e.type == type) d = std::min(d, (e.gamma - g).norm());
  }
  return d;
}

TEST(FieldEquilibria, AgreeWithABruteForceGridAndTheCountRule) {
  // Four points (r0 ≠ 0) and the offset box near the body, where the octupole and beyond move
  // and may add equilibria; the multipole field of order 5 of the box as well.
  const auto points = test::cases()[1].model, box = test::cases()[3].model;
  const std::vector<std::pair<std::string, Model>> models{
      {"exact points R = 1.6r", Model::exact(points, 1.0, 1.6 * max_radius(*points))},
      {"exact box R = 1.3r", Model::exact(box, 1.0, 1.3 * max_radius(*box))},
      {"multipole box", Model::multipole(box, 5, 1.0, 2.0 * max_radius(*box))},
  };
  const int n = 90;  // grid step π/90 = 0.035 rad
  const double match = 3 * kPi / n;
  for (const auto& [name, m] : models) {
    const EquilibriumSet set = find_equilibria(m);
    ASSERT_FALSE(set.equilibria.empty()) << name;
    EXPECT_TRUE(set.count_rule_holds()) << name << ": " << set.minima << " - " << set.saddles
                                        << " + " << set.maxima << ", " << set.degenerate;
    for (const Equilibrium& e : set.equilibria) {
      EXPECT_NEAR(e.gamma.norm(), 1.0, 1e-14) << name;
      EXPECT_LE(moment(m, e.gamma).norm(), 1e-10 * grad_gamma(m, e.gamma).norm()) << name;
      EXPECT_DOUBLE_EQ(e.potential, potential(m, e.gamma)) << name;
    }
    int grid_minima = 0, grid_maxima = 0;
    for (const GridExtremum& x : grid_extrema(m, n)) {
      const auto type = x.sign < 0 ? EquilibriumType::minimum : EquilibriumType::maximum;
      (x.sign < 0 ? grid_minima : grid_maxima)++;
      EXPECT_LE(nearest(set.equilibria, x.gamma, type), match)
          << name << ": grid extremum at " << x.gamma.transpose() << " not found";
    }
    EXPECT_EQ(grid_minima, set.minima) << name;
    EXPECT_EQ(grid_maxima, set.maxima) << name;
  }
}

/// Largest distance from an equilibrium of `a` to the nearest of `b` (same type).
double farthest(const EquilibriumSet& a, const EquilibriumSet& b) {
  double d = 0;
  for (const Equilibrium& e : a.equilibria) d = std::max(d, nearest(b.equilibria, e.gamma, e.type));
  return d;
}

TEST(FieldEquilibria, ConvergeToTheQuadraticModelsFarFromTheBody) {
  // The octupole moves the equilibria by O(r/R) against the quadrupole (offset box: r0 ≠ 0 but
  // small enough that both terms count): the distance falls at least 5× per decade of R.
  const auto box = test::cases()[3].model;
  const double r = max_radius(*box);
  double previous = 0;
  for (double q : {10.0, 100.0, 1000.0}) {
    const Model m = Model::exact(box, 1.0, q * r);
    const EquilibriumSet ex = find_equilibria(m);
    const EquilibriumSet quad = find_equilibria(quadratic_approximation(m));
    ASSERT_EQ(ex.equilibria.size(), quad.equilibria.size()) << "R/r = " << q;
    EXPECT_EQ(ex.minima, quad.minima);
    EXPECT_EQ(ex.saddles, quad.saddles);
    const double d = std::max(farthest(ex, quad), farthest(quad, ex));
    std::printf("R/r = %6g   max distance to the quadratic model's equilibria %.3e\n", q, d);
    if (previous > 0) {
      EXPECT_LT(d, previous / 5) << "R/r = " << q;
    }
    previous = d;
  }
}

TEST(FieldEquilibria, JacobianIsTheFieldsAgainstFiniteDifferencesOfRhs) {
  const auto points = test::cases()[1].model;
  const Model m = Model::exact(points, 2.0, 2.0 * max_radius(*points));
  const State s =
      state_from_omega(m.body(), Vec3(0.3, -0.2, 0.5), Vec3(0.2, 0.6, -0.7).normalized());
  const Mat6 J = jacobian(m, s);
  const double h = 1e-6;
  Mat6 D;
  for (int j = 0; j < 6; ++j) {
    State p = s, q = s;
    (j < 3 ? p.m[j] : p.gamma[j - 3]) += h;
    (j < 3 ? q.m[j] : q.gamma[j - 3]) -= h;
    const State fp = rhs(m, p), fq = rhs(m, q);
    D.col(j).head<3>() = (fp.m - fq.m) / (2 * h);
    D.col(j).tail<3>() = (fp.gamma - fq.gamma) / (2 * h);
  }
  // Central differences: error h² |f‴| ~ 1e-12 of the entries, round-off ε|f|/h ~ 1e-10.
  EXPECT_LE((J - D).norm(), 1e-8 * J.norm()) << J << "\n\n" << D;
}

TEST(FieldEquilibria, MinimumIsStableAndSaddleUnstableInTheExactField) {
  // The centred box (r0 = 0): two minima, two saddles and two maxima near the principal axes.
  const auto box = test::cases()[2].model;
  const Model m = Model::exact(box, 1.0, 1.5 * max_radius(*box));
  const EquilibriumSet set = find_equilibria(m);
  int checked = 0;
  for (const Equilibrium& e : set.equilibria) {
    if (e.type == EquilibriumType::degenerate) continue;
    const State s = state_from_omega(m.body(), Vec3::Zero(), e.gamma);
    const Spectrum sp = linear_stability(m, s);
    if (e.type == EquilibriumType::minimum) {
      EXPECT_TRUE(sp.linearly_stable);
      EXPECT_EQ(sp.lyapunov_stable, std::optional<bool>(true));
    } else {
      EXPECT_FALSE(sp.linearly_stable) << to_string(e.type);  // a real eigenvalue pair ±√|h|
    }
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

TEST(FieldRotations, EverySampledAxisIsAPermanentRotationOfTheExactField) {
  // Each admissible axis with Ω = √Ω² is a fixed point of the exact field's equations (residual
  // of d(m, γ)/dt relative to its terms; the bisection leaves ~1e-16 rad), and the quadratic
  // model's cone is not: the exact field's curve differs from it by O(r/R) near the body.
  const auto box = test::cases()[3].model;
  const Model m = Model::exact(box, 1.0, 2.0 * max_radius(*box));
  const RotationFamilies f = permanent_rotations(m, 40);
  std::size_t admissible = 0, off_quadratic = 0;
  const QuadraticModel q = quadratic_approximation(m);
  for (const ConeAxis& c : f.cone) {
    if (!c.admissible || c.omega_squared == 0.0) continue;
    ++admissible;
    const State s = permanent_rotation(m.body(), c.gamma, std::sqrt(c.omega_squared));
    EXPECT_LE(fixed_point_residual(m, s), 1e-9) << c.gamma.transpose();
    off_quadratic += fixed_point_residual(q, s) > 1e-6;
  }
  EXPECT_GT(admissible, 40u);
  EXPECT_GT(off_quadratic, admissible / 2);
}

}  // namespace
}  // namespace test_field_equilibria
}  // namespace newtop
