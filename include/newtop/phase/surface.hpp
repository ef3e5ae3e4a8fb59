#pragma once
/// \file
/// The surface of a Poincaré section: g(ω, m, γ, n) = 0 for an affine expression in the state's
/// components, written as `gamma3 = 0`, `omega1 = 0` or `gamma1 + 0.5*gamma2 = 0.1`. The orbit
/// normal's components n (`normal1..3`) exist only on an orbit scenario (docs/orbit.md).
///
/// Grammar (whitespace between tokens is free):
///
///     surface := term { ("+" | "-") term } "=" number
///     term    := [ "+" | "-" ] [ number "*" ] component        (first term only: the sign)
///     component := omega1 | omega2 | omega3 | m1 | m2 | m3 | gamma1 | gamma2 | gamma3
///                | normal1 | normal2 | normal3
///
/// A number is a finite decimal (std::from_chars); every component appears at most once, and at
/// least one coefficient is nonzero. Anything else is bad input.

#include <array>
#include <string>
#include <string_view>

#include "newtop/model/basic_model.hpp"

namespace newtop::phase {

/// a_ω·ω + a_m·m + a_γ·γ + a_n·n = c, as written.
struct Surface {
  std::string text;  ///< the expression as given
  Vec3 a_omega = Vec3::Zero(), a_m = Vec3::Zero(), a_gamma = Vec3::Zero();
  Vec3 a_normal = Vec3::Zero();  ///< the orbit normal's coefficients (orbit scenarios only)
  double c = 0.0;

  /// A surface of γ alone (no ω, m or n term): a plane cutting the Poisson sphere.
  bool of_gamma_only() const {
    return a_omega.isZero(0.0) && a_m.isZero(0.0) && a_normal.isZero(0.0);
  }
  /// A term in the orbit normal's components.
  bool has_normal() const { return !a_normal.isZero(0.0); }
};

/// Parses the expression; throws InputError "<field>: expected …, found …" (one line).
Surface parse_surface(std::string_view text, std::string_view field = "--surface");

/// Throws InputError naming `field` when the surface has a term in the orbit normal: a body
/// scenario (the fixed-centre model) has no orbit normal.
void require_body_surface(const Surface& s, std::string_view field = "--surface");

/// The surface in the Lie–Poisson variables: ω = I⁻¹(m − k) turns it into
/// g(m, γ, n) = b_m·m + b_γ·γ + b_n·n − d, affine in (m, γ, n). On a body's state (no n) b_n is
/// zero (the constructor refuses a surface with a term in n unless `with_normal`).
struct SurfaceFunction {
  Vec3 b_m = Vec3::Zero(), b_gamma = Vec3::Zero(), b_normal = Vec3::Zero();
  double d = 0.0;

  SurfaceFunction(const Surface& s, const Body& body, bool with_normal = false);
  double operator()(const State& x) const { return b_m.dot(x.m) + b_gamma.dot(x.gamma) - d; }
  /// The size of the terms of g at x, |b_m||m| + |b_γ||γ| + |d|: the rounding of g is a few ε of
  /// it.
  double scale(const State& x) const {
    return b_m.norm() * x.m.norm() + b_gamma.norm() * x.gamma.norm() + std::abs(d);
  }
  /// The same on a state with an orbit normal (an OrbitState), |b_n||n| added to the scale.
  template <class X>
  requires requires(const X& x) { x.normal; }
  double operator()(const X& x) const {
    return b_m.dot(x.m) + b_gamma.dot(x.gamma) + b_normal.dot(x.normal) - d;
  }
  template <class X>
  requires requires(const X& x) { x.normal; }
  double scale(const X& x) const {
    return b_m.norm() * x.m.norm() + b_gamma.norm() * x.gamma.norm() +
           b_normal.norm() * x.normal.norm() + std::abs(d);
  }
};

}  // namespace newtop::phase
