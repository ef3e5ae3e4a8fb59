#pragma once
/// \file
/// The surface of a Poincaré section: g(ω, m, γ) = 0 for an affine expression in the state's
/// components, written as `gamma3 = 0`, `omega1 = 0` or `gamma1 + 0.5*gamma2 = 0.1`.
///
/// Grammar (whitespace between tokens is free):
///
///     surface := term { ("+" | "-") term } "=" number
///     term    := [ "+" | "-" ] [ number "*" ] component        (first term only: the sign)
///     component := omega1 | omega2 | omega3 | m1 | m2 | m3 | gamma1 | gamma2 | gamma3
///
/// A number is a finite decimal (std::from_chars); every component appears at most once, and at
/// least one coefficient is nonzero. Anything else is bad input.

#include <array>
#include <string>
#include <string_view>

#include "newtop/model/basic_model.hpp"

namespace newtop::phase {

/// a_ω·ω + a_m·m + a_γ·γ = c, as written.
struct Surface {
  std::string text;  ///< the expression as given
  Vec3 a_omega = Vec3::Zero(), a_m = Vec3::Zero(), a_gamma = Vec3::Zero();
  double c = 0.0;

  /// A surface of γ alone (no ω or m term): a plane cutting the Poisson sphere.
  bool of_gamma_only() const { return a_omega.isZero(0.0) && a_m.isZero(0.0); }
};

/// Parses the expression; throws InputError "<field>: expected …, found …" (one line).
Surface parse_surface(std::string_view text, std::string_view field = "--surface");

/// The surface in the Lie–Poisson variables of a body: ω = I⁻¹(m − k) turns it into
/// g(m, γ) = b_m·m + b_γ·γ − d, affine in (m, γ).
struct SurfaceFunction {
  Vec3 b_m = Vec3::Zero(), b_gamma = Vec3::Zero();
  double d = 0.0;

  SurfaceFunction(const Surface& s, const Body& body);
  double operator()(const State& x) const { return b_m.dot(x.m) + b_gamma.dot(x.gamma) - d; }
  /// The size of the terms of g at x, |b_m||m| + |b_γ||γ| + |d|: the rounding of g is a few ε of
  /// it.
  double scale(const State& x) const {
    return b_m.norm() * x.m.norm() + b_gamma.norm() * x.gamma.norm() + std::abs(d);
  }
};

}  // namespace newtop::phase
