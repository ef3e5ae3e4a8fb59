// Periodic solutions of Beletsky's equation by 2-D shooting (docs/orbit.md §9): Newton's method on
// both initial values with the monodromy matrix, no symmetry assumed.

#include <cmath>
#include <numbers>

#include "newtop/orbit/spin_orbit.hpp"

namespace newtop {

namespace {

// Two starts that converge to θ(0) mod π and θ′(0) within this are the same solution.
constexpr double kSameSolution = 1e-7;

/// θ reduced to [−π/2, π/2) (the equation is π-periodic in θ).
double reduce(double theta) {
  return theta - std::numbers::pi * std::floor((theta + std::numbers::pi / 2) / std::numbers::pi);
}

}  // namespace

std::optional<PeriodicSolution> shoot_periodic(const PitchProblem& p, const SpinOrbitResonance& r,
                                               const Vec2& guess,
                                               const ShootingSettings& settings) {
  const double period = 2 * std::numbers::pi * r.periods;
  const Vec2 advance(r.half_turns * std::numbers::pi, 0.0);
  // F(x) and the flow (its Φ gives the Jacobian Φ − I).
  auto residual = [&](const Vec2& x, PitchFlow& f) {
    f = pitch_flow(p, x, 0.0, period);
    return Vec2(f.x - x - advance);
  };
  Vec2 x(reduce(guess[0]), guess[1]);
  PitchFlow flow;
  Vec2 F = residual(x, flow);
  for (int it = 0; it < settings.max_iterations; ++it) {
    if (!F.allFinite()) return std::nullopt;
    if (F.cwiseAbs().maxCoeff() <= settings.tolerance) {
      return periodic_solution_at(p, r, x[0], x[1]);
    }
    const Mat2 J = flow.phi - Mat2::Identity();
    if (!(std::abs(J.determinant()) > 1e-14 * std::max(1.0, J.cwiseAbs().maxCoeff()))) {
      return std::nullopt;
    }
    Vec2 step = J.inverse() * F;
    if (!step.allFinite()) return std::nullopt;
    if (step.norm() > settings.max_step) step *= settings.max_step / step.norm();
    // Backtracking: the Newton step, halved until |F| decreases (Armijo with a slope of 1e-4).
    bool accepted = false;
    for (double lambda = 1.0; lambda > 1e-6 && !accepted; lambda /= 2) {
      PitchFlow trial_flow;
      const Vec2 trial(reduce(x[0] - lambda * step[0]), x[1] - lambda * step[1]);
      const Vec2 trial_F = residual(trial, trial_flow);
      if (trial_F.allFinite() && trial_F.norm() <= (1 - 1e-4 * lambda) * F.norm()) {
        x = trial;
        F = trial_F;
        flow = trial_flow;
        accepted = true;
      }
    }
    if (!accepted) return std::nullopt;
  }
  return std::nullopt;
}

std::vector<PeriodicSolution> shoot_periodic_solutions(const PitchProblem& p,
                                                       const SpinOrbitResonance& r,
                                                       const ShootingGrid& grid) {
  if (grid.theta_samples < 1 || grid.rate_samples < 1) {
    throw InputError("shooting grid: expected >= 1 samples on each axis, found " +
                     std::to_string(grid.theta_samples) + " x " +
                     std::to_string(grid.rate_samples));
  }
  const double w =
      grid.half_window > 0 ? grid.half_window : std::max(0.5, 2 * std::sqrt(3 * std::abs(p.k)));
  const double centre = r.half_turns / (2.0 * r.periods);
  std::vector<PeriodicSolution> found;
  for (int i = 0; i < grid.theta_samples; ++i) {
    const double theta = -std::numbers::pi / 2 + std::numbers::pi * (i + 0.5) / grid.theta_samples;
    for (int j = 0; j < grid.rate_samples; ++j) {
      const double rate = centre - w + 2 * w * (j + 0.5) / grid.rate_samples;
      const auto s = shoot_periodic(p, r, Vec2(theta, rate));
      if (!s) continue;
      bool known = false;
      for (const PeriodicSolution& k : found) {
        known = known ||
                (std::abs(std::remainder(k.theta0 - s->theta0, std::numbers::pi)) < kSameSolution &&
                 std::abs(k.dtheta0 - s->dtheta0) < kSameSolution);
      }
      if (!known) found.push_back(*s);
    }
  }
  return found;
}

}  // namespace newtop
