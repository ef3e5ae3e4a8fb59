// Pseudo-arclength continuation with located test functions (docs/continuation.md).

#include "newtop/analysis/continuation.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "newtop/core/types.hpp"

namespace newtop {

const char* to_string(BifurcationType t) {
  switch (t) {
    case BifurcationType::fold:
      return "fold";
    case BifurcationType::flip:
      return "flip";
    case BifurcationType::branch_point:
      return "branch_point";
    case BifurcationType::krein:
      break;
  }
  return "krein";
}

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Relative step of the central differences of F when the family gives no Jacobian: ε^(1/3)
// balances truncation (h²) and round-off (ε/h) for a residual of unit scale.
constexpr double kDifferenceStep = 6e-6;
// Bits of the TOMS 748 bracket on the chord's arclength: 50 of 53 leave the located zero a few
// ulps of the chord's length from the test function's root.
constexpr int kLocationBits = 50;
constexpr std::uintmax_t kLocationIterations = 100;

/// The family in the (n + 1)-vector X = (u, p).
class ContinuationCurve {
 public:
  ContinuationCurve(const ContinuationProblem& p, const ContinuationSettings& s)
      : pr_(p), set_(s) {}
  int n() const { return pr_.unknowns; }

  VectorXd residual(const VectorXd& x) const {
    return n() == 0 ? VectorXd() : pr_.residual(x.head(n()), x[n()]);
  }

  MatrixXd jacobian(const VectorXd& x) const {
    if (n() == 0) return MatrixXd(0, 1);
    if (pr_.jacobian) return pr_.jacobian(x.head(n()), x[n()]);
    MatrixXd j(n(), n() + 1);
    for (int i = 0; i <= n(); ++i) {
      const double h = kDifferenceStep * std::max(1.0, std::abs(x[i]));
      j.col(i) = difference(x, i, h);
    }
    return j;
  }

  /// ∂F/∂x_i by a central difference, or a one-sided one of the same order, (−3F(x) + 4F(x +
  /// h) − F(x + 2h))/(2h), where x − h lies outside the family's domain (e < 0, no body).
  VectorXd difference(const VectorXd& x, int i, double h) const {
    VectorXd a = x, b = x;
    a[i] += h;
    b[i] -= h;
    try {
      return (residual(a) - residual(b)) / (2 * h);
    } catch (const InputError&) {
      b[i] += 3 * h;
      return (4 * residual(a) - 3 * residual(x) - residual(b)) / (2 * h);
    }
  }

  /// The unit null vector of [F_u F_p] at x, oriented along `previous`.
  VectorXd tangent(const VectorXd& x, const VectorXd& previous) const {
    MatrixXd a(n() + 1, n() + 1);
    a.topRows(n()) = jacobian(x);
    a.row(n()) = previous.transpose();
    VectorXd rhs = VectorXd::Zero(n() + 1);
    rhs[n()] = 1.0;
    VectorXd t = a.fullPivLu().solve(rhs);
    t.normalize();
    return t.dot(previous) < 0 ? VectorXd(-t) : t;
  }

  /// Newton's method on F(X) = 0 and normal·(X − anchor) = 0 from `guess`; the iterations, or
  /// nullopt when it does not converge within max_newton steps.
  std::optional<int> correct(VectorXd& x, const VectorXd& normal, const VectorXd& anchor) const {
    try {
      return newton(x, normal, anchor);
    } catch (const InputError&) {  // an iterate left the family's domain (e < 0, no body)
      return std::nullopt;
    }
  }

  std::optional<int> newton(VectorXd& x, const VectorXd& normal, const VectorXd& anchor) const {
    for (int it = 0; it <= set_.max_newton; ++it) {
      VectorXd g(n() + 1);
      g.head(n()) = residual(x);
      g[n()] = normal.dot(x - anchor);
      if (!g.allFinite()) return std::nullopt;
      MatrixXd a(n() + 1, n() + 1);
      a.topRows(n()) = jacobian(x);
      a.row(n()) = normal.transpose();
      const VectorXd dx = a.fullPivLu().solve(g);
      if (!dx.allFinite()) return std::nullopt;
      x -= dx;
      const double scale = std::max(1.0, x.cwiseAbs().maxCoeff());
      if (dx.cwiseAbs().maxCoeff() <= set_.tolerance * scale &&
          (n() == 0 || residual(x).cwiseAbs().maxCoeff() <= set_.tolerance * 10)) {
        return it + 1;
      }
    }
    return std::nullopt;
  }

  /// The family's evaluation at x with the fold's test function dp/ds from the tangent.
  FamilyPoint evaluate(const VectorXd& x, const VectorXd& t) const {
    FamilyPoint f = pr_.evaluate(x.head(n()), x[n()]);
    if (f.values.size() == 0) f.values = x.head(n());
    f.parameter = x[n()];
    f.tangent_parameter = t[n()];
    if (pr_.branch_points) {  // det [F_u F_p; tᵀ]: changes sign at a branch point, not at a fold
      MatrixXd a(n() + 1, n() + 1);
      a.topRows(n()) = jacobian(x);
      a.row(n()) = t.transpose();
      f.tests.push_back(a.determinant());
    }
    return f;
  }

