// Branch switching from the resonance family (docs/continuation.md §2): at a flip onto the
// period-doubled family, at a branch point onto the asymmetric pair, both by 2-D shooting.

#include <cmath>
#include <numbers>

#include "newtop/orbit/orbit_families.hpp"

namespace newtop {

namespace {

// Relative step of the central difference of the residual in the parameter: ε^(1/3).
constexpr double kParameterStep = 6e-6;

/// The unit null vector of a singular 2 × 2 matrix, from its larger row.
Vec2 null_vector(const Mat2& a) {
  const int i = a.row(0).norm() >= a.row(1).norm() ? 0 : 1;
  const Vec2 v(-a(i, 1), a(i, 0));
  if (!(v.norm() > 0)) {
    throw InputError("branch: the critical multiplier is double with two eigenvectors (M = ±I)");
  }
  return v.normalized();
}

/// x(2πN; x0) − x0 − (Mπ, 0), the periodicity residual of the resonance r over its period.
Vec2 periodicity(const PitchProblem& p, const SpinOrbitResonance& r, const Vec2& x0) {
  return pitch_advance(p, x0, 0.0, 2 * std::numbers::pi * r.periods) - x0 -
         Vec2(r.half_turns * std::numbers::pi, 0.0);
}

}  // namespace

Family resonance_branch(const PitchPath& path, const BifurcationEvent& event, double p_min,
                        double p_max, const SpinOrbitResonance& r, double line,
                        const ContinuationSettings& settings) {
  if (event.type != BifurcationType::flip && event.type != BifurcationType::branch_point) {
    throw InputError(std::string("branch: expected a flip or a branch_point, found a ") +
                     to_string(event.type));
  }
  path(p_min);  // throws for an end outside the problem's domain, before any work
  path(p_max);
  const bool flip = event.type == BifurcationType::flip;
  const SpinOrbitResonance rb =
      flip ? SpinOrbitResonance{r.p, r.q, 2 * r.periods, 2 * r.half_turns} : r;
  const double period = 2 * std::numbers::pi * rb.periods;
  const Vec2 star(line, event.point.values[1]);
  // The critical eigenvector of the parent's monodromy: the new branch leaves along (v, 0).
  const Mat2 m = periodic_solution_at(path(event.value), r, line, star[1]).monodromy;
  const Vec2 v = null_vector(flip ? Mat2(m + Mat2::Identity()) : Mat2(m - Mat2::Identity()));
  ContinuationProblem pr;
  pr.unknowns = 2;
  pr.residual = [=, &path](const Eigen::VectorXd& u, double p) -> Eigen::VectorXd {
    return periodicity(path(p), rb, Vec2(u[0], u[1]));
  };
  pr.jacobian = [=, &path](const Eigen::VectorXd& u, double p) {
    const Vec2 x0(u[0], u[1]);
    const PitchFlow f = pitch_flow(path(p), x0, 0.0, period);
    const double h = kParameterStep * std::max(1.0, std::abs(p));
    Vec2 dp;
    try {
      dp = (periodicity(path(p + h), rb, x0) - periodicity(path(p - h), rb, x0)) / (2 * h);
    } catch (const InputError&) {  // p − h outside the path's domain (e < 0): one-sided, O(h²)
      dp = (4 * periodicity(path(p + h), rb, x0) - 3 * periodicity(path(p), rb, x0) -
            periodicity(path(p + 2 * h), rb, x0)) /
           (2 * h);
    }
    Eigen::MatrixXd j(2, 3);
    j << f.phi - Mat2::Identity(), dp;
    return j;
  };
  pr.evaluate = [=, &path](const Eigen::VectorXd& u, double p) {
    const PeriodicSolution s = periodic_solution_at(path(p), rb, u[0], u[1]);
    FamilyPoint pt;
    pt.values = Eigen::Vector2d(u[0], u[1]);
    pt.period = period;
    pt.multipliers = {s.multipliers[0], s.multipliers[1]};
    pt.stability = to_string(s.stability);
    pt.tests = {s.monodromy.trace() + 2};
    return pt;
  };
  pr.tests = {{BifurcationType::flip, {}}};
  Eigen::Vector3d direction(v[0], v[1], 0.0);
  return continue_branch(pr, star, event.value, direction, p_min, p_max, settings);
}

}  // namespace newtop
