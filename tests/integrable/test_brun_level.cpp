// Brun's case on a level f ≠ 0: the sphero-conic coordinates with momenta are coordinates of the
// level (round trip to round-off), the relations M(u_s) + w_s²/P(u_s) = K hold with the coupling
// K of brun_coupling, the momenta carry the monopole bracket {p1, p2} (checked against a
// finite-difference Poisson bracket), and the Lax quadratic form and its spectral curve are those
// stated in brun_level.hpp.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "newtop/analysis/brun_level.hpp"
#include "newtop/model/integrals.hpp"
#include "support/problems.hpp"

namespace newtop {
namespace test_brun_level {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// As in test_brun_separation: ~50 operations on O(1) numbers and square roots of differences of
// the e_i (condition ≤ 10 for the bodies drawn): 64·10 ε.
constexpr double kRoundTrip = 640 * kEps;
// Central differences with step δ: truncation δ² |F‴|/6 ≲ 1e-10 (δ = 1e-5, derivatives O(1..10)
// away from the principal planes), rounding ε |F|/δ ≲ 1e-10, squared by the bilinear bracket.
constexpr double kFiniteDifference = 1e-6;
constexpr double kStep = 1e-5;

using test::random_brun_level;
using RandomLevel = test::RandomBrunLevel;

RandomLevel random_level(std::mt19937_64& rng) { return random_brun_level(rng); }

std::array<double, 3> working_signs(const BrunCurve& k, const State& s) {
  const State w = to_working_frame(k, s);
  return {std::copysign(1.0, w.gamma[0]), std::copysign(1.0, w.gamma[1]),
          std::copysign(1.0, w.gamma[2])};
}

/// The Poisson bracket of docs/model.md §4, {F, G} = ∇_m F·(m × ∇_m G + γ × ∇_γ G) + ∇_γ F·(γ × ∇_m
/// G), by central differences.
template <class F, class G>
double bracket(const F& f, const G& g, const State& x) {
  auto grad = [&](const auto& fn) {
    Eigen::Matrix<double, 6, 1> d;
    for (int i = 0; i < 6; ++i) {
      State a = x, b = x;
      (i < 3 ? a.m[i] : a.gamma[i - 3]) += kStep;
      (i < 3 ? b.m[i] : b.gamma[i - 3]) -= kStep;
      d[i] = (fn(a) - fn(b)) / (2 * kStep);
    }
    return d;
  };
  const auto dF = grad(f), dG = grad(g);
  const Vec3 Fm(dF[0], dF[1], dF[2]), Fg(dF[3], dF[4], dF[5]);
  const Vec3 Gm(dG[0], dG[1], dG[2]), Gg(dG[3], dG[4], dG[5]);
  return Fm.dot(x.m.cross(Gm) + x.gamma.cross(Gg)) + Fg.dot(x.gamma.cross(Gm));
}

TEST(BrunLevel, CoordinatesWithMomentaAreTheIdentityOnAnyLevel) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_level(L.model, L.x0);
    const State back = brun_state_from_point(k, brun_point(k, L.x0), working_signs(k, L.x0));
    // m is formed from w_s/P(u_s), both O(|u_s − e_i|) near a principal plane: the error grows
    // like (e3 − e1)/min|u_s − e_i|.
    const BrunPoint p = brun_point(k, L.x0);
    double near = k.e[2] - k.e[0];
    for (int s = 0; s < 2; ++s) {
      for (int i = 0; i < 3; ++i) near = std::min(near, std::abs(p.u[s] - k.e[i]));
    }
    const double scale = std::max(1.0, L.x0.m.norm()) * (k.e[2] - k.e[0]) / near;
    EXPECT_LT((back.m - L.x0.m).cwiseAbs().maxCoeff(), kRoundTrip * scale) << trial;
    EXPECT_LT((back.gamma - L.x0.gamma).cwiseAbs().maxCoeff(), kRoundTrip) << trial;
    EXPECT_NEAR(area(back), k.f, kRoundTrip * scale) << trial;
  }
}

