#pragma once
/// \file
/// The Newtonian potential of a mass distribution with unit gravitational constant, its gradient,
/// the moment it exerts about O, and their derivatives.

#include "newtop/core/types.hpp"

namespace newtop {

/// At a point x outside the body (the centre's position in the body frame; x = −Rγ in docs/model.md
/// §2): Φ(x) = ∫ dm / |x − ρ| (positive, G = 1) and ∇Φ(x) (points towards the body), and `moment` =
/// ∫ ρ × x dm / |x − ρ|³ = ∇Φ(x) × x, the moment about O of the attraction of a unit mass at x on
/// the body. Far away ∇Φ ≈ −M x/|x|³ is nearly parallel to x, so the cross product would cancel
/// about (|x|/r)² of its digits; every mass model forms `moment` without that cancellation where it
/// can (docs/exact_field.md, "Accuracy far from the body").
struct Attraction {
  double potential = 0.0;
  Vec3 gradient = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};

/// Second derivatives at x: the gravity-gradient tensor ∇∇Φ(x) (symmetric, trace 0 outside the
/// body) and the Jacobian of the moment, ∂(∇Φ × x)/∂x = [∇Φ]× − [x]× ∇∇Φ, formed without the
/// monopole's cancellation (the monopole contributes exactly zero to it).
struct GravityGradient {
  Mat3 tensor = Mat3::Zero();
  Mat3 moment_jacobian = Mat3::Zero();
};

}  // namespace newtop
