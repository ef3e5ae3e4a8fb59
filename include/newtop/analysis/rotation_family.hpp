#pragma once
/// \file
/// The family of permanent rotations about a principal axis pointing at the centre in the spin
/// rate Ω (docs/model.md §9), continued by pseudo-arclength with a Krein-collision test
/// (docs/continuation.md §3).

#include "newtop/analysis/continuation.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

/// The spin γ = e_axis, ω = Ω e_axis of `model` (r0 along e_axis or zero, so that it is a fixed
/// point at every Ω; InputError otherwise) from Ω = omega0 to omega1. The family is known
/// explicitly in Ω (no unknowns); FamilyPoint: values (Ω), the four leaf eigenvalues,
/// stability "stable" (linearly) or "unstable", tests: the discriminant Δ = c2² − 4c0 of the
/// characteristic polynomial s⁴ + c2 s² + c0 of the leaf Jacobian J (c2 = −tr(J²)/2, c0 = det J,
/// from the model's own linearisation). A sign change of Δ with c2 > 0 (a double σ = s² < 0) is a
/// Krein collision: two pairs of imaginary eigenvalues meet and leave the axis, Beletsky's
/// threshold Ω* = √λ(√a + √b)/(1 + √(ab)) for the largest axis.
Family rotation_family(const QuadraticModel& model, int axis, double omega0, double omega1,
                       const ContinuationSettings& settings = {});

/// The principal axis of the largest moment (the first of equal largest moments).
int largest_axis(const Body& body);

}  // namespace newtop
