// The synchronous odd family of Beletsky's equation at one point (e, k) of a sweep (docs/sweep.md
// "Orbit scenarios"): followed in e from the radial equilibrium of the circular orbit, so that a
// grid cell reports the member of that family, and no cell past the family's fold.

#include <cmath>
#include <numbers>

#include "newtop/orbit/libration.hpp"
#include "sweep_points.hpp"

namespace newtop::sweep {
namespace {

/// The longest step in e: the family's θ′(0) changes by ≲ 0.1 over it except near a fold.
constexpr double kMaxStep = 0.01;
/// The shortest: below it the family is taken to have ended (a fold between the last point and
/// the next; the grid resolves e far more coarsely).
constexpr double kMinStep = 1e-6;
/// Newton's method on θ(π) = 0 stops at |θ(π)| ≤ this: the flow's own accuracy (kPitchTolerance
/// 1e-13 per step over a half orbit).
constexpr double kResidual = 1e-12;
constexpr int kMaxIterations = 8;

struct Corrected {
  double dtheta0 = 0.0;
  double b = 0.0;  ///< ∂θ(π)/∂θ′(0): its sign changes at the family's fold
};

/// Newton's method on F(θ′(0)) = θ(π) with θ(0) = 0, F' = Φ₀₁(π, 0) from the variational equation.
std::optional<Corrected> correct(const PitchProblem& p, double guess) {
  double u = guess;
  for (int i = 0; i < kMaxIterations; ++i) {
    const PitchFlow f = pitch_flow(p, Vec2(0.0, u), 0.0, std::numbers::pi);
    const double b = f.phi(0, 1);
    if (std::abs(f.x[0]) <= kResidual) return Corrected{u, b};
    if (!(std::abs(b) > 0.0)) return std::nullopt;
    u -= f.x[0] / b;
    if (!std::isfinite(u)) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> synchronous_odd_rate(double eccentricity, double k) {
  PitchProblem p = pitch_problem(0.0, k);
  // At e = 0 the family starts at the equilibrium θ ≡ 0 (θ′(0) = 0).
  const std::optional<Corrected> start = correct(p, 0.0);
  if (!start) return std::nullopt;
  double e = 0.0, u = start->dtheta0, slope = 0.0, h = kMaxStep;
  const double b_sign = std::copysign(1.0, start->b);
  while (e < eccentricity) {
    const double next = std::min(e + h, eccentricity);
    p = pitch_problem(next, k);
    const std::optional<Corrected> c = correct(p, u + slope * (next - e));
    // A failed correction, or one whose ∂θ(π)/∂θ′(0) changed sign (past the fold onto the
    // family's other branch): a shorter step.
    if (!c || std::copysign(1.0, c->b) != b_sign) {
      h /= 2;
      if (h < kMinStep) return std::nullopt;
      continue;
    }
    slope = (c->dtheta0 - u) / (next - e);
    u = c->dtheta0;
    e = next;
    h = std::min(2 * h, kMaxStep);
  }
  return u;
}

}  // namespace newtop::sweep
