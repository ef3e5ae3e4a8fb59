#include "newtop/analysis/brun_prym_inversion.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>

#include "newtop/analysis/brun_level.hpp"
#include "newtop/core/types.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop {
namespace {

using Complex = std::complex<double>;
using Sums = std::array<Complex, 2>;
using Line = Eigen::Vector3cd;

// Gauss–Legendre nodes on a segment of lines. With every point moving by at most kMove of its
// distance to the nearest singularity of the integrand (another point, a root of D) over the
// segment, the nearest singularity is ≥ 4 half-lengths away: Bernstein ellipse ρ ≈ 8, error
// ~ρ^(−24) ≈ 2e-22, far below round-off. (A bound node to node only, 12 times looser, left
// errors of 2e-8 on some nodes.)
constexpr int kInversionNodes = 12;
constexpr double kMove = 0.5;
// Table nodes per side of the torus cell (a query starts at most 1/16 of a cell away).
constexpr int kGrid = 8;
// Newton's method: at most this many corrections; the residual of the sums (O(1) in size) is
// accepted at kAccept (round-off of the quadrature is ~1e-15).
constexpr int kNewton = 8;
constexpr double kAccept = 1e-10;
// Gauss–Newton corrections of the state (quadratic convergence from brun_prym_state's).
constexpr int kPolish = 3;
// Central differences of the residual of polish: exact for its linear and quadratic terms up to
// round-off ε/kDiff.
constexpr double kDiff = 1e-5;
// A step is given up below this fraction of the move asked for.
constexpr double kMinStep = 1e-10;
// The state after a step lies within this fraction of the first-order move of the flows from
// the prediction x + τ_H X_H + τ_c X_c (a jump to another divisor misses by O(1)).
constexpr double kContinuity = 0.5;

Line vec(const BrunPrymLine& l) { return Line(l.A, l.B, l.C); }
BrunPrymLine line(const Line& v) { return {v[0], v[1], v[2]}; }

struct Context {
  const QuadraticModel& model;
  const BrunCurve& k;
  Sums vh, vc;
  std::vector<Complex> branch;  ///< roots of D
};

/// Distance from point j to the nearest other point or root of D.
double clearance(const Context& c, const BrunPrymDivisor& d, int j) {
  double s = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) s = i == j ? s : std::min(s, std::abs(d[j].u - d[i].u));
  for (Complex b : c.branch) s = std::min(s, std::abs(d[j].u - b));
  return s;
}

/// The zeros of L matched to the points d (each moved by at most kMove of its clearance), ξ
/// continued by the nearer sign; false when a point moved farther.
bool follow(const Context& c, const Line& L, BrunPrymDivisor& d) {
  const BrunPrymDivisor z = brun_prym_zeros(c.k, line(L));
  BrunPrymDivisor out{};
  std::array<bool, 3> used{};
  for (int j = 0; j < 3; ++j) {
    const double limit = kMove * clearance(c, d, j);
    int best = -1;
    for (int r = 0; r < 3; ++r) {
      if (used[r] || !(std::abs(z[r].u - d[j].u) <= limit)) continue;
      if (best < 0 || std::abs(z[r].u - d[j].u) < std::abs(z[best].u - d[j].u)) best = r;
    }
    if (best < 0) return false;
    used[best] = true;
    out[j] = z[best];
    if (std::abs(out[j].xi - d[j].xi) > std::abs(out[j].xi + d[j].xi)) out[j].xi = -out[j].xi;
  }
  d = out;
  return true;
}

struct Chord {
  bool ok = false;
  Sums sum{};
  BrunPrymDivisor end{};
};

/// S(D(Lb)) − S(D(La)) along the straight segment of lines from La (whose divisor is da).
Chord chord(const Context& c, const Line& La, const BrunPrymDivisor& da, const Line& Lb) {
  using G = boost::math::quadrature::gauss<double, kInversionNodes>;
  const auto& x = G::abscissa();
  const auto& w = G::weights();
  const Line dL = Lb - La;
  Chord out;
  out.end = da;
  auto visit = [&](double sigma, double weight) {
    const Line L = La + sigma * dL;
    if (!follow(c, L, out.end)) return false;
    const Sums r = brun_prym_line_rate(c.k, line(L), line(dL), out.end);
    out.sum[0] += weight * r[0], out.sum[1] += weight * r[1];
    return true;
  };
  const int half = kInversionNodes / 2;
  for (int i = half - 1; i >= 0; --i) {
    if (!visit(0.5 * (1 - x[i]), 0.5 * w[i])) return out;
  }
  for (int i = 0; i < half; ++i) {
    if (!visit(0.5 * (1 + x[i]), 0.5 * w[i])) return out;
  }
  if (!follow(c, Lb, out.end)) return out;
  // The whole segment, not only node to node, within kMove of each point's clearance at both
  // ends: the quadrature's error bound above.
  for (int j = 0; j < 3; ++j) {
    const double move = std::abs(out.end[j].u - da[j].u);
    if (!(move <= kMove * std::min(clearance(c, da, j), clearance(c, out.end, j)))) return out;
  }
  out.ok = true;
  return out;
}

