#pragma once
/// \file
/// Mass models of an extended body (docs/model.md §2): point masses, a homogeneous polyhedron, a
/// homogeneous ellipsoid and box. Each gives its mass properties at O and the Newtonian potential
/// Φ(x) = ∫ dm / |x − ρ| (unit gravitational constant) with its gradient, from which the exact
/// field of a centre at x = −Rγ follows (newtop/exact/exact_field.hpp).

#include <array>
#include <memory>
#include <variant>
#include <vector>

#include "newtop/core/types.hpp"
#include "newtop/exact/attraction.hpp"
#include "newtop/exact/polyhedron.hpp"

namespace newtop {

/// Mass M, centre of mass r0 and inertia tensor J = ∫ (|ρ|² 1 − ρρᵀ) dm at O, in the frame in which
/// the mass model is given (the user's frame).
struct MassProperties {
  double mass = 0.0;
  Vec3 center_of_mass = Vec3::Zero();
  Mat3 inertia_tensor = Mat3::Zero();
};

/// Point masses m_i > 0 at ρ_i.
class PointMasses {
 public:
  /// Throws InputError (field "points") for an empty set, a mass <= 0, a non-finite number, or
  /// masses and positions whose mass properties (Σ m_i, Σ m_i |ρ_i|²) overflow.
  PointMasses(std::vector<double> masses, std::vector<Vec3> positions);
  const std::vector<double>& masses() const { return masses_; }
  const std::vector<Vec3>& positions() const { return positions_; }
  /// D = Σ m_i ρ_i = M r0, summed in twice the working precision (Ogita–Rump–Oishi Dot2) and
  /// rounded once: a centre of mass that nearly vanishes keeps its relative accuracy, which the
  /// moment far away needs (its dipole term is D/R² against the quadrupole's r²/R³).
  const Vec3& first_moment() const { return first_moment_; }

 private:
  std::vector<double> masses_;
  std::vector<Vec3> positions_;
  Vec3 first_moment_ = Vec3::Zero();
};

/// Homogeneous ellipsoid of density σ > 0, semi-axes (a, b, c) > 0 along the frame's axes, centred
/// at `center`.
struct Ellipsoid {
  Vec3 semi_axes;
  double density;
  Vec3 center = Vec3::Zero();
  /// Checks the numbers, and that the mass and inertia tensor do not overflow; throws InputError
  /// naming semi_axes, density or center.
  static Ellipsoid make(const Vec3& semi_axes, double density, const Vec3& center = Vec3::Zero());
};

/// Homogeneous box with edge lengths `dimensions` along the frame's axes, centred at `center`, as
/// a closed polyhedron of 12 outward triangles.
Polyhedron make_box(const Vec3& dimensions, double density, const Vec3& center = Vec3::Zero());

/// Any of the mass models: a std::variant (std::visit, std::get, std::holds_alternative and index()
/// work on it as on the variant), made a class of its own so that the model can hold one while it
/// only declares it (newtop/model/model.hpp: the model does not know mass models).
class MassModel : public std::variant<PointMasses, Polyhedron, Ellipsoid> {
 public:
  using std::variant<PointMasses, Polyhedron, Ellipsoid>::variant;
};

MassProperties mass_properties(const PointMasses& p);
/// Exact, by signed tetrahedra from O.
MassProperties mass_properties(const Polyhedron& p);
MassProperties mass_properties(const Ellipsoid& e);
MassProperties mass_properties(const MassModel& m);

/// Largest distance of a mass element from O (a radius of the sphere about O holding the body).
double max_radius(const MassModel& m);

/// Direct sums over the points. With s = |x|, d_i² = s² (1 + t_i), the moment is
/// Σ m_i ρ_i × x / d_i³ = (D + Σ m_i ρ_i (w_i⁻³ − 1)) × x / s³, w_i = √(1 + t_i), with D the
/// accurate first moment and w⁻³ − 1 in a form without subtraction: no cancellation however far x
/// is (each term is of the size of the result).
Attraction attraction(const PointMasses& p, const Vec3& x);
/// ∇∇Φ = Σ m (3 (x − ρ)(x − ρ)ᵀ/d⁵ − 1/d³) and the moment's Jacobian
/// [Σ m ρ/d³]× − 3 Σ m (ρ × x)(x − ρ)ᵀ/d⁵, with the sums Σ m ρ/dⁿ split as for the moment.
GravityGradient gravity_gradient(const PointMasses& p, const Vec3& x);
/// The moment ∇Φ × x (bit for bit as attraction(p, x)) and its derivative along u, the moment's
/// Jacobian of gravity_gradient applied to u, in one pass: with ρ̃ = ρ/s, x̂ = x/s and
/// q = Σ m ρ̃ (ρ̃·u)/w⁵, (D + Σ m ρ̃ (w⁻³ − 1)) × u − 3 ((D + Σ m ρ̃ (w⁻⁵ − 1)) × x̂)(x̂·u) + 3 q × x̂,
/// over s².
MomentAndDerivative moment_with_derivative(const PointMasses& p, const Vec3& x, const Vec3& u);

/// Exterior and interior potential of a homogeneous ellipsoid in Carlson's symmetric elliptic
/// integrals R_F, R_D (Boost.Math): with u = x − centre, q_i = a_i² + λ (λ the confocal parameter,
/// the largest root of Σ u_i²/q_i = 1 outside, 0 inside) and k = πσabc,
/// Φ = k (2 R_F(q) − ⅔ Σ u_i² R_D(q_j, q_k, q_i)), ∇Φ_i = −(4/3) k u_i R_D(q_j, q_k, q_i).
/// λ = |u|² − ν with ν ∈ [min a², max a²] the root of Σ u_i² (ν − a_i²)/q_i = 0, which stays well
/// conditioned however far x is.
Attraction attraction(const Ellipsoid& e, const Vec3& x);
/// ∇∇Φ = −(4/3) k diag(R_D(q_j, q_k, q_i)) + 4k u uᵀ ⊘ (q qᵀ) / (√(q1 q2 q3) Σ_l u_l²/q_l²) outside
/// (the second term from ∂λ/∂u = 2 (u ⊘ q)/Σ u_l²/q_l²), the first alone inside.
GravityGradient gravity_gradient(const Ellipsoid& e, const Vec3& x);

/// Dispatches on the model; a polyhedron is evaluated by attraction(Polyhedron, x, threads).
Attraction attraction(const MassModel& m, const Vec3& x, int threads = 1);
GravityGradient gravity_gradient(const MassModel& m, const Vec3& x, int threads = 1);
/// Point masses in one pass; the other models by attraction and gravity_gradient.
MomentAndDerivative moment_with_derivative(const MassModel& m, const Vec3& x, const Vec3& u,
                                           int threads = 1);

}  // namespace newtop
