#pragma once
// Reference problems and derived tolerances shared by the tests.

#include <cmath>
#include <limits>
#include <random>

#include "newtop/integrate/methods.hpp"
#include "newtop/newtop.hpp"
#include "newtop/phase/chaos_run.hpp"
#include "newtop/phase/section_run.hpp"

namespace newtop::test {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

/// A generic (non-integrable, chaotic) model: distinct moments, centre of mass off every axis,
/// Newtonian λ > 0 and a gyrostat. Time scales are O(1).
inline QuadraticModel generic_model(Vec3 k = Vec3::Zero()) {
  return QuadraticModel{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3(0.3, 0.2, 0.1), k),
                        QuadraticField::coulomb(1.0, 0.5)};
}

inline State generic_state(const QuadraticModel& m) {
  return state_from_omega(m.body, Vec3(0.5, 1.1, -0.4), Vec3(0.48, -0.6, 0.64));
}

/// Brun's case: r0 = 0, k = 0, λ < 0 (Brun's N = 0.8).
inline QuadraticModel brun_model() {
  return QuadraticModel{Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                        QuadraticField::brun(0.8)};
}

/// A random start of a random Brun model: distinct moments obeying the triangle inequality
/// (A ∈ [1, 1.5], B ∈ A + [0.2, 0.7], C ∈ B + [0.2, A − 0.2]), λ uniform in [−2, 2] (0 → 0.5),
/// γ the normalised uniform cube point, m uniform in [−1, 1]³ — on the level f = 0 (m projected
/// normal to γ) when asked, else with |f| up to ~1.7.
struct RandomBrunLevel {
  QuadraticModel model;
  State x0;
};

inline RandomBrunLevel random_brun_level(std::mt19937_64& rng, bool level_f_zero = false) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const double A = 1.25 + 0.25 * U(rng), B = A + 0.45 + 0.25 * U(rng);
  const double C = B + 0.2 + (A - 0.4) * 0.5 * (1 + U(rng));
  const double lambda = 2.0 * U(rng);
  Vec3 g;  // drawn in order: the arguments of one call are evaluated in no fixed order
  for (int i = 0; i < 3; ++i) g[i] = U(rng);
  g.normalize();
  Vec3 m;
  for (int i = 0; i < 3; ++i) m[i] = U(rng);
  if (level_f_zero) m -= m.dot(g) * g;
  return {QuadraticModel{Body::from_principal(Vec3(A, B, C), 1.0, Vec3::Zero()),
                         QuadraticField::coulomb(0.0, lambda == 0.0 ? 0.5 : lambda)},
          State{m, g}};
}

/// Max-norm distance between two states.
inline double distance(const State& a, const State& b) {
  return std::max((a.m - b.m).cwiseAbs().maxCoeff(), (a.gamma - b.gamma).cwiseAbs().maxCoeff());
}

/// Reference solution by Fehlberg 7(8) at a tolerance near round-off.
inline State reference_solution(const QuadraticModel& model, const State& x0, double T,
                                double tol = 1e-14) {
  Fehlberg78Stepper s(tol, tol);
  return integrate(s, model, x0, 0.0, T, IntegrateOptions{}).state;
}

}  // namespace newtop::test
