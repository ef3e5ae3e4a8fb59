#pragma once
/// \file
/// The exact sub-flows of the Lie–Poisson splitting (docs/model.md §4), as explicit operations on a
/// phase point (m, γ) held as plain numbers in a working frame (the body axes relabelled by a
/// proper signed permutation, so that every formula keeps its form):
///
/// - rotation about the working axis e_i by an angle θ: the flow of a function of m_i alone
///   (½(m_i − k_i)²/I_i, or ½α m_i² + β m_i); m and γ turn alike, m_i is constant;
/// - spin: γ turns about m by the angle φ = τ|m| (the flow of ½|m|²/I over τ = t/I); m is constant;
/// - kick: m += t γ × ∂V/∂γ with γ fixed (the flow of V(γ) over t).
///
/// Each is a Poisson map that keeps γ·γ and m·γ exactly. A stepper composes them; the attitude
/// R ∈ SO(3) and the tangent map are carried by applying the same operation to them (a rotation
/// turns R's rows about the same axis; the kick leaves R), which is why they are kept separate.

#include <cmath>

namespace newtop {

namespace detail {

/// Two numbers handled as one: a packed SSE2 register for double (GCC and clang vector extension),
/// a plain pair otherwise.
template <class R>
struct PairOf {
  struct type {
    R x, y;
    R operator[](int i) const { return i == 0 ? x : y; }
    friend type operator+(type a, type b) { return {a.x + b.x, a.y + b.y}; }
    friend type operator-(type a, type b) { return {a.x - b.x, a.y - b.y}; }
    friend type operator*(type a, type b) { return {a.x * b.x, a.y * b.y}; }
  };
};
template <>
struct PairOf<double> {
  typedef double type __attribute__((vector_size(16)));
};

}  // namespace detail

/// Two numbers that one operation treats alike (see PairOf).
template <class R>
using Pair = typename detail::PairOf<R>::type;

/// m and γ in a working frame, held as the pairs (m_i, γ_i): a rotation about another axis turns
/// both lanes alike, so one packed operation updates m and γ together. The scalar is a parameter
/// so that a long-double shadow of a run can measure its round-off (bench/brouwer.cpp).
template <class R>
struct PhaseT {
  Pair<R> v[3];

