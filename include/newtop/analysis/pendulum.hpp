#pragma once
/// \file
/// Plane pendulum motion (docs/model.md §10): with the centre of mass in the principal plane z0 = 0
/// and k1 = k2 = 0, the motion p = q = γ3 = 0 is invariant. With γ = (cos φ, −sin φ, 0) and φ̇ = r,
///   C φ̈ = Mg (x0 sin φ + y0 cos φ) − (λ/2)(B − A) sin 2φ,
///   V(φ) = Mg (x0 cos φ − y0 sin φ) + (λ/2)(A cos²φ + B sin²φ),  ½Cφ̇² + V(φ) = h.
/// Pure gravity gradient (Mg r0 = 0): a pendulum in θ = 2φ (shifted by π when λ(B − A) < 0),
/// θ̈ = −ω0² sin θ, ω0² = |λ(B − A)|/C, solved by Jacobi functions: libration
/// sin(θ/2) = k sn(ω0 t + u0, k), rotation θ/2 = ±am(k ω0 t + u0, 1/k). Otherwise by quadrature:
/// t = ∫ dφ/φ̇ along an unfolded angle α (φ = c − d cos α between the turning points, or φ = φ0 ± α
/// for a rotation), inverted by Newton's method.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "newtop/model/basic_model.hpp"

namespace newtop {

enum class PendulumKind { libration, rotation, equilibrium };
std::string to_string(PendulumKind k);

/// The plane motion from one initial state (data only).
struct Pendulum {
  PendulumKind kind = PendulumKind::equilibrium;
  bool closed_form = false;          ///< Mg r0 = 0: Jacobi functions, else quadrature
  double C = 0, k3 = 0;              ///< moment about the normal, gyrostat k3
  double mgx = 0, mgy = 0;           ///< M g x0, M g y0
  double lambda_ = 0, A = 0, B = 0;  ///< λ and the moments in the plane
  double h = 0;                      ///< energy ½ C r² + V(φ)
  double phi0 = 0, r0 = 0;           ///< φ(0), r(0)
  double period = 0;  ///< libration period, or time of a full turn of φ (∞ at rest)
  std::vector<double> turning_points;  ///< φ1 < φ2 for a libration
  // Closed form: θ = 2φ − shift, modulus, frequency ω0, u0, sense σ, θ(0) reduced to (−π, π].
  double modulus = 0, omega0 = 0, u0 = 0, sense = 1, theta0 = 0;
  // Quadrature: φ(α) = c − d cos α (libration) or φ0 + sense·α (rotation), α(0) = alpha0.
  double c = 0, d = 0, alpha0 = 0;
};

/// V(φ) of docs/model.md §10.
double pendulum_potential(const Pendulum& p, double phi);

/// True when the plane motion applies to (model, x0): Mg z0 = 0, k1 = k2 = 0 and p = q = γ3 = 0 at
/// the start (to 1e-12). `why` receives the failed condition.
bool pendulum_holds(const QuadraticModel& model, const State& x0, std::string* why = nullptr);

/// The solution from x0; throws InputError if pendulum_holds is false.
Pendulum pendulum(const QuadraticModel& model, const State& x0);

/// φ(t) and r(t) = φ̇(t).
std::array<double, 2> pendulum_angle(const Pendulum& p, double t);

/// The full state at t: γ = (cos φ, −sin φ, 0), m = (0, 0, C r + k3).
State pendulum_state(const Pendulum& p, double t);

}  // namespace newtop