double distance(const State& a, const State& b) {
  return std::max((a.m - b.m).cwiseAbs().maxCoeff(), (a.gamma - b.gamma).cwiseAbs().maxCoeff());
}

/// The state x of the level (|γ| = 1, m·γ = f, energy h, Brun's integral c) whose line is
/// proportional to L, by Gauss–Newton from brun_prym_state's: that map alone takes a square root
/// where the two real directions through the points meet (a fold), which the level's h and c
/// resolve.
State polish(const Context& c, const Line& L, State x) {
  using Y = Eigen::Matrix<double, 8, 1>;
  using R = Eigen::Matrix<double, 10, 1>;
  const Line l = L / L.norm();
  Complex mu = vec(brun_prym_line(c.k, x)).dot(l);  // conj(l)·line: the scale
  auto residual = [&](const Y& y) {
    const State s{y.head<3>(), y.segment<3>(3)};
    const Line d = vec(brun_prym_line(c.k, s)) - Complex(y[6], y[7]) * l;
    R r;
    r << d[0].real(), d[0].imag(), d[1].real(), d[1].imag(), d[2].real(), d[2].imag(),
        s.gamma.squaredNorm() - 1, s.m.dot(s.gamma) - c.k.f, energy(c.model, s) - c.k.h,
        brun(c.model, s) - c.k.c;
    return r;
  };
  Y y;
  y << x.m, x.gamma, mu.real(), mu.imag();
  for (int it = 0; it < kPolish; ++it) {
    Eigen::Matrix<double, 10, 8> J;
    for (int i = 0; i < 8; ++i) {
      Y a = y, b = y;
      a[i] += kDiff, b[i] -= kDiff;
      J.col(i) = (residual(a) - residual(b)) / (2 * kDiff);
    }
    y -= J.colPivHouseholderQr().solve(residual(y));
  }
  return {y.head<3>(), y.segment<3>(3)};
}

struct Move {
  bool ok = false;
  BrunPrymNode node;
  double residual = 0;
};

/// One step from node a by flow times dtau: Newton's method on the line (its largest component
/// held), then the state and the checks.
Move step(const Context& c, const BrunPrymNode& a, const Eigen::Vector2d& dtau) {
  const Eigen::Vector2cd target(c.vh[0] * dtau[0] + c.vc[0] * dtau[1],
                                c.vh[1] * dtau[0] + c.vc[1] * dtau[1]);
  const Line La = vec(a.line);
  int fix = 0;
  La.cwiseAbs().maxCoeff(&fix);
  const std::array<int, 2> free{(fix + 1) % 3, (fix + 2) % 3};
  auto jacobian = [&](const Line& L, const BrunPrymDivisor& d) {
    Eigen::Matrix2cd J;
    for (int q = 0; q < 2; ++q) {
      Line e = Line::Zero();
      e[free[q]] = 1.0;
      const Sums r = brun_prym_line_rate(c.k, line(L), line(e), d);
      J(0, q) = r[0], J(1, q) = r[1];
    }
    return J;
  };
  Line L = La, best = La;
  Eigen::Vector2cd dz = jacobian(La, a.divisor).partialPivLu().solve(target);
  Move out;
  double last = std::numeric_limits<double>::infinity();
  Chord ch;
  for (int it = 0; it <= kNewton; ++it) {
    L[free[0]] += dz[0], L[free[1]] += dz[1];
    const Chord trial = chord(c, La, a.divisor, L);
    if (!trial.ok) return out;
    const Eigen::Vector2cd R(trial.sum[0] - target[0], trial.sum[1] - target[1]);
    const double res = R.cwiseAbs().maxCoeff();
    if (!(res < 0.5 * last)) break;  // converged to round-off (or diverging): keep the best
    last = res, best = L, ch = trial;
    dz = -jacobian(L, ch.end).partialPivLu().solve(R);
  }
  if (!(last <= kAccept)) return out;
  L = best;
  State x;
  try {
    x = polish(c, L, brun_prym_state(c.k, ch.end));
  } catch (const InputError&) {
    return out;  // no real state of the level carries it: a wrong sheet
  }
  const State vH = rhs(c.model, a.state), vC = brun_c_flow(c.k, a.state);
  const State predicted{a.state.m + dtau[0] * vH.m + dtau[1] * vC.m,
                        a.state.gamma + dtau[0] * vH.gamma + dtau[1] * vC.gamma};
  const double size = std::abs(dtau[0]) * std::max(vH.m.norm(), vH.gamma.norm()) +
                      std::abs(dtau[1]) * std::max(vC.m.norm(), vC.gamma.norm());
  if (!(distance(x, predicted) <= kContinuity * size + 1e-12)) return out;
  out.ok = true;
  out.residual = last;
  out.node = {{a.tau[0] + dtau[0], a.tau[1] + dtau[1]}, line(L / L.norm()), ch.end, x};
  return out;
}

