#pragma once
/// \file
/// The Newtonian potential of a mass distribution with unit gravitational constant.

#include "newtop/core/types.hpp"

namespace newtop {

/// Φ(x) = ∫ dm / |x − ρ| (positive, G = 1) and ∇Φ(x) (points towards the body).
struct Attraction {
  double potential = 0.0;
  Vec3 gradient = Vec3::Zero();
};

}  // namespace newtop
