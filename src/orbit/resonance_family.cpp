// The symmetric periodic solutions of one spin–orbit resonance continued along a path of (e, k)
// (docs/continuation.md §2; the shooting of docs/orbit.md §9).

#include <cmath>
#include <numbers>

#include "newtop/orbit/orbit_families.hpp"

namespace newtop {

namespace {

// Relative step of the central difference of the residual in the parameter: ε^(1/3).
constexpr double kFamilyParameterStep = 6e-6;

}  // namespace

PitchPath eccentricity_path(double k) {
  return [k](double e) { return pitch_problem(e, k); };
}

PitchPath inertia_path(const Vec3& inertia, int index, double eccentricity) {
  if (index < 0 || index > 2) {
    throw InputError("inertia index: expected 0, 1 or 2, found " + std::to_string(index));
  }
  return [inertia, index, eccentricity](double p) {
    Vec3 I = inertia;
    I[index] = p;
    const Body body = Body::from_principal(I, 1.0, Vec3::Zero());  // checks the moments
    return pitch_problem(eccentricity, (body.B() - body.A()) / body.C());
  };
}

Family resonance_family(const PitchPath& path, double p0, double p1, const SpinOrbitResonance& r,
                        double line, double guess, const ContinuationSettings& settings) {
  if (line != 0.0 && line != std::numbers::pi / 2) {
    throw InputError("line: expected theta(0) = 0 or pi/2 (a reversibility line), found " +
                     format_number(line));
  }
  path(p1);  // throws for an end outside the problem's domain, before any work
  const PitchProblem start = path(p0);
  const double half = std::numbers::pi * r.periods;
  const double target = line + r.half_turns * std::numbers::pi / 2;
  const std::vector<PeriodicSolution> found = periodic_solutions(start, r);
  const PeriodicSolution* best = nullptr;
  for (const PeriodicSolution& s : found) {
    if (s.theta0 == line &&
        (!best || std::abs(s.dtheta0 - guess) < std::abs(best->dtheta0 - guess)))
      best = &s;
  }
  if (!best) {
    throw InputError("resonance " + std::to_string(r.p) + ":" + std::to_string(r.q) +
                     ": no symmetric periodic solution on the line theta(0) = " +
                     format_number(line) + " at the range's first value " + format_number(p0));
  }
  ContinuationProblem pr;
  pr.unknowns = 1;
  auto theta_half = [&path, line, half](double dtheta0, double p) {
    return pitch_advance(path(p), Vec2(line, dtheta0), 0.0, half)[0];
  };
  pr.residual = [=](const Eigen::VectorXd& u, double p) {
    return Eigen::VectorXd::Constant(1, theta_half(u[0], p) - target);
  };
  pr.jacobian = [=, &path](const Eigen::VectorXd& u, double p) {
    const PitchFlow f = pitch_flow(path(p), Vec2(line, u[0]), 0.0, half);
    const double h = kFamilyParameterStep * std::max(1.0, std::abs(p));
    Eigen::MatrixXd j(1, 2);
    double dp = 0.0;
    try {
      dp = (theta_half(u[0], p + h) - theta_half(u[0], p - h)) / (2 * h);
    } catch (const InputError&) {  // p − h outside the path's domain (e < 0): one-sided, O(h²)
      dp = (-3 * theta_half(u[0], p) + 4 * theta_half(u[0], p + h) - theta_half(u[0], p + 2 * h)) /
           (2 * h);
    }
    j << f.phi(0, 1), dp;
    return j;
  };
  pr.evaluate = [=, &path](const Eigen::VectorXd& u, double p) {
    const PitchProblem problem = path(p);
    const PeriodicSolution s = periodic_solution_at(problem, r, line, u[0]);
    const PitchFlow f = pitch_flow(problem, Vec2(line, u[0]), 0.0, half);
    FamilyPoint pt;
    pt.values = Eigen::Vector2d(line, u[0]);
    pt.period = 2 * std::numbers::pi * r.periods;
    pt.multipliers = {s.multipliers[0], s.multipliers[1]};
    pt.stability = to_string(s.stability);
    pt.tests = {s.monodromy.trace() + 2, f.phi(1, 0)};
    return pt;
  };
  pr.tests = {{BifurcationType::flip, {}}, {BifurcationType::branch_point, {}}};
  return continue_family(pr, Eigen::VectorXd::Constant(1, best->dtheta0), p0, p1, settings);
}

}  // namespace newtop
