#include "newtop/analysis/brun_separation.hpp"

#include <cmath>
#include <limits>

namespace newtop {
namespace {

double half_range(const BrunCurve& k, int s) {
  return 0.5 * (k.root[k.upper[s]] - k.root[k.lower[s]]);
}

/// √|u_s − root[r]| at φ, signed when root[r] bounds the range: √(2d) sin(φ/2) at the lower end,
/// √(2d) cos(φ/2) at the upper end.
double signed_root(const BrunCurve& k, int s, int r, double phi) {
  const double d = half_range(k, s);
  const double a = k.root[k.lower[s]], b = k.root[k.upper[s]];
  const double sh = std::sin(0.5 * phi), ch = std::cos(0.5 * phi);
  if (r == k.lower[s]) return std::sqrt(2 * d) * sh;
  if (r == k.upper[s]) return std::sqrt(2 * d) * ch;
  const double x = k.root[r];
  // u − x = (a − x) + 2d sin²(φ/2) below the range, x − u = (x − b) + 2d cos²(φ/2) above it.
  return x <= a ? std::sqrt((a - x) + 2 * d * sh * sh) : std::sqrt((x - b) + 2 * d * ch * ch);
}

/// P′(e_i) = Π_{j≠i}(e_i − e_j).
double dP(const BrunCurve& k, int i) {
  return (k.e[i] - k.e[(i + 1) % 3]) * (k.e[i] - k.e[(i + 2) % 3]);
}

/// Sign of (u_s − e_j)(u_s − e_k) inside the range of u_s (u1 ∈ [e1, e2], u2 ∈ [e2, e3]).
double pair_sign(int s, int j, int k) { return (j <= s ? 1.0 : -1.0) * (k <= s ? 1.0 : -1.0); }

}  // namespace

double brun_u_at(const BrunCurve& k, int s, double phi) {
  const double a = k.root[k.lower[s]], b = k.root[k.upper[s]];
  const double d = 0.5 * (b - a);
  // From the nearer end: a + 2d sin²(φ/2) or b − 2d cos²(φ/2).
  const double sh = std::sin(0.5 * phi), ch = std::cos(0.5 * phi);
  return sh * sh <= 0.5 ? a + 2 * d * sh * sh : b - 2 * d * ch * ch;
}

double brun_reduced_R_at(const BrunCurve& k, int s, double phi) {
  double r = std::abs(k.lambda_);
  for (int j = 0; j < 5; ++j) {
    if (j == k.lower[s] || j == k.upper[s]) continue;
    const double q = signed_root(k, s, j, phi);
    r *= q * q;
  }
  return r;
}

BrunPoint brun_point(const BrunCurve& k, const State& s) {
  const State x = to_working_frame(k, s);
  const Vec3 y = x.m.cross(x.gamma);
  BrunPoint p;
  p.u = brun_u(k, x.gamma);
  for (int t = 0; t < 2; ++t) {
    double w = 0.0;
    for (int i = 0; i < 3; ++i) {
      w += x.gamma[i] * y[i] * (p.u[t] - k.e[(i + 1) % 3]) * (p.u[t] - k.e[(i + 2) % 3]);
    }
    p.w[t] = w;
  }
  return p;
}

State brun_state_at(const BrunCurve& k, const BrunAngles& a) {
  // ρ[s][r] = signed √|u_s − root[r]|.
  double rho[2][5];
  std::array<double, 2> u{};
  for (int s = 0; s < 2; ++s) {
    u[s] = brun_u_at(k, s, a.phi[s]);
    for (int r = 0; r < 5; ++r) rho[s][r] = signed_root(k, s, r, a.phi[s]);
  }
  State x;
  for (int i = 0; i < 3; ++i) {
    x.gamma[i] = a.S[i] * rho[0][i] * rho[1][i] / std::sqrt(std::abs(dP(k, i)));
  }
  // γ_j γ_k w_s (u_s − e_i)/P(u_s) = S_j S_k σ_s √|λ| sgn((u_s − e_j)(u_s − e_k))
  //   ρ_{s,i} ρ_{s,ν1} ρ_{s,ν2} ρ_{t,j} ρ_{t,k} / √|P′(e_j) P′(e_k)|: the squares of ρ_{s,j} and
  //   ρ_{s,k} cancel, so the formula stays finite where γ_j or γ_k vanishes.
  const double sl = std::sqrt(std::abs(k.lambda_));
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, kk = (i + 2) % 3;
    const double norm = std::sqrt(std::abs(dP(k, j) * dP(k, kk)));
    double sum = 0.0;
    for (int s = 0; s < 2; ++s) {
      const int t = 1 - s;
      const double term = kBrunOrientation[s] * sl * pair_sign(s, j, kk) * rho[s][i] * rho[s][3] *
                          rho[s][4] * rho[t][j] * rho[t][kk];
      sum += term / (u[t] - u[s]);
    }
    x.m[i] = (k.e[kk] - k.e[j]) * a.S[j] * a.S[kk] * sum / norm;
  }
  return from_working_frame(k, x);
}

BrunAngles brun_angles(const BrunCurve& k, const State& s) {
  const BrunPoint p = brun_point(k, s);
  BrunAngles best;
  for (int t = 0; t < 2; ++t) {
    const double a = k.root[k.lower[t]], b = k.root[k.upper[t]];
    const double c = 0.5 * (a + b), d = 0.5 * (b - a);
    const double cosphi = (c - p.u[t]) / d;
    const double sinphi =
        kBrunOrientation[t] * p.w[t] / (d * std::sqrt(brun_reduced_R(k, t, p.u[t])));
    double phi = std::atan2(sinphi, cosphi);
    if (phi < 0) phi += 2 * std::acos(-1.0);
    best.phi[t] = phi;
  }
  // The signs S_i: the one of the eight choices that gives back the state.
  double best_err = std::numeric_limits<double>::infinity();
  const std::array<double, 2> phi = best.phi;
  for (int code = 0; code < 8; ++code) {
    BrunAngles cand{phi, {code & 1 ? -1.0 : 1.0, code & 2 ? -1.0 : 1.0, code & 4 ? -1.0 : 1.0}};
    const State back = brun_state_at(k, cand);
    const double err = (back.m - s.m).squaredNorm() + (back.gamma - s.gamma).squaredNorm();
    if (err < best_err) best_err = err, best = cand;
  }
  return best;
}

}  // namespace newtop
