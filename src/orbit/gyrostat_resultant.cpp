// The branch of relative equilibria with every active Δ_i ≠ 0 (docs/orbit.md §6.3): the real
// intersections of the plane cubic F1 = Σ h_i²/Δ_i − κ = 0 and the plane quartic
// F2 = ε²(S2 − S1²/S0) − 1 = 0 in the multipliers (p, q).

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "equilibria_detail.hpp"

namespace newtop::orbit_detail {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// A colleague-matrix eigenvalue is a candidate real root when its imaginary part (in the scaled
// variable x ∈ [−1, 1]) is below 1e-6: simple roots come out to ~ε·cond, double roots (tangent
// curves, where two equilibria are born) to ~√ε; Newton then decides.
constexpr double kImagTolerance = 1e-6;
// |F1| and |F2| relative to the sums of the magnitudes of their terms at an accepted root: Newton
// reaches a few ε; 1e-10 leaves room and rejects the near-real complex pairs, where the residuals
// stay bounded away from 0 (the orientation is then polished on SO(3) and checked as a fixed
// point).
constexpr double kAcceptResidual = 1e-10;
// Two polished roots closer than this (relative) are one.
constexpr double kSameRoot = 1e-8;

struct Plane {
  const EquilibriumProblem& pb;
  std::vector<int> A;
  double e(int i, double p) const { return pb.eps * pb.I[i] * pb.I[i] + p * pb.I[i]; }
  double h2(int i) const { return pb.h[i] * pb.h[i]; }
};

/// Σ_{i ∈ A, i ∉ {a, b}} h_i²/(q + e_i) − κ.
double others(const Plane& pl, double p, double q, int a, int b) {
  double s = -pl.pb.kappa;
  for (int i : pl.A) {
    if (i != a && i != b) s += pl.h2(i) / (q + pl.e(i, p));
  }
  return s;
}

/// The |A| real roots q of Σ h_i²/(q + e_i) = κ at fixed p: one between consecutive poles
/// q = −e_i (where the function falls from +∞ to −∞) and one right of the last pole. Each is
/// found by TOMS 748 on the function times its two bracketing pole factors (no poles inside).
std::vector<double> q_branches(const Plane& pl, double p) {
  std::vector<std::pair<double, int>> poles;
  for (int i : pl.A) poles.push_back({-pl.e(i, p), i});
  std::sort(poles.begin(), poles.end());
  std::vector<double> roots;
  boost::math::tools::eps_tolerance<double> tol(50);
  for (std::size_t k = 0; k + 1 < poles.size(); ++k) {
    const double lo = poles[k].first, hi = poles[k + 1].first;
    const int a = poles[k].second, b = poles[k + 1].second;
    if (!(hi > lo)) {
      roots.push_back(lo);  // coincident poles pinch the branch onto them
      continue;
    }
    auto phi = [&](double q) {
      const double qa = q + pl.e(a, p), qb = q + pl.e(b, p);
      return -(pl.h2(a) * qb + pl.h2(b) * qa + qa * qb * others(pl, p, q, a, b));
    };
    std::uintmax_t it = 200;
    const auto r = boost::math::tools::toms748_solve(phi, lo, hi, pl.h2(a) * (hi - lo),
                                                     -pl.h2(b) * (hi - lo), tol, it);
    roots.push_back(0.5 * (r.first + r.second));
  }
  const double last = poles.back().first;
  const int z = poles.back().second;
  double sum_h2 = 0;
  for (int i : pl.A) sum_h2 += pl.h2(i);
  const double hi = last + sum_h2 / pl.pb.kappa;
  auto phi = [&](double q) { return pl.h2(z) + (q + pl.e(z, p)) * others(pl, p, q, z, z); };
  const double f_hi = phi(hi);
  if (f_hi >= 0) {
    roots.push_back(hi);
  } else {
    std::uintmax_t it = 200;
    const auto r = boost::math::tools::toms748_solve(phi, last, hi, pl.h2(z), f_hi, tol, it);
    roots.push_back(0.5 * (r.first + r.second));
  }
  return roots;
}

/// The quartic in product form, ε² Σ_{i<k} h_i² h_k² (I_i − I_k)² Π_{j≠i,k} Δ_j² −
/// Σ_i h_i² Π_{k≠i} Δ_k² (F2 times Π Δ_i² S0): a polynomial, finite at the poles.
double quartic(const Plane& pl, double p, double q) {
  const auto& A = pl.A;
  const double eps2 = pl.pb.eps * pl.pb.eps;
  auto D = [&](int i) { return q + pl.e(i, p); };
  double v = 0;
  for (std::size_t x = 0; x < A.size(); ++x) {
    double prod = pl.h2(A[x]);
    for (std::size_t y = 0; y < A.size(); ++y) {
      if (y != x) prod *= D(A[y]) * D(A[y]);
    }
    v -= prod;
    for (std::size_t y = x + 1; y < A.size(); ++y) {
      const double dI = pl.pb.I[A[x]] - pl.pb.I[A[y]];
      double pair = eps2 * pl.h2(A[x]) * pl.h2(A[y]) * dI * dI;
      for (std::size_t w = 0; w < A.size(); ++w) {
        if (w != x && w != y) pair *= D(A[w]) * D(A[w]);
      }
      v += pair;
    }
  }
  return v;
}

struct Residual {
  Eigen::Vector2d f;      // (F1, F2)
  Eigen::Vector2d scale;  // sums of the magnitudes of their terms (round-off scale)
  Eigen::Matrix2d J;      // ∂(F1, F2)/∂(p, q)
};

/// F1 = Σ h_i²/Δ_i − κ and F2 = ε² P/S0 − 1 with P = S0 S2 − S1² = Σ_{i<k} ξ_i² ξ_k² (I_i − I_k)²
/// (written as that sum: no cancellation), ξ_i = h_i/Δ_i.
Residual residual(const Plane& pl, double p, double q) {
  const double eps2 = pl.pb.eps * pl.pb.eps;
  Vec3 x = Vec3::Zero(), d = Vec3::Ones();
  double f1 = -pl.pb.kappa, s1 = pl.pb.kappa, S0 = 0, P = 0;
  for (int i : pl.A) {
    d[i] = q + pl.e(i, p);
    x[i] = pl.h2(i) / (d[i] * d[i]);
    f1 += pl.h2(i) / d[i];
    s1 += std::abs(pl.h2(i) / d[i]);
    S0 += x[i];
  }
  Vec3 dP = Vec3::Zero();  // ∂P/∂x_i
  for (int i : pl.A) {
    for (int k : pl.A) {
      const double dI2 = (pl.pb.I[i] - pl.pb.I[k]) * (pl.pb.I[i] - pl.pb.I[k]);
      dP[i] += x[k] * dI2;
      if (k > i) P += x[i] * x[k] * dI2;
    }
  }
  Residual r{{f1, eps2 * P / S0 - 1.0}, {s1, 1.0 + eps2 * P / S0}, Eigen::Matrix2d::Zero()};
  for (int i : pl.A) {
    const double I = pl.pb.I[i];
    const double d1 = -pl.h2(i) / (d[i] * d[i]);                 // ∂F1/∂Δ_i
    const double dx = -2.0 * x[i] / d[i];                        // ∂x_i/∂Δ_i
    const double d2 = eps2 * (dP[i] * S0 - P) / (S0 * S0) * dx;  // ∂F2/∂Δ_i
    r.J(0, 0) += I * d1;  // ∂Δ_i/∂p = I_i, ∂Δ_i/∂q = 1
    r.J(0, 1) += d1;
    r.J(1, 0) += I * d2;
    r.J(1, 1) += d2;
  }
  return r;
}

/// Newton's method on (F1, F2) from (p, q); keeps the iterate of least scaled residual and
/// accepts it when that is below kAcceptResidual.
bool polish(const Plane& pl, double& p, double& q) {
  auto size = [](const Residual& r) {
    return std::max(std::abs(r.f[0]) / r.scale[0], std::abs(r.f[1]) / r.scale[1]);
  };
  Residual r = residual(pl, p, q);
  double best = size(r), bp = p, bq = q;
  for (int it = 0; it < 60 && r.f.allFinite() && r.J.allFinite(); ++it) {
    const Eigen::Vector2d d = r.J.fullPivLu().solve(-r.f);
    if (!d.allFinite()) break;
    p += d[0];
    q += d[1];
    r = residual(pl, p, q);
    if (r.f.allFinite() && size(r) < best) {
      best = size(r);
      bp = p;
      bq = q;
    }
    if (std::abs(d[0]) + std::abs(d[1]) <= 4 * kEps * (1 + std::abs(p) + std::abs(q))) break;
  }
  p = bp;
  q = bq;
  return best <= kAcceptResidual;
}

/// Real roots in [−1, 1] of Σ c_k T_k(x): eigenvalues of the colleague matrix.
std::vector<double> colleague_real_roots(Eigen::VectorXd c) {
  const double size = c.cwiseAbs().maxCoeff();
  Eigen::Index n = c.size() - 1;
  while (n > 0 && std::abs(c[n]) <= 1e-14 * size) --n;  // leading zeros: lower degree
  if (n < 1) return {};
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  if (n == 1) return {-c[0] / c[1]};
  M(0, 1) = 1.0;
  for (Eigen::Index k = 1; k < n; ++k) {
    M(k, k - 1) = 0.5;
    if (k + 1 < n) M(k, k + 1) = 0.5;
  }
  for (Eigen::Index j = 0; j < n; ++j) M(n - 1, j) -= c[j] / (2.0 * c[n]);
  const Eigen::VectorXcd z = Eigen::EigenSolver<Eigen::MatrixXd>(M, false).eigenvalues();
  std::vector<double> roots;
  for (const auto& r : z) {
    if (std::abs(r.imag()) <= kImagTolerance && std::abs(r.real()) <= 1.0 + kImagTolerance) {
      roots.push_back(r.real());
    }
  }
  return roots;
}

}  // namespace

