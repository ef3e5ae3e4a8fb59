#pragma once
/// \file
/// Mass models of an extended body (spec §2): point masses, a homogeneous polyhedron, a homogeneous
/// ellipsoid and box. Each gives its mass properties at O and the Newtonian potential
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
  /// Throws InputError (field "points") for an empty set, a mass <= 0 or a non-finite number.
  PointMasses(std::vector<double> masses, std::vector<Vec3> positions);
  const std::vector<double>& masses() const { return masses_; }
  const std::vector<Vec3>& positions() const { return positions_; }

 private:
  std::vector<double> masses_;
  std::vector<Vec3> positions_;
};

/// Homogeneous ellipsoid of density σ > 0, semi-axes (a, b, c) > 0 along the frame's axes, centred
/// at `center`.
struct Ellipsoid {
  Vec3 semi_axes;
  double density;
  Vec3 center = Vec3::Zero();
  /// Checks the numbers; throws InputError naming semi_axes, density or center.
  static Ellipsoid make(const Vec3& semi_axes, double density, const Vec3& center = Vec3::Zero());
};

/// Homogeneous box with edge lengths `dimensions` along the frame's axes, centred at `center`, as
/// a closed polyhedron of 12 outward triangles.
Polyhedron make_box(const Vec3& dimensions, double density, const Vec3& center = Vec3::Zero());

/// Any of the mass models.
using MassModel = std::variant<PointMasses, Polyhedron, Ellipsoid>;

MassProperties mass_properties(const PointMasses& p);
/// Exact, by signed tetrahedra from O.
MassProperties mass_properties(const Polyhedron& p);
MassProperties mass_properties(const Ellipsoid& e);
MassProperties mass_properties(const MassModel& m);

/// Largest distance of a mass element from O (a radius of the sphere about O holding the body).
double max_radius(const MassModel& m);

Attraction attraction(const PointMasses& p, const Vec3& x);
/// Exterior and interior potential of a homogeneous ellipsoid in Carlson's symmetric elliptic
/// integrals R_F, R_D (Boost.Math).
Attraction attraction(const Ellipsoid& e, const Vec3& x);
/// Dispatches on the model; a polyhedron is evaluated by attraction(Polyhedron, x, threads).
Attraction attraction(const MassModel& m, const Vec3& x, int threads = 1);

}  // namespace newtop
