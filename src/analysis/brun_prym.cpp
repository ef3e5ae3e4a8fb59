#include "newtop/analysis/brun_prym.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>

#include "newtop/core/types.hpp"

namespace newtop {
namespace {

using Complex = std::complex<double>;
using Sums = std::array<Complex, 2>;

// Newton steps to polish a companion-matrix root of the cubic (quadratic convergence).
constexpr int kPrymPolishSteps = 3;
// Gauss–Legendre nodes per interval: spectral accuracy for the analytic state and sums of a
// motion.
constexpr int kNodes = 12;
// Bisection levels of brun_prym_abel_increment at most (an interval of 2⁻⁸ of the first).
constexpr int kMaxLevels = 8;
// A candidate whose eigenvalues agree with the ξ_j to this fraction of their size carries the
// divisor (the other candidates differ at O(1); a divisor found by inverting the Abel–Prym map
// carries its round-off amplified by the conditioning of that map, measured up to ~2e-7).
constexpr double kMatch = 1e-6;
// Relative round-off of a rate term (a polished root, the line, square roots): a few ε.
constexpr double kRoundOff = 4 * std::numeric_limits<double>::epsilon();

/// c_i = √(e_j − e_k), (i, j, k) cyclic.
std::array<Complex, 3> isotropic(const BrunCurve& k) {
  std::array<Complex, 3> c{};
  for (int i = 0; i < 3; ++i) c[i] = std::sqrt(Complex(k.e[(i + 1) % 3] - k.e[(i + 2) % 3]));
  return c;
}

/// A = Σ c_i m_i, B = −Σ c_i e_i m_i, C = Σ c_i γ_i of a working-frame state (or tangent vector).
BrunPrymLine line_of(const BrunCurve& k, const std::array<Complex, 3>& c, const State& w) {
  BrunPrymLine l{0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i) {
    l.A += c[i] * w.m[i];
    l.B -= c[i] * k.e[i] * w.m[i];
    l.C += c[i] * w.gamma[i];
  }
  return l;
}

Complex dP_of(const BrunCurve& k, Complex u) {
  return (u - k.e[1]) * (u - k.e[2]) + (u - k.e[0]) * (u - k.e[2]) + (u - k.e[0]) * (u - k.e[1]);
}

/// Gauss–Legendre nodes and weights on [−1, 1], ascending, and the spectral differentiation matrix
/// at the nodes (barycentric weights).
struct Rule {
  std::array<double, kNodes> x{}, w{};
  Eigen::Matrix<double, kNodes, kNodes> D;
  double norm = 0;  ///< ‖D‖∞
  Rule() {
    using G = boost::math::quadrature::gauss<double, kNodes>;
    const auto& a = G::abscissa();
    const auto& wt = G::weights();
    const int half = kNodes / 2;
    for (int i = 0; i < half; ++i) {
      x[half - 1 - i] = -a[i], w[half - 1 - i] = wt[i];
      x[half + i] = a[i], w[half + i] = wt[i];
    }
    std::array<double, kNodes> bary{};
    for (int i = 0; i < kNodes; ++i) {
      double p = 1.0;
      for (int j = 0; j < kNodes; ++j) p *= j == i ? 1.0 : x[i] - x[j];
      bary[i] = 1.0 / p;
    }
    for (int i = 0; i < kNodes; ++i) {
      double diag = 0.0;
      for (int j = 0; j < kNodes; ++j) {
        if (j == i) continue;
        D(i, j) = bary[j] / bary[i] / (x[i] - x[j]);
        diag -= D(i, j);
      }
      D(i, i) = diag;
    }
    norm = D.cwiseAbs().rowwise().sum().maxCoeff();
  }
};

const Rule& rule() {
  static const Rule r;
  return r;
}

struct Piece {
  Sums sum{};
  double noise = 0;  ///< round-off of sum (differentiation amplifies the nodes' noise)
};

/// One Gauss–Legendre interval [a, b]: the states at the nodes, their derivative by spectral
/// differentiation, and the rates of brun_prym_rate along it.
Piece piece(const BrunCurve& k, const BrunMotion& x, double a, double b) {
  const Rule& r = rule();
  const double half = 0.5 * (b - a);
  Eigen::Matrix<double, kNodes, 6> X;
  std::array<State, kNodes> node{};
  for (int n = 0; n < kNodes; ++n) {
    node[n] = x(a + half * (r.x[n] + 1));
    X.row(n) << node[n].m.transpose(), node[n].gamma.transpose();
  }
  const Eigen::Matrix<double, kNodes, 6> dX = r.D * X;  // d/dτ, τ ∈ [−1, 1]
  Piece p;
  for (int n = 0; n < kNodes; ++n) {
    const State d{dX.block<1, 3>(n, 0).transpose(), dX.block<1, 3>(n, 3).transpose()};
    const BrunPrymRate q = brun_prym_rate(k, node[n], d);
    p.sum[0] += r.w[n] * q.rate[0];
    p.sum[1] += r.w[n] * q.rate[1];
    // The nodes' noise, amplified by the differentiation, enters linearly through the magnitude
    // of the terms; the rates' own round-off through their error scale.
    p.noise += kRoundOff * r.w[n] * (r.norm * q.magnitude + q.error_scale);
  }
  return p;
}

double gap(const Sums& a, const Sums& b) {
  return std::max(std::abs(a[0] - b[0]), std::abs(a[1] - b[1]));
}

Piece refine(const BrunCurve& k, const BrunMotion& x, double a, double b, const Piece& whole,
             double tolerance, int level) {
  const double mid = 0.5 * (a + b);
  Piece left = piece(k, x, a, mid);
  Piece right = piece(k, x, mid, b);
  const Sums split{left.sum[0] + right.sum[0], left.sum[1] + right.sum[1]};
  // Converged, or the two levels differ by no more than their round-off: bisecting further only
  // adds round-off.
  const double floor = whole.noise + left.noise + right.noise;
  if (gap(split, whole.sum) <= std::max(tolerance, floor) || level >= kMaxLevels) {
    return {split, left.noise + right.noise};
  }
  left = refine(k, x, a, mid, left, tolerance / 2, level + 1);
  right = refine(k, x, mid, b, right, tolerance / 2, level + 1);
  return {{left.sum[0] + right.sum[0], left.sum[1] + right.sum[1]}, left.noise + right.noise};
}

/// ξ with X(u) × α(u) = iξ α(u) at a zero (u, v) of α·X, for a working-frame state x: X and α on
/// the lift (w1, w2, w3) of (u, v), ξ read off the largest component of α.
Complex eigenvalue(const BrunCurve& k, const std::array<Complex, 3>& c, const State& x, Complex u,
                   Complex v) {
  const Complex sl = std::sqrt(Complex(k.lambda_));
  std::array<Complex, 3> w{};
  for (int i = 0; i < 3; ++i) w[i] = std::sqrt(u - k.e[i]);
  if (std::abs(w[0] * w[1] * w[2] - v) > std::abs(w[0] * w[1] * w[2] + v)) w[0] = -w[0];
  std::array<Complex, 3> X{}, alpha{};
  for (int i = 0; i < 3; ++i) {
    X[i] = w[i] * x.m[i] + sl * w[(i + 1) % 3] * w[(i + 2) % 3] * x.gamma[i];
    alpha[i] = c[i] * w[i];
  }
  int big = 0;
  for (int i = 1; i < 3; ++i) big = std::abs(alpha[i]) > std::abs(alpha[big]) ? i : big;
  const int i1 = (big + 1) % 3, i2 = (big + 2) % 3;
  return (X[i1] * alpha[i2] - X[i2] * alpha[i1]) / (Complex(0.0, 1.0) * alpha[big]);
}

}  // namespace

BrunPrymDivisor brun_prym_zeros(const BrunCurve& k, const BrunPrymLine& l) {
  const Complex sl = std::sqrt(Complex(k.lambda_));
  if (l.C == Complex(0.0) || k.lambda_ == 0.0) {
    throw InputError("Brun divisor: expected C = sum c_i gamma_i != 0 and lambda != 0");
  }
  // λC² P(u) − (Au + B)² = a3 u³ + a2 u² + a1 u + a0.
  const double S1 = k.e[0] + k.e[1] + k.e[2];
  const double S2 = k.e[0] * k.e[1] + k.e[1] * k.e[2] + k.e[2] * k.e[0];
  const double S3 = k.e[0] * k.e[1] * k.e[2];
  const Complex q = k.lambda_ * l.C * l.C;
  const std::array<Complex, 4> a{-q * S3 - l.B * l.B, q * S2 - 2.0 * l.A * l.B, -q * S1 - l.A * l.A,
                                 q};
  Eigen::Matrix3cd companion = Eigen::Matrix3cd::Zero();
  companion(1, 0) = companion(2, 1) = 1.0;
  for (int i = 0; i < 3; ++i) companion(i, 2) = -a[i] / a[3];
  const Eigen::Vector3cd z =
      Eigen::ComplexEigenSolver<Eigen::Matrix3cd>(companion, false).eigenvalues();
  BrunPrymDivisor d{};
  for (int r = 0; r < 3; ++r) {
    Complex u = z[r];
    for (int it = 0; it < kPrymPolishSteps; ++it) {
      const Complex f = ((a[3] * u + a[2]) * u + a[1]) * u + a[0];
      const Complex df = (3.0 * a[3] * u + 2.0 * a[2]) * u + a[1];
      if (df == Complex(0.0)) break;
      u -= f / df;
    }
    const Complex v = -(l.A * u + l.B) / (sl * l.C);
    d[r] = {u, v, std::sqrt(brun_N(k, u) + 2.0 * sl * k.f * v)};
  }
  return d;
}

std::array<Complex, 2> brun_prym_line_rate(const BrunCurve& k, const BrunPrymLine& l,
                                           const BrunPrymLine& dl, const BrunPrymDivisor& d) {
  const Complex sl = std::sqrt(Complex(k.lambda_));
  std::array<Complex, 2> r{};
  for (const BrunPrymPoint& p : d) {
    const Complex term = -2.0 * (dl.A * p.u + dl.B + sl * dl.C * p.v) /
                         ((2.0 * l.A * p.v + sl * l.C * dP_of(k, p.u)) * p.xi);
    r[0] += term;
    r[1] += p.u * term;
  }
  return r;
}

BrunPrymDivisor brun_prym_divisor(const BrunCurve& k, const State& s) {
  const State x = to_working_frame(k, s);
  const auto c = isotropic(k);
  BrunPrymDivisor d = brun_prym_zeros(k, line_of(k, c, x));
  for (BrunPrymPoint& p : d) {
    // The value from ξ² = N(u) + 2√λ f v (u and v are accurate; the w_i are not near u = e_i),
    // the sign from the eigenvector.
    const Complex xi_sign = eigenvalue(k, c, x, p.u, p.v);
    if (std::abs(p.xi - xi_sign) > std::abs(p.xi + xi_sign)) p.xi = -p.xi;
  }
  return d;
}

BrunPrymLine brun_prym_line(const BrunCurve& k, const State& s) {
  return line_of(k, isotropic(k), to_working_frame(k, s));
}

State brun_prym_state(const BrunCurve& k, const BrunPrymDivisor& d) {
  const auto c = isotropic(k);
  const Complex sl = std::sqrt(Complex(k.lambda_));
  // (A : B : C): the line A u + B + √λ C v = 0 through the three points.
  Eigen::Matrix3cd rows;
  for (int j = 0; j < 3; ++j) rows.row(j) << d[j].u, 1.0, sl * d[j].v;
  const Eigen::Vector3cd line =
      Eigen::JacobiSVD<Eigen::Matrix3cd>(rows, Eigen::ComputeFullV).matrixV().col(2);
  // Real unknowns (m, γ, Re μ, Im μ) with Σc_i m_i = μA, −Σc_i e_i m_i = μB, Σc_i γ_i = μC:
  // six real homogeneous equations, a plane of solutions.
  Eigen::Matrix<double, 6, 8> L = Eigen::Matrix<double, 6, 8>::Zero();
  for (int i = 0; i < 3; ++i) {
    const std::array<Complex, 3> coef{c[i], -c[i] * k.e[i], c[i]};
    for (int row = 0; row < 3; ++row) {
      const int col = row < 2 ? i : 3 + i;
      L(2 * row, col) = coef[row].real();
      L(2 * row + 1, col) = coef[row].imag();
    }
  }
  for (int row = 0; row < 3; ++row) {  // −μ (line[row]): μ = μr + i μi
    const Complex w = line[row];
    L(2 * row, 6) = -w.real(), L(2 * row, 7) = w.imag();
    L(2 * row + 1, 6) = -w.imag(), L(2 * row + 1, 7) = -w.real();
  }
  const Eigen::Matrix<double, 8, 8> V =
      Eigen::JacobiSVD<Eigen::Matrix<double, 6, 8>>(L, Eigen::ComputeFullV).matrixV();
  const Eigen::Matrix<double, 8, 1> Y1 = V.col(6), Y2 = V.col(7);
  // On the plane s Y1 + t Y2: |γ|² and m·γ are quadratic forms; m·γ = f |γ|² fixes s : t.
  auto form = [](const Eigen::Matrix<double, 8, 1>& a, const Eigen::Matrix<double, 8, 1>& b,
                 bool gamma_gamma) {
    return gamma_gamma
               ? a.segment<3>(3).dot(b.segment<3>(3))
               : 0.5 * (a.head<3>().dot(b.segment<3>(3)) + b.head<3>().dot(a.segment<3>(3)));
  };
  Eigen::Matrix2d G, S;
  for (int p = 0; p < 2; ++p) {
    for (int q = 0; q < 2; ++q) {
      const auto& a = p == 0 ? Y1 : Y2;
      const auto& b = q == 0 ? Y1 : Y2;
      G(p, q) = form(a, b, true);
      S(p, q) = form(a, b, false) - k.f * G(p, q);
    }
  }
  // Directions (s, t) with S(s, t) = 0: the eigenvectors of S give S = diag(σ1, σ2) in a rotated
  // basis, zero on σ1 x² + σ2 y² = 0.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(S);
  const double s1 = eig.eigenvalues()[0], s2 = eig.eigenvalues()[1];
  const double r = std::sqrt(std::max(0.0, -s1 / s2));  // s1 ≤ 0 ≤ s2 on a real solution
  // The size of the points, for the match below.
  double size = 0;
  for (const BrunPrymPoint& p : d) size += std::abs(p.xi);
  double best = std::numeric_limits<double>::infinity();
  State state;
  for (double sign_y : {1.0, -1.0}) {
    const Eigen::Vector2d dir = eig.eigenvectors().col(0) + sign_y * r * eig.eigenvectors().col(1);
    const double g2 = dir.dot(G * dir);
    if (!(g2 > 0)) continue;
    for (double sign : {1.0, -1.0}) {
      const Eigen::Matrix<double, 8, 1> z = sign / std::sqrt(g2) * (dir[0] * Y1 + dir[1] * Y2);
      const State w = from_working_frame(k, State{z.head<3>(), z.segment<3>(3)});
      // A candidate whose own eigenvalues at the points are the ξ_j (the sign of (m, γ) flips
      // every ξ; the other direction is a state of another level through the same points).
      const State x = to_working_frame(k, w);
      double mismatch = 0;
      for (const BrunPrymPoint& p : d) mismatch += std::abs(eigenvalue(k, c, x, p.u, p.v) - p.xi);
      if (mismatch < best) best = mismatch, state = w;
    }
  }
  if (!(best <= kMatch * size)) {
    throw InputError("Brun divisor: no real state of the level carries these points");
  }
  return state;
}

State brun_c_flow(const BrunCurve& k, const State& s) {
  const State x = to_working_frame(k, s);
  const Vec3 dc_dm = 2 * x.m;
  const Vec3 dc_dgamma = -2 * k.lambda_ * k.kappa * x.gamma.cwiseQuotient(k.inertia);
  return from_working_frame(k, {x.m.cross(dc_dm) + x.gamma.cross(dc_dgamma), x.gamma.cross(dc_dm)});
}

BrunPrymRate brun_prym_rate(const BrunCurve& k, const State& s, const State& ds) {
  const auto c = isotropic(k);
  const BrunPrymLine l = line_of(k, c, to_working_frame(k, s));
  const BrunPrymLine dl = line_of(k, c, to_working_frame(k, ds));
  const Complex sl = std::sqrt(Complex(k.lambda_));
  BrunPrymRate r;
  const BrunPrymDivisor d = brun_prym_divisor(k, s);
  for (int j = 0; j < 3; ++j) {
    const BrunPrymPoint& p = d[j];
    // d(Au + B + √λ C v) = 0 on v² = P(u), dv = P′(u) du/(2v), so
    // u̇/(vξ) = −2(Ȧu + Ḃ + √λ Ċ v)/((2Av + √λ C P′(u)) ξ): finite where the point passes e_i.
    const Complex term = -2.0 * (dl.A * p.u + dl.B + sl * dl.C * p.v) /
                         ((2.0 * l.A * p.v + sl * l.C * dP_of(k, p.u)) * p.xi);
    r.rate[0] += term;
    r.rate[1] += p.u * term;
    // Round-off model: the root's error grows as 1/δ as another point comes within δ, and the
    // term (∝ 1/δ there) passes it on; ξ's error is ε(|N| + |2√λ f v|)/|ξ| relative to ξ.
    const double delta =
        std::min(std::abs(p.u - d[(j + 1) % 3].u), std::abs(p.u - d[(j + 2) % 3].u));
    const double scale = 1 + std::abs(p.u);
    const Complex lin = 2.0 * sl * k.f * p.v;
    const double xi_ratio = (std::abs(p.xi * p.xi - lin) + std::abs(lin)) / std::norm(p.xi);
    r.magnitude += std::abs(term) * scale;
    r.error_scale += std::abs(term) * scale * (1 + scale / delta + xi_ratio);
  }
  return r;
}

std::array<Complex, 2> brun_prym_abel_increment(const BrunCurve& k, const BrunMotion& x, double t0,
                                                double t1, double tolerance) {
  return refine(k, x, t0, t1, piece(k, x, t0, t1), tolerance, 1).sum;
}

}  // namespace newtop
