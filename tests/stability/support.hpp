#pragma once
// Helpers shared by the stability tests: random models and a reference integrator.

#include <cmath>
#include <limits>
#include <random>

#include "newtop/integrate/methods.hpp"
#include "newtop/model/model.hpp"

namespace newtop::stability_test {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Uniform random number in [lo, hi].
inline double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// Uniform random unit vector.
inline Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

/// Body with random distinct moments in [1, 2] (the triangle inequality holds) and given r0.
inline Body random_body(std::mt19937& rng, const Vec3& r0) {
  return Body::from_principal(Vec3(uniform(rng, 1, 2), uniform(rng, 1, 2), uniform(rng, 1, 2)), 1.0,
                              r0);
}

/// Fixed step of the trajectory checks: the 6th-order splitting moves a fixed point by
/// O(h⁶) ≈ 1e-12 (the fixed point of its modified Hamiltonian) and samples every oscillation of
/// period ≳ 1 at least 100 times. An adaptive method is no use here: at a fixed point its error
/// estimate vanishes and it steps over the whole interval at once.
inline constexpr double kTrajectoryStep = 0.01;

/// Largest distance of the trajectory from x0 over [0, T] (max norm over m and γ), sampled at every
/// step of the 6th-order Lie–Poisson splitting, an integrator independent of the linear analysis.
inline double max_departure(const QuadraticModel& model, const State& x0, double T) {
  double d = 0.0;
  SplittingStepper stepper(composition_table("splitting6"));
  const Outcome out =
      integrate(stepper, model, x0, 0.0, T, IntegrateOptions{.step = kTrajectoryStep},
                [&](double, const State& s) {
                  d = std::max({d, (s.m - x0.m).cwiseAbs().maxCoeff(),
                                (s.gamma - x0.gamma).cwiseAbs().maxCoeff()});
                });
  return out.status == Status::finished ? d : std::numeric_limits<double>::infinity();
}

}  // namespace newtop::stability_test