TEST(BrunLevel, CoupledRelationsHoldWithTheCouplingK) {
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_level(L.model, L.x0);
    const BrunPoint p = brun_point(k, L.x0);
    const double K = brun_coupling(k, L.x0);
    // Terms of size |m|² (e3 − e1) and w²/P ≲ |m|² (e3 − e1)²/|u − e|: relative round-off.
    const double scale = std::max(1.0, L.x0.m.squaredNorm()) * std::pow(k.e[2] - k.e[0], 2);
    for (int s = 0; s < 2; ++s) {
      const double P = brun_P(k, p.u[s]);
      const double lhs = brun_M(k, p.u[s]) + p.w[s] * p.w[s] / P;
      const double tol = 1e3 * kEps * scale * std::max(1.0, 1.0 / std::abs(P));
      EXPECT_NEAR(lhs, K, tol) << trial << " s=" << s;
    }
  }
  // On f = 0 the coupling vanishes and the relations are w_s² = R(u_s).
  const QuadraticModel model{Body::from_principal(Vec3(1, 1.5, 2.2), 1.0, Vec3::Zero()),
                             QuadraticField::brun(0.8)};
  const Vec3 g = Vec3(0.48, -0.6, 0.64).normalized();
  Vec3 m(0.5, 1.65, -0.88);
  m -= m.dot(g) * g;
  const BrunCurve k = brun_level(model, State{m, g});
  // (f is zero to rounding after the projection.)
  EXPECT_NEAR(brun_coupling(k, State{m, g}), 0.0, 64 * kEps);
}

TEST(BrunLevel, CouplingAndIntegralsInSeparatedCoordinates) {
  // K, h and c from (u, w, S) alone (brun_coupling_at, brun_integrals_at) against K from the
  // state and the integrals of the model: the level written in its sphero-conic coordinates.
  std::mt19937_64 rng(16);
  for (int trial = 0; trial < 200; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_level(L.model, L.x0);
    const BrunPoint p = brun_point(k, L.x0);
    const auto S = working_signs(k, L.x0);
    // As in CoupledRelationsHoldWithTheCouplingK: terms of size |m|² (e3 − e1)² divided by
    // |P(u_s)| and, for h and c, by u2 − u1.
    double P = 1.0;
    for (int s = 0; s < 2; ++s) P = std::min(P, std::abs(brun_P(k, p.u[s])));
    const double scale = std::max(1.0, L.x0.m.squaredNorm()) * std::pow(k.e[2] - k.e[0], 2) / P;
    const double tol = 1e3 * kEps * scale;
    EXPECT_NEAR(brun_coupling_at(k, p, S), brun_coupling(k, L.x0), tol) << trial;
    const BrunIntegrals I = brun_integrals_at(k, p, S);
    const double spread = tol / (p.u[1] - p.u[0]);
    EXPECT_NEAR(I.c, brun(L.model, L.x0), spread) << trial;
    EXPECT_NEAR(I.h, energy(L.model, L.x0), spread / k.kappa) << trial;
    // Routh's form: with t1 = w1/√P(u1), t2 = w2/√(−P(u2)) and ε = S1S2S3,
    // 2κh = −[u2 (t1 − fε√(−P(u2))/u2)² + u1 (t2 − fε√P(u1)/u1)²]/(u2 − u1) + λu1u2
    //       + f²κ²/(u1u2): the amended potential f²/(2γ·Iγ) (u1u2 = κ γ·Iγ) is of Stäckel form;
    // only the gyroscopic shift of the momenta couples u1 and u2.
    const double r1 = std::sqrt(brun_P(k, p.u[0])), r2 = std::sqrt(-brun_P(k, p.u[1]));
    const double eps = S[0] * S[1] * S[2], f = k.f, u1 = p.u[0], u2 = p.u[1];
    const double a1 = p.w[0] / r1 - f * eps * r2 / u2, a2 = p.w[1] / r2 - f * eps * r1 / u1;
    const double routh = -(u2 * a1 * a1 + u1 * a2 * a2) / (u2 - u1) + k.lambda_ * u1 * u2 +
                         f * f * k.kappa * k.kappa / (u1 * u2);
    EXPECT_NEAR(routh, 2 * k.kappa * energy(L.model, L.x0), 2 * spread) << trial;
  }
}

