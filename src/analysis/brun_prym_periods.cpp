// GCC 12 reports a false -Wuninitialized inside Boost.Odeint's Fehlberg 7(8) copy constructor.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "newtop/analysis/brun_prym_periods.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "newtop/analysis/brun_level.hpp"
#include "newtop/analysis/brun_prym.hpp"
#include "newtop/core/types.hpp"
#include "newtop/integrate/methods.hpp"
#include "prym_lattice.hpp"

namespace newtop {
namespace {

using Complex = std::complex<double>;
using Period = Eigen::Vector4d;  // (Re ∫du/(vξ), Re ∫u du/(vξ), Im ..., Im ...)
using prym_lattice::lattice_basis;
using prym_lattice::reduce;
using prym_lattice::torus_lattice;

constexpr double kTwoPi = 2 * std::numbers::pi;
// Sub-segments of a path no longer than this fraction of the distance to the nearest branch
// point (8-point Gauss–Legendre: relative error ~(1/20)^16 per sub-segment).
constexpr double kSegment = 0.1;
// A loop circles its branch point at this fraction of the distance to the nearest other one.
constexpr double kLoopRadius = 0.3;
constexpr int kLoopPoints = 96;
// Sheets are told apart at this relative distance (they differ at O(1)).
constexpr double kSheet = 1e-6;
// The flows over a candidate period: rkf78 at this tolerance; a period returns the state to
// ~1e-12, a non-period misses by O(1).
constexpr double kFlowTol = 1e-13;
constexpr double kReturn = 1e-6;
// Gauss pieces on one segment of a path (each 0.1 of its clearance): past 1e7 the path passes
// within 1e-6 of the segment's length of a branch point, i.e. two branch points have merged to
// round-off (a permanent rotation's curve: 9.5e-8 apart at a segment of O(1)) and the curve is
// singular. Small λ brings them close but not so close (λ = 0.02: 5e-3 apart, 1e5 pieces).
constexpr double kMaxPieces = 1e7;

struct Curve {
  const BrunCurve& k;
  Complex sl;
  std::vector<Complex> branch;
  Complex P(Complex u) const { return (u - k.e[0]) * (u - k.e[1]) * (u - k.e[2]); }
  Complex N(Complex u) const { return brun_N(k, u); }
  double clearance(Complex u) const {
    double d = std::numeric_limits<double>::infinity();
    for (Complex b : branch) d = std::min(d, std::abs(u - b));
    return d;
  }
};

struct Sheet {
  Complex v, xi;
};

Complex nearest_sign(Complex value, Complex previous) {
  return std::abs(value - previous) <= std::abs(value + previous) ? value : -value;
}

/// ∫ (1, u) du/(vξ) along a polyline, v and ξ continued node to node from `sheet` (left at the
/// sheet of the last point).
std::array<Complex, 2> path_integral(const Curve& g, const std::vector<Complex>& path,
                                     Sheet& sheet) {
  using G = boost::math::quadrature::gauss<double, 8>;
  const auto& x = G::abscissa();  // the non-negative half, ascending
  const auto& w = G::weights();
  std::array<Complex, 2> sum{};
  auto visit = [&](Complex u, Complex weight) {
    sheet.v = nearest_sign(std::sqrt(g.P(u)), sheet.v);
    sheet.xi = nearest_sign(std::sqrt(g.N(u) + 2.0 * g.sl * g.k.f * sheet.v), sheet.xi);
    const Complex q = weight / (sheet.v * sheet.xi);
    sum[0] += q;
    sum[1] += u * q;
  };
  for (std::size_t s = 0; s + 1 < path.size(); ++s) {
    const Complex a = path[s], b = path[s + 1];
    const double near = std::max(std::min(g.clearance(a), g.clearance(b)), 1e-12);
    const double pieces = std::ceil(std::abs(b - a) / (kSegment * near));
    if (!(pieces <= kMaxPieces)) {  // branch points (nearly) merged: no torus to integrate on
      char apart[32];
      std::snprintf(apart, sizeof(apart), "%.3g", near);
      throw InputError(
          "Brun periods: the spectral curve is singular on this level (branch points " +
          std::string(apart) +
          " apart: a degenerate torus, such as a permanent rotation); no "
          "quasi-periodic motion to invert");
    }
    const int n = std::max(1, static_cast<int>(pieces));
    for (int j = 0; j < n; ++j) {
      const Complex ua = a + (b - a) * (double(j) / n), ub = a + (b - a) * (double(j + 1) / n);
      const Complex mid = 0.5 * (ua + ub), half = 0.5 * (ub - ua);
      const int m = static_cast<int>(x.size());
      for (int i = m - 1; i >= 0; --i) visit(mid - half * x[i], half * w[i]);
      for (int i = 0; i < m; ++i) visit(mid + half * x[i], half * w[i]);
    }
    visit(b, 0.0);
  }
  return sum;
}

/// A loop from the base point around one branch point: its end sheet from each start sheet and
/// its integrals.
struct Loop {
  std::array<int, 4> end{};
  std::array<std::array<Complex, 2>, 4> integral{};
};

double clearance_of_rays(const Curve& g, Complex base) {
  double worst = std::numeric_limits<double>::infinity();
  for (Complex t : g.branch) {
    for (Complex o : g.branch) {
      if (o == t) continue;
      const double s =
          std::clamp(((o - base) * std::conj(t - base)).real() / std::norm(t - base), 0.0, 1.0);
      worst = std::min(worst, std::abs(base + s * (t - base) - o) / std::abs(t - o));
    }
  }
  return worst;
}

std::vector<Loop> loops(const Curve& g, Complex base, const std::array<Sheet, 4>& sheets) {
  auto which = [&](const Sheet& s) {
    for (int n = 0; n < 4; ++n) {
      if (std::abs(s.v - sheets[n].v) < kSheet * std::abs(sheets[n].v) &&
          std::abs(s.xi - sheets[n].xi) < kSheet * std::abs(sheets[n].xi)) {
        return n;
      }
    }
    throw InputError("Brun frequencies: a loop ended off the sheets of the base point");
  };
  std::vector<Loop> out;
  for (Complex t : g.branch) {
    double rho = std::numeric_limits<double>::infinity();
    for (Complex o : g.branch) rho = o == t ? rho : std::min(rho, std::abs(t - o));
    rho *= kLoopRadius;
    const Complex d = (t - base) / std::abs(t - base);
    std::vector<Complex> path{base};
    for (int n = 0; n <= kLoopPoints; ++n) {
      path.push_back(t - d * rho * std::exp(Complex(0, kTwoPi * n / kLoopPoints)));
    }
    path.push_back(base);
    Loop l;
    for (int s = 0; s < 4; ++s) {
      Sheet sh = sheets[s];
      l.integral[s] = path_integral(g, path, sh);
      l.end[s] = which(sh);
    }
    out.push_back(l);
  }
  return out;
}

/// The periods of every closed word of two and four loops, as vectors of R⁴.
std::vector<Period> closed_words(const std::vector<Loop>& l) {
  std::vector<Period> out;
  const int n = static_cast<int>(l.size());
  for (int length : {2, 4}) {
    int count = 1;
    for (int i = 0; i < length; ++i) count *= n;
    for (int word = 0; word < count; ++word) {
      for (int s0 = 0; s0 < 4; ++s0) {
        int s = s0, code = word;
        std::array<Complex, 2> total{};
        for (int i = 0; i < length; ++i, code /= n) {
          const Loop& g = l[code % n];
          total[0] += g.integral[s][0], total[1] += g.integral[s][1];
          s = g.end[s];
        }
        if (s == s0 && std::max(std::abs(total[0]), std::abs(total[1])) > 1e-9) {
          out.push_back(Period(total[0].real(), total[1].real(), total[0].imag(), total[1].imag()));
        }
      }
    }
  }
  return out;
}

/// max |x(τ) − x0| after the flow of H for τ_H, then the flow of c for τ_c, from x0.
double return_error(const QuadraticModel& model, const BrunCurve& k, const State& x0,
                    const Eigen::Vector2d& tau) {
  Fehlberg78Stepper stepper(kFlowTol, kFlowTol);
  const State x = integrate(stepper, model, x0, 0.0, tau[0], {}).state;
  using Y = std::array<double, 6>;
  Y y{x.m[0], x.m[1], x.m[2], x.gamma[0], x.gamma[1], x.gamma[2]};
  const double sign = tau[1] >= 0 ? 1.0 : -1.0;
  auto field = [&](const Y& a, Y& d, double) {
    const State r = brun_c_flow(k, State{Vec3(a[0], a[1], a[2]), Vec3(a[3], a[4], a[5])});
    for (int i = 0; i < 3; ++i) d[i] = sign * r.m[i], d[3 + i] = sign * r.gamma[i];
  };
  namespace ode = boost::numeric::odeint;
  ode::integrate_adaptive(ode::make_controlled<ode::runge_kutta_fehlberg78<Y>>(kFlowTol, kFlowTol),
                          field, y, 0.0, std::abs(tau[1]), 1e-3);
  double err = 0;
  for (int i = 0; i < 3; ++i) {
    err = std::max({err, std::abs(y[i] - x0.m[i]), std::abs(y[3 + i] - x0.gamma[i])});
  }
  return err;
}

}  // namespace

BrunPrymFrequencies brun_prym_frequencies(const QuadraticModel& model, const State& s) {
  const BrunCurve k = brun_level(model, s);
  if (k.f == 0.0) {
    throw InputError("Brun frequencies: the level f = 0 has the separation of brun_case.hpp");
  }
  Curve g{k, std::sqrt(Complex(k.lambda_)), {}};
  for (int i = 0; i < 3; ++i) g.branch.push_back(k.e[i]);
  for (Complex r : brun_spectral_curve(k).branch_point) g.branch.push_back(r);
  // The base point: of a grid below the real axis, the one whose rays to the branch points pass
  // farthest from the other branch points.
  double lo = g.branch[0].real(), hi = lo;
  for (Complex b : g.branch) lo = std::min(lo, b.real()), hi = std::max(hi, b.real());
  const double span = std::max(hi - lo, 1e-3);
  Complex base;
  double best = -1;
  for (int i = 0; i <= 25; ++i) {
    for (double y : {0.02, 0.05, 0.13, 0.3}) {
      const Complex c(lo - 0.25 * span + 1.5 * span * i / 25, -y * span);
      const double cl = clearance_of_rays(g, c);
      if (cl > best) best = cl, base = c;
    }
  }
  std::array<Sheet, 4> sheets{};
  for (int sv = 0; sv < 2; ++sv) {
    const Complex v = (sv == 0 ? 1.0 : -1.0) * std::sqrt(g.P(base));
    for (int sx = 0; sx < 2; ++sx) {
      sheets[2 * sv + sx] = {v,
                             (sx == 0 ? 1.0 : -1.0) * std::sqrt(g.N(base) + 2.0 * g.sl * k.f * v)};
    }
  }
  const std::vector<Period> periods = closed_words(loops(g, base, sheets));
  const Eigen::Matrix4d L = lattice_basis(periods);
  BrunPrymFrequencies out;
  out.period_vectors = static_cast<int>(periods.size());
  out.velocity_c = brun_prym_rate(k, s, brun_c_flow(k, s)).rate;
  const Complex vh(0.0, -2.0 / k.kappa);
  Eigen::Matrix<double, 4, 2> W;
  W << vh.real(), out.velocity_c[0].real(), 0.0, out.velocity_c[1].real(), vh.imag(),
      out.velocity_c[0].imag(), 0.0, out.velocity_c[1].imag();
  Eigen::Matrix2d T = torus_lattice(L, W);
  // The map from the torus to the Prym can be two to one: of the three index-2 sublattices, the
  // one the flows close on (decided by integrating them over t0, t1, t0 + t1).
  const Eigen::Vector2d t0 = T.col(0), t1 = T.col(1);
  const bool r0 = return_error(model, k, s, t0) < kReturn;
  const bool r1 = return_error(model, k, s, t1) < kReturn;
  if (r0 && r1) {
    out.index = 1;
  } else {
    out.index = 2;
    if (r0) {
      T.col(1) = 2 * t1;
    } else if (r1) {
      T.col(0) = 2 * t0;
    } else if (return_error(model, k, s, t0 + t1) < kReturn) {
      T.col(0) = t0 + t1, T.col(1) = 2 * t1;
    } else {
      throw InputError("Brun frequencies: the flows close on no index-2 sublattice");
    }
    Eigen::Vector2d a = T.col(0), b = T.col(1);
    reduce(a, b);
    T << a, b;
  }
  Eigen::Vector2d omega = kTwoPi * T.inverse() * Eigen::Vector2d(1.0, 0.0);
  for (int c = 0; c < 2; ++c) {  // the basis cycle turned so that its angle grows with t
    if (omega[c] < 0) omega[c] = -omega[c], T.col(c) = -T.col(c);
  }
  out.frequency = {omega[0], omega[1]};
  out.torus_period = {{{T(0, 0), T(1, 0)}, {T(0, 1), T(1, 1)}}};
  out.resonance = brun_resonance(std::abs(omega[0]), std::abs(omega[1]));
  return out;
}

}  // namespace newtop
