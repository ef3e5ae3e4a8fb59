#pragma once
/// \file
/// The exact flow of the free rigid body H = ½ m·I⁻¹m (Euler–Poinsot, docs/model.md §4), and a
/// splitting stepper that uses it as a sub-flow: free body + potential kick. The angular momentum
/// m(t) is given by Jacobi elliptic functions and the attitude γ(t) by Euler angles about the
/// (space-fixed) angular momentum, the precession angle in closed form through the elliptic
/// integral of the third kind (Carlson's R_F and R_J; Boost.Math in double precision throughout).

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/integrate/splitting.hpp"
#include "newtop/model/basic_model.hpp"

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
///
/// Precession about m with the body axis p as pole: dφ/dt = L (2E − m_p²/I_p)/(L² − m_p²), where
/// L² − m_p² = c (1 − n sn²u) for constants c > 0 and n < 1, so that
///   φ(t) − φ(0) = (2E − L²/I_p) L t/c + L/I_p t + (L (2E − L²/I_p)/(c ν)) (ΔΠ − ν t),
/// with ΔΠ = Π(n; am u, k) − Π(n; am u0, k) (Celledoni, Fassò, Säfström & Zanna, SIAM J. Sci.
/// Comput. 30 (2008) 2084). With Carlson's form Π(n; φ) = F(φ) + (n/3) sin³φ R_J(cos²φ, dn²,
/// 1, 1 − n sin²φ) for |φ| ≤ π/2, F(am u) = u and Π(n; φ + jπ) = Π(n; φ) + 2jΠ(n), only R_J at the
/// two ends (and the complete R_J when u crosses a half period) is needed.
struct EulerPoinsot {
  Vec3 inertia;                   ///< (A, B, C) of the body, body frame
  State initial;                  ///< state at t = 0
  bool permanent = false;         ///< m constant: γ turns uniformly about ω
  Mat3 frame = Mat3::Identity();  ///< working frame: x' = frame · x
  Vec3 moments = Vec3::Zero();    ///< (A, B, C) in the working frame
  Vec3 amplitude = Vec3::Zero();  ///< (α1, α2, σ3 α3)
  double modulus = 0.0;           ///< k of the Jacobi functions, 0 ≤ k ≤ 1
  double complementary = 1.0;     ///< k'² = 1 − k²
  double nu = 0.0;                ///< dU/dt (signed)
  double u0 = 0.0;                ///< argument at t = 0
  double period = 0.0;            ///< period of m(t), 4K(k)/|ν| (∞ for a permanent rotation)
  int pole = 2;                   ///< body axis used as the pole of the Euler angles
  double momentum_norm = 0.0;     ///< |m|, an invariant of the motion
  double quarter = 0.0;           ///< K(k) (∞ on the separatrix)
  double characteristic = 0.0;    ///< n of Π(n; φ, k)
  double mean_rate = 0.0;         ///< L/I_p + L (2E − L²/I_p)/c
  double third_kind_scale = 0.0;  ///< L (2E − L²/I_p) n / (3 c ν)
  double third_kind_start = 0.0;  ///< sin³φ R_J(…) at the start, reduced to |φ| ≤ π/2
  int half_periods_start = 0;     ///< u0 = u0r + 2 j K with |u0r| ≤ K: this j
  Vec3 jacobi_start = Vec3(0.0, 1.0, 1.0);  ///< (sn u0, cn u0, dn u0)
  Mat3 euler_start = Mat3::Identity();      ///< the Euler frame of the initial m
};

/// The free motion from x0. Throws InputError if the body carries a gyrostatic moment (k ≠ 0) or x0
/// is not finite.
EulerPoinsot euler_poinsot(const Body& body, const State& x0);

/// m(t) = Iω(t), exact (Jacobi elliptic functions).
Vec3 angular_momentum(const EulerPoinsot& s, double t);

/// The full state (m(t), γ(t)): γ(t) from the Euler angles about the fixed angular momentum and the
/// precession angle φ(t) − φ(0) = ∫ |m| (m_a²/I_a + m_b²/I_b)/(m_a² + m_b²) dt ((a, b, pole)
/// cyclic), in closed form.
State free_body_state(const EulerPoinsot& s, double t);

/// The same, with the rotation G(t) of the motion: γ(t) = G(t) γ(0) (every body-frame vector fixed
/// in space moves alike).
State free_body_state(const EulerPoinsot& s, double t, Mat3& G);

/// The attitude at t of the motion started with the attitude q0 (body → inertial): R(t) = R(0)
/// G(t)ᵀ, in closed form.
Quaternion free_body_attitude(const EulerPoinsot& s, const Quaternion& q0, double t);

/// The Euler angles of the free motion (3-1-3, newtop/model/attitude.hpp): body → N is
/// R_z(φ) R_x(θ) R_z(ψ) Q, with N the frame fixed in space whose z axis is along the angular
/// momentum and whose x axis is the line of nodes at t = 0 (φ(0) = 0), and Q the permutation of
/// the body axes (a, b, pole) → (x, y, z) with a = pole + 1, b = pole + 2 (mod 3) (Q = I for pole
/// 2). Precession φ(t) = precession_angle(s, t), nutation cos θ = m_pole/|m|, spin (sin ψ, cos ψ) ∝
/// (m_a, m_b), m = m(t) in the body frame (Landau & Lifshitz §37). Returned as (φ, θ, ψ). Not for
/// a permanent rotation (s.permanent: m is constant and the turn is G of free_body_state).
Vec3 free_body_euler_angles(const EulerPoinsot& s, double t);

/// Q above, as a rotation.
Quaternion free_body_pole_frame(const EulerPoinsot& s);

/// The precession angle φ(t) − φ(0) about the angular momentum (0 for a permanent rotation).
double precession_angle(const EulerPoinsot& s, double t);

/// Its rate dφ/dt = |m| (m_a²/I_a + m_b²/I_b)/(m_a² + m_b²) at the angular momentum m.
double precession_rate(const EulerPoinsot& s, const Vec3& m);

/// Exact free-body flow over time h: free_body_state(euler_poinsot(body, x), h), computed for
/// |ν h| < π (within a half period of m) from sn cn dn of the start and of ν h by the addition
/// theorems, without the complete integral K and the start argument u0 (two R_F fewer).
State free_body_flow(const Body& body, const State& x, double h);

/// Splitting of H = ½ m·I⁻¹m + V(γ) into the exact free-body flow F and the potential kick K
/// (m += h γ × ∂V/∂γ): the symmetric base K(h/2) F(h) K(h/2), composed to order 4, 6 or 8 by a
/// CompositionTable, or a near-integrable table's own steps. Both sub-flows are Poisson maps
/// preserving γ·γ and m·γ, so every composition is a Poisson integrator; it is exact for the free
/// body (V = 0). Needs k = 0 (the step throws InputError otherwise).
class FreeBodySplittingStepper : public SplittingStepper {
 public:
  explicit FreeBodySplittingStepper(const CompositionTable& table)
      : SplittingStepper(table, SplitOrdering{{0, 1, 2}, true, false, FreeBodySplit::exact}) {}
};

}  // namespace newtop
