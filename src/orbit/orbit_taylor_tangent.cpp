// Taylor's method on the orbit's variational equations (newtop/orbit/orbit_taylor.hpp): with
// δω = I⁻¹ δm, each product of the right-hand side a × b becomes δa × b + a × δb, so on a circular
// orbit
//
//   δṁ = δm × ω + m × δω + λ (δγ × Iγ + γ × Iδγ),   δγ̇ = δγ × ω + γ × δω + ω0 (δn × γ + n × δγ),
//   δṅ = δn × ω + n × δω,
//
// and on an ellipse, in ν, the same products multiplied by the series of σ and σλ
// (orbit_taylor.cpp); δx^[k+1] = 1/(k + 1) × the coefficient k of the right-hand side, the Cauchy
// sums along the state's series. The step rule takes the max norm of each order over the state and
// the vectors.

#include <cmath>

#include "newtop/orbit/orbit_taylor.hpp"

namespace newtop::detail {
namespace {

constexpr int K = OrbitTaylorSeries::kMaxOrder + 1;
using Series3 = std::array<Vec3, K>;

/// The series of (m, γ, n), ω and Iγ of the state (or of a tangent vector, with `tangent`: no
/// gyrostatic moment in δω = I⁻¹ δm).
struct Vectors {
  Series3 m, g, n, w, ig;
  void set(const Body& body, int k, const Vec3& mk, const Vec3& gk, const Vec3& nk, bool tangent) {
    const auto i = static_cast<std::size_t>(k);
    m[i] = mk;
    g[i] = gk;
    n[i] = nk;
    w[i] = (k == 0 && !tangent ? Vec3(mk - body.gyrostat()) : mk).cwiseQuotient(body.inertia());
    ig[i] = body.inertia().cwiseProduct(gk);
  }
};

Vec3 vec(const std::array<double, 9>& x, int at) { return Vec3(x[at], x[at + 1], x[at + 2]); }

Vectors state_vectors(const Body& body, const OrbitTaylorSeries& s) {
  Vectors z;
  for (int k = 0; k <= s.order; ++k) {
    const auto& x = s.x[static_cast<std::size_t>(k)];
    z.set(body, k, vec(x, 0), vec(x, 3), vec(x, 6), false);
  }
  return z;
}

/// Σ_{j=0..k} δa^[j] × b^[k−j] + a^[j] × δb^[k−j]: the coefficient k of δ(a × b).
Vec3 tangent_cross(const Series3& da, const Series3& b, const Series3& a, const Series3& db,
                   int k) {
  Vec3 s = Vec3::Zero();
  for (int j = 0; j <= k; ++j) {
    const auto i = static_cast<std::size_t>(j), l = static_cast<std::size_t>(k - j);
    s += da[i].cross(b[l]) + a[i].cross(db[l]);
  }
  return s;
}

Vec3 scale_sum(const double* f, const Series3& v, int k) {
  Vec3 s = Vec3::Zero();
  for (int j = 0; j <= k; ++j) s += f[j] * v[static_cast<std::size_t>(k - j)];
  return s;
}

/// Expands every column with rhs(x, d, k, dm, dg, dn), the coefficient k of the right-hand side.
template <class Rhs>
void expand_columns(const Body& body, const OrbitTaylorSeries& s, OrbitTangentSeries& ts,
                    Rhs&& rhs) {
  const Vectors x = state_vectors(body, s);
  ts.order = s.order;
  for (int c = 0; c < ts.columns; ++c) {
    auto& v = ts.v[static_cast<std::size_t>(c)];
    Vectors d;
    d.set(body, 0, vec(v[0], 0), vec(v[0], 3), vec(v[0], 6), true);
    for (int k = 0; k < s.order; ++k) {
      Vec3 dm, dg, dn;
      rhs(x, d, k, dm, dg, dn);
      const double inv = 1.0 / static_cast<double>(k + 1);
      d.set(body, k + 1, dm * inv, dg * inv, dn * inv, true);
      auto& out = v[static_cast<std::size_t>(k + 1)];
      for (int i = 0; i < 3; ++i) {
        const auto u = static_cast<std::size_t>(i);
        out[u] = d.m[static_cast<std::size_t>(k + 1)][i];
        out[3 + u] = d.g[static_cast<std::size_t>(k + 1)][i];
        out[6 + u] = d.n[static_cast<std::size_t>(k + 1)][i];
      }
    }
  }
}

}  // namespace

void orbit_taylor_expand_tangent(const CircularOrbitModel& model, const OrbitTaylorSeries& s,
                                 OrbitTangentSeries& ts) {
  const double rate = model.orbit().rate, lambda = model.orbit().lambda_;
  expand_columns(
      model.body(), s, ts,
      [&](const Vectors& x, const Vectors& d, int k, Vec3& dm, Vec3& dg, Vec3& dn) {
        dm = tangent_cross(d.m, x.w, x.m, d.w, k) + lambda * tangent_cross(d.g, x.ig, x.g, d.ig, k);
        dg = tangent_cross(d.g, x.w, x.g, d.w, k) + rate * tangent_cross(d.n, x.g, x.n, d.g, k);
        dn = tangent_cross(d.n, x.w, x.n, d.w, k);
      });
}

void orbit_taylor_expand_tangent(const EllipticOrbitModel& model, const OrbitTaylorSeries& s,
                                 double nu, OrbitTangentSeries& ts) {
  std::array<double, K> sigma{}, sigma_lambda{};
  orbit_anomaly_series(model.orbit(), nu, s.order, sigma.data(), sigma_lambda.data());
  Series3 mw, gig, gw, nw;  // the series of δ(m × ω), δ(γ × Iγ), δ(γ × ω), δ(n × ω)
  expand_columns(model.body(), s, ts,
                 [&](const Vectors& x, const Vectors& d, int k, Vec3& dm, Vec3& dg, Vec3& dn) {
                   const auto i = static_cast<std::size_t>(k);
                   mw[i] = tangent_cross(d.m, x.w, x.m, d.w, k);
                   gig[i] = tangent_cross(d.g, x.ig, x.g, d.ig, k);
                   gw[i] = tangent_cross(d.g, x.w, x.g, d.w, k);
                   nw[i] = tangent_cross(d.n, x.w, x.n, d.w, k);
                   dm = scale_sum(sigma.data(), mw, k) + scale_sum(sigma_lambda.data(), gig, k);
                   dg = scale_sum(sigma.data(), gw, k) + tangent_cross(d.n, x.g, x.n, d.g, k);
                   dn = scale_sum(sigma.data(), nw, k);
                 });
}

std::array<double, 9> orbit_tangent_sum(const OrbitTangentSeries& ts, int c, double h) {
  const auto& v = ts.v[static_cast<std::size_t>(c)];
  std::array<double, 9> y = v[static_cast<std::size_t>(ts.order)];
  for (int k = ts.order - 1; k >= 0; --k) {
    const auto& a = v[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < 9; ++i) y[i] = y[i] * h + a[i];
  }
  return y;
}

}  // namespace newtop::detail