void add_from_amplitudes(const EquilibriumProblem& pb, const Vec3& xi,
                         std::vector<Orientation>& out) {
  const Vec3 x2 = xi.cwiseProduct(xi);
  const double S0 = x2.sum(), S1 = x2.dot(pb.I);
  const double a = pb.eps * S1 / S0, c = 1.0 / std::sqrt(S0);
  const Vec3 n = -(pb.eps * pb.I - Vec3::Constant(a)).cwiseProduct(xi);
  for (double sign : {1.0, -1.0}) out.push_back({(-sign * c * xi).normalized(), n.normalized()});
}

double solve_free_branch(const EquilibriumProblem& pb, const std::vector<int>& active,
                         std::vector<Orientation>& out) {
  const Plane pl{pb, active};
  const int na = static_cast<int>(active.size());
  const int degree = na * (2 * na - 2);  // Bezout: (cubic or conic) × (quartic or conic)
  // A priori range of p = εb − a: a = ε γ·Iγ ∈ ε[I_min, 1], b = −n·In − h·n ∈
  // [−1 − |h|, −I_min + |h|] (moments in units of the largest); widened by 1%.
  const double hn = pb.h.norm(), Imin = pb.I.minCoeff();
  const double lo = -pb.eps * (2.0 + hn), hi = pb.eps * (hn - 2.0 * Imin);
  const double mid = 0.5 * (lo + hi), half = 0.505 * (hi - lo);
  // The resultant Π_b quartic(p, q_b(p)) is a polynomial of the given degree in p: interpolate it
  // at 2·degree + 1 Chebyshev points (the coefficients above the degree measure round-off).
  const int N = 2 * degree + 1;
  Eigen::VectorXd g(N), c = Eigen::VectorXd::Zero(N);
  for (int j = 0; j < N; ++j) {
    const double x = std::cos(std::numbers::pi * (j + 0.5) / N), p = mid + half * x;
    double v = 1.0;
    for (double q : q_branches(pl, p)) v *= quartic(pl, p, q);
    g[j] = v;
  }
  for (int k = 0; k < N; ++k) {
    for (int j = 0; j < N; ++j) c[k] += g[j] * std::cos(std::numbers::pi * k * (j + 0.5) / N);
    c[k] *= (k == 0 ? 1.0 : 2.0) / N;
  }
  const double size = c.cwiseAbs().maxCoeff();
  const double tail = size > 0 ? c.tail(N - degree - 1).cwiseAbs().maxCoeff() / size : 0.0;
  std::vector<std::pair<double, double>> found;
  for (double x : colleague_real_roots(c.head(degree + 1))) {
    double p = mid + half * x;
    // The branch through the root: the one where F2 is smallest.
    double best_q = 0, best = std::numeric_limits<double>::infinity();
    for (double q : q_branches(pl, p)) {
      const double f2 = std::abs(residual(pl, p, q).f[1]);
      if (f2 < best) {
        best = f2;
        best_q = q;
      }
    }
    double q = best_q;
    if (!polish(pl, p, q)) continue;
    const bool seen = std::any_of(found.begin(), found.end(), [&](const auto& r) {
      return std::abs(r.first - p) <= kSameRoot * (1 + std::abs(p)) &&
             std::abs(r.second - q) <= kSameRoot * (1 + std::abs(q));
    });
    if (seen) continue;
    found.push_back({p, q});
    Vec3 xi = Vec3::Zero();
    for (int i : active) xi[i] = pb.h[i] / (q + pl.e(i, p));
    add_from_amplitudes(pb, xi, out);
  }
  return tail;
}

}  // namespace newtop::orbit_detail
