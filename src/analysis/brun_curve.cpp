#include "newtop/analysis/brun_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "newtop/model/integrals.hpp"

namespace newtop {
namespace {

// |γ| = 1 and m·γ = 0 to this relative tolerance: states written to 15 digits pass; a level
// f ≠ 0 beyond it is another motion (its separation is Kötter's, not implemented).
constexpr double kLevelTolerance = 1e-12;
// Moments closer than this (relative) make two e_i coincide: sphero-conic coordinates degenerate.
constexpr double kDistinctMoments = 1e-9;
// A range narrower than this (relative to e3 − e1) is a double root of R: a stationary u_s.
constexpr double kDegenerateRange = 1e-12;

std::string fmt(double x) { return format_number(x); }

/// Roots of a x² + b x + c0 by the stable formula, ascending (a ≠ 0, real roots assumed: a
/// negative discriminant from rounding is taken as zero).
std::array<double, 2> quadratic_roots(double a, double b, double c0) {
  const double disc = std::max(0.0, b * b - 4 * a * c0);
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  std::array<double, 2> r{q / a, q != 0.0 ? c0 / q : 0.0};
  if (r[0] > r[1]) std::swap(r[0], r[1]);
  return r;
}

void check_level(const BrunCurve& k, const State& s) {
  if (!(std::abs(k.f) <= kLevelTolerance * std::max(1.0, s.m.norm()))) {
    throw InputError(
        "initial: Brun's case is solved on the level f = m.gamma = 0 (sphero-conic "
        "separation); found f = " +
        fmt(k.f) + " (the level f != 0 needs Koetter's separation, not implemented)");
  }
}

/// Working frame: axes sorted by moment, one sign flipped if the permutation is odd.
void set_frame(BrunCurve& k, const Vec3& I) {
  std::array<int, 3> p{0, 1, 2};
  std::sort(p.begin(), p.end(), [&](int a, int b) { return I[a] < I[b]; });
  k.axis = p;
  const int inversions = (p[0] > p[1]) + (p[0] > p[2]) + (p[1] > p[2]);
  k.sign = {inversions % 2 ? -1.0 : 1.0, 1.0, 1.0};
  for (int i = 0; i < 3; ++i) k.inertia[i] = I[p[i]];
  const double scale = k.inertia[2];
  if (k.inertia[1] - k.inertia[0] <= kDistinctMoments * scale ||
      k.inertia[2] - k.inertia[1] <= kDistinctMoments * scale) {
    throw InputError(
        "body.inertia: Brun's case needs distinct moments for its sphero-conic "
        "separation, found " +
        fmt(I[0]) + ", " + fmt(I[1]) + ", " + fmt(I[2]));
  }
}

/// The range of u_s: the segment between consecutive roots of R in [e_s, e_(s+1)] that holds u_s
/// and where R > 0.
void set_range(BrunCurve& k, int s, double u) {
  std::vector<int> idx{s, s + 1};
  for (int j = 3; j < 5; ++j) {
    if (k.root[j] > k.e[s] && k.root[j] < k.e[s + 1]) idx.push_back(j);
  }
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return k.root[a] < k.root[b]; });
  const double tol = kLevelTolerance * (k.e[2] - k.e[0]);
  for (std::size_t i = 0; i + 1 < idx.size(); ++i) {
    const double a = k.root[idx[i]], b = k.root[idx[i + 1]];
    if (u < a - tol || u > b + tol || !(brun_R(k, 0.5 * (a + b)) > 0)) continue;
    if (b - a <= kDegenerateRange * (k.e[2] - k.e[0])) break;
    k.lower[s] = idx[i], k.upper[s] = idx[i + 1];
    return;
  }
  throw InputError("initial: Brun's case level with a stationary or inconsistent u" +
                   std::to_string(s + 1) + " = " + fmt(u) +
                   " (a double root of the curve: a periodic motion, not supported)");
}

}  // namespace

std::array<double, 2> brun_u(const BrunCurve& k, const Vec3& gamma) {
  // Σ γ_i² Π_{j≠i}(u − e_j) in v = u − e2: |γ|² v² + β v − γ2² d1 d3, d1 = e2 − e1, d3 = e3 − e2.
  const double d1 = k.e[1] - k.e[0], d3 = k.e[2] - k.e[1];
  const Vec3 g2 = gamma.cwiseProduct(gamma);
  const double a = g2.sum(), beta = -g2[0] * d3 + g2[1] * (d1 - d3) + g2[2] * d1;
  const double c0 = -g2[1] * d1 * d3;
  const double q = -0.5 * (beta + std::copysign(std::sqrt(beta * beta - 4 * a * c0), beta));
  double v1 = q / a, v2 = q != 0.0 ? c0 / q : 0.0;
  if (v1 > v2) std::swap(v1, v2);
  return {std::clamp(k.e[1] + v1, k.e[0], k.e[1]), std::clamp(k.e[1] + v2, k.e[1], k.e[2])};
}