TEST(BrunLevel, MomentaCarryTheMonopoleBracket) {
  std::mt19937_64 rng(13);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_level(L.model, L.x0);
    const State w = to_working_frame(k, L.x0);
    if (w.gamma.cwiseAbs().minCoeff() < 0.15) continue;  // near a principal plane: stiff
    auto u = [&](int s) { return [&k, s](const State& x) { return brun_point(k, x).u[s]; }; };
    auto p = [&](int s) {
      return [&k, s](const State& x) {
        const BrunPoint q = brun_point(k, x);
        return q.w[s] / (2 * brun_P(k, q.u[s]));
      };
    };
    const double scale = std::max(1.0, L.x0.m.squaredNorm());
    EXPECT_NEAR(bracket(u(0), u(1), L.x0), 0.0, kFiniteDifference) << trial;
    EXPECT_NEAR(bracket(u(0), p(0), L.x0), -1.0, kFiniteDifference * scale) << trial;
    EXPECT_NEAR(bracket(u(1), p(1), L.x0), -1.0, kFiniteDifference * scale) << trial;
    EXPECT_NEAR(bracket(u(0), p(1), L.x0), 0.0, kFiniteDifference * scale) << trial;
    // The real momenta of Routh's form, t1 = w1/√P(u1), t2 = w2/√(−P(u2)):
    // {t1, t2} = −4√(−P(u1)P(u2)) {p1, p2} = −εf(u2 − u1), ε = S1S2S3.
    auto t = [&](int s) {
      return [&k, s](const State& x) {
        const BrunPoint q = brun_point(k, x);
        return q.w[s] / std::sqrt(std::abs(brun_P(k, q.u[s])));
      };
    };
    const BrunPoint q0 = brun_point(k, L.x0);
    const auto S = working_signs(k, L.x0);
    const double ft = -S[0] * S[1] * S[2] * k.f * (q0.u[1] - q0.u[0]);
    EXPECT_NEAR(bracket(t(0), t(1), L.x0), ft,
                kFiniteDifference * scale * std::max(1.0, std::abs(ft)))
        << trial;
    const double expected = brun_momentum_bracket(k, L.x0);
    EXPECT_NEAR(bracket(p(0), p(1), L.x0), expected,
                kFiniteDifference * scale * std::max(1.0, std::abs(expected)))
        << trial;
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

TEST(BrunLevel, LaxQuadraticFormIsNPlusTwoRootLambdaFV) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_level(L.model, L.x0);
    const std::complex<double> u(6 * U(rng), 3 * U(rng));
    const auto X = brun_lax(k, L.x0, u);
    std::complex<double> v(1.0);
    for (int i = 0; i < 3; ++i) v *= std::sqrt(u - k.e[i]);
    const std::complex<double> N =
        (k.lambda_ * u + (k.c - k.lambda_ * (k.e[0] + k.e[1] + k.e[2]))) * u + 2 * k.kappa * k.h;
    const std::complex<double> rhs = N + 2.0 * std::sqrt(std::complex<double>(k.lambda_)) * k.f * v;
    const std::complex<double> lhs = X[0] * X[0] + X[1] * X[1] + X[2] * X[2];
    // Sums of terms |m|² |u − e| and |λ| |P(u)|, each to a few ε.
    const double scale = std::max(1.0, L.x0.m.squaredNorm()) * std::pow(std::abs(u) + 5.0, 3);
    EXPECT_LT(std::abs(lhs - rhs), 64 * kEps * scale) << trial;
  }
}

