#pragma once
/// \file
/// The exact flow of the free rigid body H = ½ m·I⁻¹m (Euler–Poinsot, spec §4), and a splitting
/// stepper that uses it as a sub-flow: free body + potential kick. The angular momentum m(t) is
/// given by Jacobi elliptic functions (Boost.Math) and the attitude γ(t) by Euler angles about the
/// (space-fixed) angular momentum, the precession angle by quadrature of its rate.

#include <vector>

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/model/model.hpp"

namespace newtop {

/// The exact free motion from one initial state: data only, evaluated by the free functions below.
///
/// In a working frame x' = frame · x (a signed permutation, det = +1) with moments (A, B, C)
/// ordered so that m circulates about the C axis (ascending when L² > 2E·I_mid, descending
/// otherwise):
///   m1' = α1 cn(u), m2' = α2 sn(u), m3' = σ3 α3 dn(u), u = u0 + ν t,
///   ν = σ3 sgn(C − B) √((C − B)(L² − 2EA)/(ABC)), k² = (B − A)(2EC − L²) / ((C − B)(L² − 2EA)),
/// with L = |m| and 2E = m·I⁻¹m (Landau & Lifshitz, Mechanics §37). When m × ω = 0 (rotation about
/// a principal axis, a sphere, or rest) the motion is a permanent rotation and m is constant.
struct EulerPoinsot {
  Vec3 inertia;                   ///< (A, B, C) of the body, body frame
  State initial;                  ///< state at t = 0
  bool permanent = false;         ///< m constant: γ turns uniformly about ω
  Mat3 frame = Mat3::Identity();  ///< working frame: x' = frame · x
  Vec3 moments = Vec3::Zero();    ///< (A, B, C) in the working frame
  Vec3 amplitude = Vec3::Zero();  ///< (α1, α2, σ3 α3)
  double modulus = 0.0;           ///< k of the Jacobi functions, 0 ≤ k ≤ 1
  double nu = 0.0;                ///< dU/dt (signed)
  double u0 = 0.0;                ///< argument at t = 0
  double period = 0.0;            ///< period of m(t), 4K(k)/|ν| (∞ for a permanent rotation)
  int pole = 2;                   ///< body axis used as the pole of the Euler angles
};

/// The free motion from x0. Throws InputError if the body carries a gyrostatic moment (k ≠ 0) or x0
/// is not finite.
EulerPoinsot euler_poinsot(const Body& body, const State& x0);

/// m(t) = Iω(t), exact (Jacobi elliptic functions).
Vec3 angular_momentum(const EulerPoinsot& s, double t);

/// The full state (m(t), γ(t)): γ(t) from the Euler angles about the fixed angular momentum, the
/// precession angle φ(t) = ∫ |m| (m_a²/I_a + m_b²/I_b)/(m_a² + m_b²) dt by Gauss–Kronrod quadrature
/// ((a, b, pole) cyclic).
State free_body_state(const EulerPoinsot& s, double t);

/// The precession angle φ(t) − φ(0) about the angular momentum (0 for a permanent rotation): whole
/// periods by the trapezoidal rule (geometric convergence for a periodic integrand), the rest by
/// adaptive Gauss–Kronrod.
double precession_angle(const EulerPoinsot& s, double t);

/// Exact free-body flow over time h: free_body_state(euler_poinsot(body, x), h).
State free_body_flow(const Body& body, const State& x, double h);

/// Splitting of H = ½ m·I⁻¹m + V(γ) into the exact free-body flow F and the potential kick K
/// (m += h γ × ∂V/∂γ): the symmetric base K(h/2) F(h) K(h/2), composed to order 4, 6 or 8 by a
/// CompositionTable. Both sub-flows are Poisson maps preserving γ·γ and m·γ, so every composition
/// is a Poisson integrator; it is exact for the free body (V = 0). Needs k = 0 (the step throws
/// InputError otherwise).
class FreeBodySplittingStepper {
 public:
  explicit FreeBodySplittingStepper(const CompositionTable& table);

  int order() const { return order_; }
  /// Sub-flows per step (kicks + free-body flows).
  std::size_t stages() const { return program_.size(); }

  template <Field F>
  void step(const BasicModel<F>& model, State& x, double h) {
    for (const auto& [kick, fraction] : program_) {
      if (kick) {
        x.m += fraction * h * x.gamma.cross(grad_gamma(model, x.gamma));
      } else {
        x = free_body_flow(model.body, x, fraction * h);
      }
    }
  }

 private:
  int order_;
  std::vector<std::pair<bool, double>> program_;  // (is a kick, fraction of h)
};

}  // namespace newtop