/// From node a by flow times dtau, in steps halved until each succeeds.
BrunPrymNode travel(const Context& c, BrunPrymNode a, const Eigen::Vector2d& dtau, int& steps,
                    double& residual) {
  double done = 0, h = 1;
  while (done < 1) {
    h = std::min(h, 1 - done);
    const Move m = step(c, a, h * dtau);
    if (m.ok) {
      a = m.node;
      done += h;
      h *= 2;
      ++steps;
      residual = m.residual;
    } else {
      h *= 0.5;
      if (h < kMinStep) {
        throw InputError("Brun inversion: the continuation on the torus stalled at tau = (" +
                         std::to_string(a.tau[0]) + ", " + std::to_string(a.tau[1]) + ")");
      }
    }
  }
  return a;
}

Eigen::Matrix2d lattice(const BrunPrymSolution& s) {
  Eigen::Matrix2d T;
  T << s.torus.torus_period[0][0], s.torus.torus_period[1][0], s.torus.torus_period[0][1],
      s.torus.torus_period[1][1];
  return T;
}

Context context(const BrunPrymSolution& s) {
  Context c{s.model, s.curve, s.velocity_h, s.velocity_c, {}};
  for (Complex b : brun_spectral_curve(s.curve).branch_point) c.branch.push_back(b);
  return c;
}

int index(int i, int j) { return i * (kGrid + 1) + j; }

}  // namespace

BrunPrymSolution brun_prym_solution(const QuadraticModel& model, const State& x0) {
  BrunPrymSolution s{model, brun_level(model, x0), x0, {}, {}, {}, kGrid, {}};
  if (s.curve.f == 0.0) {
    throw InputError("Brun inversion: the level f = 0 has the separation of brun_case.hpp");
  }
  // The start's divisor first: a level whose real state carries no divisor (a degenerate torus,
  // such as a permanent rotation) is refused here at once, before the periods are sought.
  const BrunPrymDivisor d0 = brun_prym_divisor(s.curve, x0);
  s.torus = brun_prym_frequencies(model, x0);
  s.velocity_h = {Complex(0.0, -2.0 / s.curve.kappa), 0.0};
  s.velocity_c = {0.0, Complex(0.0, -4.0)};
  const Context c = context(s);
  const Eigen::Matrix2d T = lattice(s);
  s.table.resize((kGrid + 1) * (kGrid + 1));
  const int mid = kGrid / 2;
  const BrunPrymLine l0 = brun_prym_line(s.curve, x0);
  const Line v0 = vec(l0);
  s.table[index(mid, mid)] = {{0.0, 0.0}, line(v0 / v0.norm()), d0, x0};
  int steps = 0;
  double residual = 0;
  const Eigen::Vector2d d1 = T.col(0) / kGrid, d2 = T.col(1) / kGrid;
  for (int i = mid + 1; i <= kGrid; ++i) {
    s.table[index(i, mid)] = travel(c, s.table[index(i - 1, mid)], d1, steps, residual);
    s.table[index(kGrid - i, mid)] =
        travel(c, s.table[index(kGrid - i + 1, mid)], -d1, steps, residual);
  }
  for (int i = 0; i <= kGrid; ++i) {
    for (int j = mid + 1; j <= kGrid; ++j) {
      s.table[index(i, j)] = travel(c, s.table[index(i, j - 1)], d2, steps, residual);
      s.table[index(i, kGrid - j)] =
          travel(c, s.table[index(i, kGrid - j + 1)], -d2, steps, residual);
    }
  }
  return s;
}

BrunPrymStateAt brun_prym_state_at(const BrunPrymSolution& s, double t) {
  if (!std::isfinite(t)) throw InputError("Brun inversion: expected a finite time");
  const Eigen::Matrix2d T = lattice(s);
  Eigen::Vector2d theta = T.inverse() * Eigen::Vector2d(t, 0.0);
  theta -= theta.array().round().matrix();
  const int i = static_cast<int>(std::lround((theta[0] + 0.5) * kGrid));
  const int j = static_cast<int>(std::lround((theta[1] + 0.5) * kGrid));
  const BrunPrymNode& start = s.table[index(i, j)];
  const Eigen::Vector2d node_theta(double(i) / kGrid - 0.5, double(j) / kGrid - 0.5);
  BrunPrymStateAt out;
  out.cell = {theta[0], theta[1]};
  const Eigen::Vector2d tau = T * theta;
  out.tau = {tau[0], tau[1]};
  const BrunPrymNode end =
      travel(context(s), start, T * (theta - node_theta), out.steps, out.residual);
  out.state = end.state;
  out.divisor = end.divisor;
  return out;
}

State brun_state_at(const QuadraticModel& model, const State& x0, double t) {
  return brun_prym_state_at(brun_prym_solution(model, x0), t).state;
}

BrunPrymCheck brun_prym_check(const BrunPrymSolution& s) {
  const BrunCurve& k = s.curve;
  const State& x0 = s.initial;
  BrunPrymCheck c;
  c.divisor = brun_prym_divisor(k, x0);
  const State back = brun_prym_state(k, c.divisor);
  c.round_trip_error = std::max((back.m - x0.m).cwiseAbs().maxCoeff(),
                                (back.gamma - x0.gamma).cwiseAbs().maxCoeff());
  c.rate = brun_prym_rate(k, x0, rhs(s.model, x0));
  return c;
}

}  // namespace newtop