TEST(BrunLevel, RationalLaxMatrixIsIsospectralWithTheBigonalCurve) {
  // −ℓ det(μ − L(ℓ)) = λ z² P(v) + z N(v) + f² with v = −μ/(λℓ), z = λℓ² at random complex ℓ, μ:
  // the characteristic polynomial is a function of h, c, f alone (so conserved).
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_level(L.model, L.x0);
    const std::complex<double> l(2 * U(rng), 2 * U(rng)), mu(4 * U(rng), 4 * U(rng));
    const Eigen::Matrix3cd Lax = brun_rational_lax(k, L.x0, l);
    const std::complex<double> lhs = -l * (mu * Eigen::Matrix3cd::Identity() - Lax).determinant();
    const std::complex<double> v = -mu / (k.lambda_ * l), z = k.lambda_ * l * l;
    std::complex<double> P(1.0);
    for (int i = 0; i < 3; ++i) P *= v - k.e[i];
    const std::complex<double> N =
        (k.lambda_ * v + (k.c - k.lambda_ * (k.e[0] + k.e[1] + k.e[2]))) * v + 2 * k.kappa * k.h;
    const std::complex<double> rhs = k.lambda_ * z * z * P + z * N + k.f * k.f;
    // Sums of products of three entries of size ≤ |ℓ||λe| + |μ| + |m| + 1/|ℓ|, times |ℓ|: a few ε
    // of entry³|ℓ| (≤ 0.73 ε measured); 64 ε.
    const double entry =
        std::abs(l) * std::abs(k.lambda_ * k.e[0]) + std::abs(mu) + L.x0.m.norm() + 1 / std::abs(l);
    EXPECT_LT(std::abs(lhs - rhs), 64 * kEps * std::pow(entry, 3) * std::abs(l)) << trial;
  }
}

TEST(BrunLevel, SpectralCurveBranchPointsAreTheRootsOfD) {
  std::mt19937_64 rng(15);
  for (int trial = 0; trial < 100; ++trial) {
    const RandomLevel L = random_level(rng);
    const BrunCurve k = brun_level(L.model, L.x0);
    const BrunSpectralCurve g = brun_spectral_curve(k);
    for (const auto& r : g.branch_point) {
      // D(r) = (N − 2√λ f v)(N + 2√λ f v) at r: one factor vanishes, checked independently.
      std::complex<double> v(1.0);
      for (int i = 0; i < 3; ++i) v *= std::sqrt(r - k.e[i]);
      const std::complex<double> N =
          (k.lambda_ * r + (k.c - k.lambda_ * (k.e[0] + k.e[1] + k.e[2]))) * r + 2 * k.kappa * k.h;
      const std::complex<double> t = 2.0 * std::sqrt(std::complex<double>(k.lambda_)) * k.f * v;
      const double size = std::abs(N) + std::abs(t) + 1.0;
      EXPECT_LT(std::min(std::abs(N - t), std::abs(N + t)), 1e-9 * size) << trial;
    }
  }
}

TEST(BrunLevel, SmallAreaSplitsEachRootOfNAsPredicted) {
  // D = N² − 4λf²P: near a simple root ν of N, |u − ν| = 2|f| √|λ P(ν)| / |N′(ν)| + O(f²).
  const QuadraticModel model{Body::from_principal(Vec3(1, 1.5, 2.2), 1.0, Vec3::Zero()),
                             QuadraticField::brun(0.8)};
  const Vec3 g = Vec3(0.48, -0.6, 0.64).normalized();
  Vec3 m0(0.5, 1.65, -0.88);
  m0 -= m0.dot(g) * g;
  // (N is that of the perturbed level itself: h and c move by O(f).)
  const double f = 1e-4;
  const BrunCurve k = brun_level(model, State{m0 + f * g, g});
  const BrunSpectralCurve sc = brun_spectral_curve(k);
  for (double nu : k.nu) {
    const double dN = 2 * k.lambda_ * nu + (k.c - k.lambda_ * (k.e[0] + k.e[1] + k.e[2]));
    const double split = 2 * f * std::sqrt(std::abs(k.lambda_ * brun_P(k, nu))) / std::abs(dN);
    int near = 0;
    for (const auto& r : sc.branch_point) {
      // The next term is O(f²): relative O(f) to the split.
      if (std::abs(std::abs(r - nu) - split) < 1e-2 * split) ++near;
    }
    EXPECT_EQ(near, 2) << nu;
  }
}

}  // namespace
}  // namespace test_brun_level
}  // namespace newtop
