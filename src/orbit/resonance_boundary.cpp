// The loci of the resonance family's folds, flips and pitchforks in a second parameter: the
// boundaries of a stability chart as curves (docs/continuation.md §2).

#include <cmath>
#include <numbers>

#include "newtop/orbit/orbit_families.hpp"

namespace newtop {

namespace {}  // namespace

PitchPlanePath pitch_plane_path(const Vec3& inertia, double eccentricity, int p_key, int q_key) {
  for (const int key : {p_key, q_key}) {
    if (key < kEccentricityKey || key > 2) {
      throw InputError(
          "parameter: expected the eccentricity or a principal moment 0, 1, 2, found "
          "code " +
          std::to_string(key));
    }
  }
  if (p_key == q_key) throw InputError("parameter: expected two different keys, found the same");
  return [=](double p, double q) {
    double e = eccentricity;
    Vec3 I = inertia;
    (p_key == kEccentricityKey ? e : I[p_key]) = p;
    (q_key == kEccentricityKey ? e : I[q_key]) = q;
    const Body body = Body::from_principal(I, 1.0, Vec3::Zero());  // checks the moments
    return pitch_problem(e, (body.B() - body.A()) / body.C());
  };
}

Family resonance_boundary(const PitchPlanePath& path, const BifurcationEvent& event, double q0,
                          double q1, const SpinOrbitResonance& r, double line,
                          const ContinuationSettings& settings) {
  if (event.type == BifurcationType::krein) {
    throw InputError(
        "boundary: a Krein collision does not occur on a family of Beletsky's "
        "equation (two multipliers)");
  }
  path(event.value, q1);  // throws for an end outside the problem's domain, before any work
  const double half = std::numbers::pi * r.periods, period = 2 * std::numbers::pi * r.periods;
  const double target = line + r.half_turns * std::numbers::pi / 2;
  const BifurcationType type = event.type;
  ContinuationProblem pr;
  pr.unknowns = 2;
  pr.residual = [=, &path](const Eigen::VectorXd& u, double q) {
    const PitchProblem problem = path(u[1], q);
    const PitchFlow h = pitch_flow(problem, Vec2(line, u[0]), 0.0, half);
    double g = 0.0;
    if (type == BifurcationType::fold) {
      g = h.phi(0, 1);
    } else if (type == BifurcationType::branch_point) {
      g = h.phi(1, 0);
    } else {
      g = pitch_flow(problem, Vec2(line, u[0]), 0.0, period).phi.trace() + 2;
    }
    return Eigen::Vector2d(h.x[0] - target, g);
  };
  pr.evaluate = [=, &path](const Eigen::VectorXd& u, double q) {
    const PeriodicSolution s = periodic_solution_at(path(u[1], q), r, line, u[0]);
    FamilyPoint pt;
    pt.values = Eigen::Vector3d(line, u[0], u[1]);
    pt.period = period;
    pt.multipliers = {s.multipliers[0], s.multipliers[1]};
    pt.stability = to_string(s.stability);
    return pt;
  };
  const Eigen::Vector2d u0(event.point.values[1], event.value);
  return continue_family(pr, u0, q0, q1, settings);
}

}  // namespace newtop