  const ContinuationProblem& problem() const { return pr_; }
  const ContinuationSettings& settings() const { return set_; }

 private:
  const ContinuationProblem& pr_;
  const ContinuationSettings& set_;
};

double test_value(const FamilyPoint& f, int j) { return j < 0 ? f.tangent_parameter : f.tests[j]; }

/// The zeros of the test functions between two accepted points a and b, located along the chord.
void locate_events(const ContinuationCurve& c, const VectorXd& xa, const FamilyPoint& fa,
                   const VectorXd& xb, const FamilyPoint& fb,
                   std::vector<BifurcationEvent>& events) {
  const double length = (xb - xa).norm();
  if (!(length > 0)) return;
  const VectorXd d = (xb - xa) / length;
  const int count = static_cast<int>(c.problem().tests.size());
  for (int j = -1; j < count + (c.problem().branch_points ? 1 : 0); ++j) {
    const double ga = test_value(fa, j), gb = test_value(fb, j);
    if (!(std::isfinite(ga) && std::isfinite(gb)) || ga == 0 || (ga < 0) == (gb < 0)) continue;
    FamilyPoint at;
    auto g = [&](double sigma) {
      VectorXd x = xa + sigma * d;
      if (!c.correct(x, d, xa + sigma * d)) return std::numeric_limits<double>::quiet_NaN();
      at = c.evaluate(x, c.tangent(x, d));
      return test_value(at, j);
    };
    double root = length;
    if (gb != 0) {
      std::uintmax_t iterations = kLocationIterations;
      const auto r = boost::math::tools::toms748_solve(
          g, 0.0, length, ga, gb, boost::math::tools::eps_tolerance<double>(kLocationBits),
          iterations);
      root = 0.5 * (r.first + r.second);
    }
    if (!std::isfinite(g(root))) continue;
    const bool own = j >= 0 && j < count;  // one of the family's tests, not the fold or the BP
    const BifurcationType type = j < 0 ? BifurcationType::fold
                                 : own ? c.problem().tests[j].type
                                       : BifurcationType::branch_point;
    if (own && c.problem().tests[j].confirm && !c.problem().tests[j].confirm(at)) continue;
    events.push_back({type, at.parameter, at});
  }
}

/// Newton's method in u at fixed p (the start, and the last point exactly at p_end).
bool solve_at(const ContinuationCurve& c, VectorXd& x) {
  VectorXd normal = VectorXd::Zero(c.n() + 1);
  normal[c.n()] = 1.0;
  return c.correct(x, normal, x).has_value();
}

/// Where the march ends: past p_end with the last point exactly there (`range`); past p0 either
/// with no point there (`left_range`, a family) or with the last point exactly there (`range`,
/// a branch: both ends of the range are ends); at a branch point of the branch (`branch_point`).
struct Ends {
  double p0 = 0.0, p_end = 0.0;
  bool both_exact = false;
  bool stop_at_branch_point = false;
};

/// Predictor–corrector steps from the accepted point x (tangent t, already the family's last
/// point) until an end.
void march(const ContinuationCurve& c, VectorXd x, VectorXd t, const Ends& ends, Family& fam) {
  const ContinuationSettings& settings = c.settings();
  const int n = c.n();
  const double dir = ends.p_end > ends.p0 ? 1.0 : -1.0;
  double h = settings.initial_step;
  fam.end = "max_points";
  while (static_cast<int>(fam.points.size()) < settings.max_points) {
    VectorXd y = x + h * t;
    if (!ends.both_exact && (y[n] - ends.p0) * dir < 0) {  // the predictor turned back
      fam.end = "left_range";
      break;
    }
    if (ends.both_exact) {  // a branch's predictor past an end: the end itself at fixed p
      for (const double bound : {ends.p0, ends.p_end}) {
        if ((y[n] - bound) * (bound == ends.p0 ? -dir : dir) <= 0) continue;
        y = x + (bound - x[n]) / (y[n] - x[n]) * (y - x);
        y[n] = bound;
        break;
      }
    }
    const bool at_end = ends.both_exact && (y[n] == ends.p0 || y[n] == ends.p_end);
    const std::optional<int> its =
        at_end ? (solve_at(c, y) ? std::optional<int>(1) : std::nullopt) : c.correct(y, t, y);
    const VectorXd ty = its ? c.tangent(y, t) : t;
    const bool turned = its && std::acos(std::clamp(ty.dot(t), -1.0, 1.0)) > settings.max_angle;
    if (!its || turned) {
      h /= 2;
      if (h < settings.min_step) {
        fam.end = "step_underflow";
        break;
      }
      continue;
    }
    const double p = y[n];
    if (!ends.both_exact && (p - ends.p0) * dir < 0) {  // turned back past the start
      fam.end = "left_range";
      break;
    }
    bool last = false;
    for (const double bound : {ends.p_end, ends.p0}) {
      const double side = bound == ends.p_end ? dir : -dir;
      if (last || (bound == ends.p0 && !ends.both_exact) || (p - bound) * side < 0) continue;
      // past an end: the last point exactly there
      const double w = (bound - x[n]) / (p - x[n]);
      y = x + w * (y - x);
      y[n] = bound;
      if (!solve_at(c, y)) {
        fam.end = "step_underflow";
        return;
      }
      last = true;
    }
    const VectorXd t_new = c.tangent(y, t);
    FamilyPoint fy = c.evaluate(y, t_new);
    const std::size_t before = fam.events.size();
    locate_events(c, x, fam.points.back(), y, fy, fam.events);
    fam.points.push_back(std::move(fy));
    x = y;
    t = t_new;
    if (last) {
      fam.end = "range";
      break;
    }
    if (ends.stop_at_branch_point &&
        std::any_of(
            fam.events.begin() + static_cast<std::ptrdiff_t>(before), fam.events.end(),
            [](const BifurcationEvent& e) { return e.type == BifurcationType::branch_point; })) {
      fam.end = "branch_point";
      break;
    }
    if (*its <= 2) h = std::min(1.5 * h, settings.max_step);
    if (*its >= 5) h *= 0.7;
  }
}

}  // namespace