State to_working_frame(const BrunCurve& k, const State& s) {
  State w;
  for (int i = 0; i < 3; ++i) {
    w.m[i] = k.sign[i] * s.m[k.axis[i]];
    w.gamma[i] = k.sign[i] * s.gamma[k.axis[i]];
  }
  return w;
}

State from_working_frame(const BrunCurve& k, const State& w) {
  State s;
  for (int i = 0; i < 3; ++i) {
    s.m[k.axis[i]] = k.sign[i] * w.m[i];
    s.gamma[k.axis[i]] = k.sign[i] * w.gamma[i];
  }
  return s;
}

namespace {

/// N(u) = λu² + (c − λ(e1 + e2 + e3)) u + 2κh, real or complex u.
template <class T>
T N_of(const BrunCurve& k, T u) {
  const double S = k.e[0] + k.e[1] + k.e[2];
  return (k.lambda_ * u + (k.c - k.lambda_ * S)) * u + 2 * k.kappa * k.h;
}

}  // namespace

double brun_N(const BrunCurve& k, double u) { return N_of(k, u); }

std::complex<double> brun_N(const BrunCurve& k, std::complex<double> u) { return N_of(k, u); }

double brun_R(const BrunCurve& k, double u) {
  return -(u - k.e[0]) * (u - k.e[1]) * (u - k.e[2]) * brun_N(k, u);
}

double brun_reduced_R(const BrunCurve& k, int s, double u) {
  double r = std::abs(k.lambda_);
  for (int j = 0; j < 5; ++j) {
    if (j != k.lower[s] && j != k.upper[s]) r *= std::abs(u - k.root[j]);
  }
  return r;
}

bool brun_level_solvable(const QuadraticModel& model, const State& x0) {
  return brun_holds(model) && model.field.lambda_ != 0.0 &&
         std::abs(area(x0)) <= kLevelTolerance * std::max(1.0, x0.m.norm());
}

BrunCurve brun_level(const QuadraticModel& model, const State& x0) {
  if (!brun_holds(model) || model.field.lambda_ == 0.0) {
    throw InputError("case: Brun's case needs M g r0 = 0, k = 0 and lambda != 0");
  }
  BrunCurve k;
  set_frame(k, model.body.inertia());
  k.kappa = k.inertia.prod();
  k.lambda_ = model.field.lambda_;
  k.h = energy(model, x0);
  k.c = brun(model, x0);
  k.f = area(x0);
  const double g = x0.gamma.norm();
  if (!(std::abs(g - 1.0) <= kLevelTolerance)) {
    throw InputError("initial.gamma: expected a unit vector for Brun's case, found |gamma| = " +
                     fmt(g));
  }
  for (int i = 0; i < 3; ++i) k.e[i] = -k.kappa / k.inertia[i];
  const double S = k.e[0] + k.e[1] + k.e[2];
  k.nu = quadratic_roots(k.lambda_, k.c - k.lambda_ * S, 2 * k.kappa * k.h);
  k.root = {k.e[0], k.e[1], k.e[2], k.nu[0], k.nu[1]};
  // R = −P N, P = u³ − S u² + S2 u − S3, N = λu² + b u + c0.
  const double S2 = k.e[0] * k.e[1] + k.e[1] * k.e[2] + k.e[2] * k.e[0];
  const double S3 = k.e[0] * k.e[1] * k.e[2];
  const std::array<double, 4> P{-S3, S2, -S, 1.0};
  const std::array<double, 3> N{2 * k.kappa * k.h, k.c - k.lambda_ * S, k.lambda_};
  k.coefficient.fill(0.0);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 3; ++j) k.coefficient[i + j] -= P[i] * N[j];
  }
  return k;
}

BrunCurve brun_curve(const QuadraticModel& model, const State& x0) {
  BrunCurve k = brun_level(model, x0);
  check_level(k, x0);
  const State w = to_working_frame(k, x0);
  const auto u = brun_u(k, w.gamma);
  set_range(k, 0, u[0]);
  set_range(k, 1, u[1]);
  return k;
}

}  // namespace newtop