  R m(int i) const { return v[i][0]; }
  R g(int i) const { return v[i][1]; }
  void set(int i, R m_i, R g_i) { v[i] = Pair<R>{m_i, g_i}; }
};
using Phase = PhaseT<double>;

namespace detail {

// Taylor coefficients of sin θ/θ = Σ (−1)ⁿ θ²ⁿ/(2n+1)! and (1 − cos θ)/θ² = Σ (−1)ⁿ θ²ⁿ/(2n+2)!.
template <class R>
inline constexpr R kS1 = R(-1) / 6;
template <class R>
inline constexpr R kS2 = R(1) / 120;
template <class R>
inline constexpr R kS3 = R(-1) / 5040;
template <class R>
inline constexpr R kS4 = R(1) / 362880;
template <class R>
inline constexpr R kS5 = R(-1) / 39916800;
template <class R>
inline constexpr R kC0 = R(1) / 2;
template <class R>
inline constexpr R kC1 = R(-1) / 24;
template <class R>
inline constexpr R kC2 = R(1) / 720;
template <class R>
inline constexpr R kC3 = R(-1) / 40320;
template <class R>
inline constexpr R kC4 = R(1) / 3628800;
template <class R>
inline constexpr R kC5 = R(-1) / 479001600;
// Below θ² = 1e-4 (|θ| ≤ 0.01) the series are cut after θ⁶ (sin θ/θ) and θ⁶ ((1 − cos θ)/θ²):
// the first term dropped is below θ⁸/9! = 2.8e-22, far under the 1.1e-16 of a rounding. Below
// θ² = 1e-2 (|θ| ≤ 0.1) they are cut after θ¹⁰: the first term dropped is below θ¹²/13! = 1.6e-22.
inline constexpr double kShortSeries = 1e-4;
inline constexpr double kLongSeries = 1e-2;

}  // namespace detail

/// sin θ and cos θ − 1 to round-off: for |θ| ≤ 0.1 (the usual case, θ = h ω_i) by their Taylor
/// series with constant coefficients (no division), in Estrin's scheme so that the dependency
/// chain stays short; for larger angles by std::sin and cos θ − 1 = −2 sin²(θ/2), which avoids
/// the cancellation of cos θ − 1.
template <class R>
[[gnu::always_inline]] inline void sin_cosm1(R theta, R& s, R& cm1) {
  using namespace detail;
  const R t2 = theta * theta;
  if (t2 <= kShortSeries) {
    const R t4 = t2 * t2;
    s = theta + (theta * t2) * ((kS1<R> + t2 * kS2<R>)+t4 * kS3<R>);
    cm1 = -t2 * ((kC0<R> + t2 * kC1<R>)+t4 * (kC2<R> + t2 * kC3<R>));
  } else if (t2 <= kLongSeries) {
    const R t4 = t2 * t2, t8 = t4 * t4;
    s = theta + (theta * t2) * ((kS1<R> + t2 * kS2<R>)+t4 * (kS3<R> + t2 * kS4<R>)+t8 * kS5<R>);
    cm1 = -t2 * ((kC0<R> + t2 * kC1<R>)+t4 * (kC2<R> + t2 * kC3<R>)+t8 * (kC4<R> + t2 * kC5<R>));
  } else {
    const R sin_half = std::sin(theta / 2), cos_half = std::cos(theta / 2);
    s = 2 * sin_half * cos_half;
    cm1 = -2 * sin_half * sin_half;
  }
}

/// sin φ/φ and (1 − cos φ)/φ² as functions of φ², to round-off (same series and branches as
/// sin_cosm1).
template <class R>
inline void spin_factors(R phi2, R& f1, R& f2) {
  using namespace detail;
  if (phi2 <= kShortSeries) {
    const R p4 = phi2 * phi2;
    f1 = 1 + phi2 * ((kS1<R> + phi2 * kS2<R>)+p4 * kS3<R>);
    f2 = (kC0<R> + phi2 * kC1<R>)+p4 * (kC2<R> + phi2 * kC3<R>);
  } else if (phi2 <= kLongSeries) {
    const R p4 = phi2 * phi2, p8 = p4 * p4;
    f1 = 1 + phi2 * ((kS1<R> + phi2 * kS2<R>)+p4 * (kS3<R> + phi2 * kS4<R>)+p8 * kS5<R>);
    f2 = (kC0<R> + phi2 * kC1<R>)+p4 * (kC2<R> + phi2 * kC3<R>)+p8 * (kC4<R> + phi2 * kC5<R>);
  } else {
    const R phi = std::sqrt(phi2);
    const R sin_half = std::sin(phi / 2);
    f1 = std::sin(phi) / phi;
    f2 = 2 * sin_half * sin_half / phi2;
  }
}

/// Turns m and γ about the working axis e_I by θ (sin θ = s, cos θ − 1 = cm1), in the direction
/// of the flow γ̇ = γ × (θ̇ e_I): x_J' = c x_J + s x_K, x_K' = c x_K − s x_J with (I, J, K) cyclic,
/// for x = m and x = γ at once. Written as x + increment, so that the rounding is relative to the
/// increment and a cos θ − 1 far below ε is not lost.
template <int I, class R>
[[gnu::always_inline]] inline void rotate(PhaseT<R>& z, R s, R cm1) {
  constexpr int J = (I + 1) % 3, K = (I + 2) % 3;
  const Pair<R> a = z.v[J], b = z.v[K], S{s, s}, C{cm1, cm1};
  z.v[J] = a + (C * a + S * b);
  z.v[K] = b + (C * b - S * a);
}

/// The flow of ½α m_I² + β m_I over time t (β = −k_I/I_I for the kinetic energy ½(m_I − k_I)²/I_I
/// with α = 1/I_I): m and γ turn about e_I by θ = t α m_I + t β. The arguments are ta = t α and
/// tb = t β, computed by the caller off the serial chain through m.
///
/// Passengers (pairs of body-frame vectors held as PhaseT, e.g. the rows of the attitude R) turn
/// with the same sin θ and cos θ − 1.
template <int I, class R, class... A>
[[gnu::always_inline]] inline void axis_flow(PhaseT<R>& z, R ta, R tb, A&... passengers) {
  R s, cm1;
  sin_cosm1(z.m(I) * ta + tb, s, cm1);
  rotate<I>(z, s, cm1);
  (rotate<I>(passengers, s, cm1), ...);
}

/// Both lanes x of a pair of vectors turned by Rodrigues' formula x' = x + f₁ u × x + f₂ u × (u ×
/// x).
template <class R>
inline void rodrigues(PhaseT<R>& a, R u0, R u1, R u2, R f1, R f2) {
  const Pair<R> x0 = a.v[0], x1 = a.v[1], x2 = a.v[2];
  const Pair<R> U0{u0, u0}, U1{u1, u1}, U2{u2, u2}, F1{f1, f1}, F2{f2, f2};
  const Pair<R> c0 = U1 * x2 - U2 * x1, c1 = U2 * x0 - U0 * x2, c2 = U0 * x1 - U1 * x0;
  const Pair<R> d0 = U1 * c2 - U2 * c1, d1 = U2 * c0 - U0 * c2, d2 = U0 * c1 - U1 * c0;
  a.v[0] = x0 + (F1 * c0 + F2 * d0);
  a.v[1] = x1 + (F1 * c1 + F2 * d1);
  a.v[2] = x2 + (F1 * c2 + F2 * d2);
}

/// The flow of ½|m|²/I over time t (tau = t/I): m is constant and γ turns about m by −τ|m|
/// (γ̇ = γ × m/I), by Rodrigues' formula with u = −τ m: γ' = γ + f₁ u × γ + f₂ u × (u × γ),
/// f₁ = sin φ/φ, f₂ = (1 − cos φ)/φ², φ = |u|. No square root for the usual small angles.
/// Passengers (both lanes) turn by the same formula with the same u, f₁ and f₂.
template <class R, class... A>
inline void spin_flow(PhaseT<R>& z, R tau, A&... passengers) {
  const R m0 = z.m(0), m1 = z.m(1), m2 = z.m(2);
  const R u0 = -tau * m0, u1 = -tau * m1, u2 = -tau * m2;
  R f1, f2;
  spin_factors(u0 * u0 + u1 * u1 + u2 * u2, f1, f2);
  const R g0 = z.g(0), g1 = z.g(1), g2 = z.g(2);
  const R c0 = u1 * g2 - u2 * g1, c1 = u2 * g0 - u0 * g2, c2 = u0 * g1 - u1 * g0;
  const R d0 = u1 * c2 - u2 * c1, d1 = u2 * c0 - u0 * c2, d2 = u0 * c1 - u1 * c0;
  z.set(0, m0, g0 + (f1 * c0 + f2 * d0));
  z.set(1, m1, g1 + (f1 * c1 + f2 * d1));
  z.set(2, m2, g2 + (f1 * c2 + f2 * d2));
  (rodrigues(passengers, u0, u1, u2, f1, f2), ...);
}

}  // namespace newtop