Family continue_family(const ContinuationProblem& problem, const VectorXd& u0, double p0,
                       double p_end, const ContinuationSettings& settings) {
  if (problem.unknowns < 0 || u0.size() != problem.unknowns || !u0.allFinite() ||
      !std::isfinite(p0) || !std::isfinite(p_end) || p0 == p_end) {
    throw InputError("continuation: expected a finite start of " +
                     std::to_string(problem.unknowns) + " values and a range p0 != p_end");
  }
  const ContinuationCurve c(problem, settings);
  const int n = problem.unknowns;
  const double dir = p_end > p0 ? 1.0 : -1.0;
  VectorXd x(n + 1);
  x << u0, p0;
  if (!solve_at(c, x)) {
    throw InputError(
        "continuation: Newton's method found no solution of the family near the "
        "start at p = " +
        format_number(p0));
  }
  VectorXd axis = VectorXd::Zero(n + 1);
  axis[n] = dir;
  const VectorXd t = c.tangent(x, axis);
  Family fam;
  fam.points.push_back(c.evaluate(x, t));
  march(c, x, t, {p0, p_end, false, false}, fam);
  return fam;
}

Family continue_branch(const ContinuationProblem& problem, const VectorXd& u_star, double p_star,
                       const VectorXd& direction, double p_min, double p_max,
                       const ContinuationSettings& settings) {
  const int n = problem.unknowns;
  if (n < 1 || u_star.size() != n || direction.size() != n + 1 || !u_star.allFinite() ||
      !direction.allFinite() || !(direction.norm() > 0) || !std::isfinite(p_star) ||
      !(p_min < p_max) || p_star < p_min || p_star > p_max) {
    throw InputError("branch: expected a finite branch point of " + std::to_string(n) +
                     " values in [p_min, p_max] and a nonzero direction of " +
                     std::to_string(n + 1));
  }
  ContinuationProblem pr = problem;
  pr.branch_points = true;
  const ContinuationCurve c(pr, settings);
  VectorXd star(n + 1);
  star << u_star, p_star;
  const VectorXd d = direction.normalized();
  // The first point of the branch: the branch point moved by the switching step along the new
  // branch's direction, corrected on the hyperplane orthogonal to it (Keller 1977; AUTO's ISW).
  // Near the branch point [F_u F_p; dᵀ] is ill-conditioned (its least singular value is of the
  // order of the switching step), which magnifies the residual's round-off in the corrections:
  // this first correction may take four times the iterations.
  ContinuationSettings first = settings;
  first.max_newton *= 4;
  VectorXd x = star + settings.switch_step * d;
  if (!ContinuationCurve(pr, first).correct(x, d, x)) {
    throw InputError("branch: Newton's method found no point of the new branch at " +
                     format_number(settings.switch_step) +
                     " from the branch point at p = " + format_number(p_star));
  }
  Family fam;
  fam.points.push_back(c.evaluate(star, d));
  const VectorXd t = c.tangent(x, d);
  fam.points.push_back(c.evaluate(x, t));
  const double p_end = t[n] >= 0 ? p_max : p_min;
  march(c, x, t, {p_end == p_max ? p_min : p_max, p_end, true, true}, fam);
  return fam;
}

}  // namespace newtop
