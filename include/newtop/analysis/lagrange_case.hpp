#pragma once
/// \file
/// The Lagrange-like case (docs/model.md §6): A = B, centre of mass on the symmetry axis (x0 = y0 =
/// 0), k = (0, 0, k3). r is constant and γ3 obeys
///   γ̇3² = F(γ3) = (1 − γ3²)(E − a γ3 − a1 γ3²) − (b − β γ3)²,
/// E = (2h − C r² − λA)/A, a = 2Mg z0/A, a1 = λ(C − A)/A, b = f/A, β = (C r + k3)/A (= c r, c =
/// C/A, when k3 = 0). γ3(t) is the elliptic function
///   γ3 = u1 + F′(u1) / (4 (℘(t − t1) − F″(u1)/24))
/// (Whittaker & Watson §20.6) with u1 a root of F (a turning point reached at t1) and ℘ formed with
/// the invariants g2, g3 of the quartic, evaluated through Jacobi elliptic functions (Abramowitz &
/// Stegun 18.9). The proper-rotation angle ψ (γ1 = sinθ sinψ, γ2 = sinθ cosψ, cosθ = γ3) follows by
/// quadrature of ψ̇ = r − (b − βγ3) γ3/(1 − γ3²), and p, q from the area integral and γ̇3.

#include <array>
#include <vector>

#include "newtop/model/basic_model.hpp"

namespace newtop {

/// The γ3 quartic F(u) = Σ coefficient[i] uⁱ and the parameters of docs/model.md §6.
struct LagrangeQuartic {
  double E = 0, a = 0, a1 = 0, b = 0, c = 0;  ///< docs/model.md §6 (c = C/A)
  double r = 0;                               ///< the constant r
  double beta = 0;                            ///< (C r + k3)/A
  std::array<double, 5> coefficient{};        ///< F(u) = Σ coefficient[i] uⁱ
};

/// The exact motion in the Lagrange-like case from one initial state (data only).
struct LagrangeCase {
  LagrangeQuartic quartic;
  std::vector<double> real_roots;  ///< real roots of F, ascending
  double u1 = 0, u2 = 0;           ///< turning values of γ3 (γ3 ∈ [min, max] of them)
  bool steady = false;             ///< γ3 constant (regular precession, or the vertical)
  double nutation_period = 0;      ///< period of γ3(t) (∞ when steady)
  // Weierstrass data: ℘ through Jacobi functions with modulus k and argument w = scale·z.
  double g2 = 0, g3 = 0;
  bool three_real = true;  ///< discriminant g2³ − 27 g3² > 0
  double e_low = 0;        ///< e3 (three real roots) or e2 (one real root)
  double e_span = 0;       ///< e1 − e3, or H2 = √(3e2² − g2/4)
  double modulus = 0, scale = 0;
  double z0 = 0;           ///< z at t = 0
  double direction = 1;    ///< z = z0 + direction · t
  double dF = 0, d2F = 0;  ///< F′(u1), F″(u1)
  double psi0 = 0;         ///< ψ at t = 0
  State initial;
  Vec3 inertia;
  Vec3 gyrostat;
};

/// True when the Lagrange-like case applies (the conditions of docs/model.md §5: lagrange_holds).
bool lagrange_case_holds(const QuadraticModel& model);

/// The quartic of docs/model.md §6 for the model and state.
LagrangeQuartic lagrange_quartic(const QuadraticModel& model, const State& x0);

/// The solution from x0. Throws InputError when the case does not apply or x0 is not a unit γ.
LagrangeCase lagrange_case(const QuadraticModel& model, const State& x0);

/// γ3(t) and γ̇3(t), the elliptic function.
std::array<double, 2> lagrange_gamma3(const LagrangeCase& s, double t);

/// The full state at t (ψ by Gauss–Kronrod quadrature).
State lagrange_state(const LagrangeCase& s, double t);

}  // namespace newtop
