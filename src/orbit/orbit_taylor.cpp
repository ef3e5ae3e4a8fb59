#include "newtop/orbit/orbit_taylor.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "newtop/core/types.hpp"
#include "newtop/integrate/taylor.hpp"

namespace newtop {

namespace detail {

namespace {

using Series3 = std::array<Vec3, OrbitTaylorSeries::kMaxOrder + 1>;
using Series1 = std::array<double, OrbitTaylorSeries::kMaxOrder + 1>;

/// Σ_{j=0..n} a^[j] × b^[n−j]: the coefficient n of the series of a × b.
Vec3 cross_sum(const Series3& a, const Series3& b, int n) {
  Vec3 s = Vec3::Zero();
  for (int j = 0; j <= n; ++j)
    s += a[static_cast<std::size_t>(j)].cross(b[static_cast<std::size_t>(n - j)]);
  return s;
}

/// Σ_{j=0..n} f^[j] v^[n−j]: the coefficient n of the series of the scalar f times v.
Vec3 scale_sum(const Series1& f, const Series3& v, int n) {
  Vec3 s = Vec3::Zero();
  for (int j = 0; j <= n; ++j)
    s += f[static_cast<std::size_t>(j)] * v[static_cast<std::size_t>(n - j)];
  return s;
}

/// The series of (m, γ, n) and of ω = I⁻¹(m − k) and Iγ, filled order by order.
struct OrbitSeries {
  Series3 m, g, nrm, w, ig;

  OrbitSeries(const Body& body, const OrbitState& x) { set(body, 0, x.m, x.gamma, x.normal); }
  void set(const Body& body, int k, const Vec3& mk, const Vec3& gk, const Vec3& nk) {
    const auto i = static_cast<std::size_t>(k);
    m[i] = mk;
    g[i] = gk;
    nrm[i] = nk;
    w[i] = (k == 0 ? Vec3(mk - body.gyrostat()) : mk).cwiseQuotient(body.inertia());
    ig[i] = body.inertia().cwiseProduct(gk);
  }
  void write(int order, OrbitTaylorSeries& s) const {
    s.order = order;
    for (int k = 0; k <= order; ++k) {
      const auto i = static_cast<std::size_t>(k);
      for (int c = 0; c < 3; ++c) {
        s.x[i][static_cast<std::size_t>(c)] = m[i][c];
        s.x[i][static_cast<std::size_t>(3 + c)] = g[i][c];
        s.x[i][static_cast<std::size_t>(6 + c)] = nrm[i][c];
      }
    }
  }
};

}  // namespace

void check_orbit_taylor_order(int order) {
  if (order < 1 || order > OrbitTaylorSeries::kMaxOrder) {
    throw InputError("order: Taylor's method on an orbit expands to an order in [1, " +
                     std::to_string(OrbitTaylorSeries::kMaxOrder) + "], found " +
                     std::to_string(order));
  }
}

namespace {

double max_norm(const std::array<double, 9>& v) {
  double r = 0.0;
  for (double c : v) {
    if (std::isnan(c)) return std::numeric_limits<double>::quiet_NaN();
    r = std::max(r, std::abs(c));
  }
  return r;
}

}  // namespace

// ẋ = (m × ω + λ γ × Iγ, γ × ω + ω0 n × γ, n × ω): x^[k+1] = (ẋ)^[k] / (k + 1).
void orbit_taylor_expand(const CircularOrbitModel& model, const OrbitState& x, int order,
                         OrbitTaylorSeries& s) {
  check_orbit_taylor_order(order);
  const Body& body = model.body();
  const double rate = model.orbit().rate, lambda = model.orbit().lambda_;
  OrbitSeries z(body, x);
  for (int k = 0; k < order; ++k) {
    const double inv = 1.0 / static_cast<double>(k + 1);
    const Vec3 dm = cross_sum(z.m, z.w, k) + lambda * cross_sum(z.g, z.ig, k);
    const Vec3 dg = cross_sum(z.g, z.w, k) + rate * cross_sum(z.nrm, z.g, k);
    const Vec3 dn = cross_sum(z.nrm, z.w, k);
    z.set(body, k + 1, dm * inv, dg * inv, dn * inv);
  }
  z.write(order, s);
}

void orbit_anomaly_series(const EllipticOrbit& orbit, double nu, int order, double* sigma,
                          double* sigma_lambda) {
  const double e = orbit.eccentricity, n_mean = orbit.mean_motion;
  const double q = std::pow(1.0 - e * e, 1.5);
  const double c_sigma = q / n_mean, c_lambda = 3.0 * n_mean / q;
  Series1 u{}, inv_u{};
  const double cos0 = std::cos(nu), sin0 = std::sin(nu);
  double factorial_inv = 1.0;
  for (int k = 0; k < order; ++k) {  // σ and σλ to the order order − 1 of ẋ
    const auto i = static_cast<std::size_t>(k);
    if (k > 0) factorial_inv /= static_cast<double>(k);
    const double derivative = k % 4 == 0 ? cos0 : k % 4 == 1 ? -sin0 : k % 4 == 2 ? -cos0 : sin0;
    u[i] = (k == 0 ? 1.0 : 0.0) + e * derivative * factorial_inv;
    double r = k == 0 ? 1.0 : 0.0;
    for (int j = 1; j <= k; ++j)
      r -= u[static_cast<std::size_t>(j)] * inv_u[i - static_cast<std::size_t>(j)];
    inv_u[i] = r / u[0];
    double sq = 0.0;
    for (int j = 0; j <= k; ++j)
      sq += inv_u[static_cast<std::size_t>(j)] * inv_u[i - static_cast<std::size_t>(j)];
    sigma[i] = c_sigma * sq;
    sigma_lambda[i] = c_lambda * u[i];
  }
}

// d/dν x = (σ m × ω + σλ γ × Iγ, σ γ × ω + n × γ, σ n × ω) with u = 1 + e cos ν,
// σ = (1 − e²)^{3/2}/(n u²) and σλ = 3n u/(1 − e²)^{3/2} (orbit.hpp's time_per_anomaly and
// lambda_at): the series of cos ν from its derivatives, 1/u by the recurrence of a quotient.
void orbit_taylor_expand(const EllipticOrbitModel& model, const OrbitState& x, double nu, int order,
                         OrbitTaylorSeries& s) {
  check_orbit_taylor_order(order);
  const Body& body = model.body();
  Series1 sigma{}, sigma_lambda{};
  orbit_anomaly_series(model.orbit(), nu, order, sigma.data(), sigma_lambda.data());
  OrbitSeries z(body, x);
  Series3 mw, gig, gw, nw;  // the series of m × ω, γ × Iγ, γ × ω, n × ω
  for (int k = 0; k < order; ++k) {
    const auto i = static_cast<std::size_t>(k);
    mw[i] = cross_sum(z.m, z.w, k);
    gig[i] = cross_sum(z.g, z.ig, k);
    gw[i] = cross_sum(z.g, z.w, k);
    nw[i] = cross_sum(z.nrm, z.w, k);
    const double inv = 1.0 / static_cast<double>(k + 1);
    const Vec3 dm = scale_sum(sigma, mw, k) + scale_sum(sigma_lambda, gig, k);
    const Vec3 dg = scale_sum(sigma, gw, k) + cross_sum(z.nrm, z.g, k);
    const Vec3 dn = scale_sum(sigma, nw, k);
    z.set(body, k + 1, dm * inv, dg * inv, dn * inv);
  }
  z.write(order, s);
}

OrbitState orbit_taylor_sum(const OrbitTaylorSeries& s, double h) {
  std::array<double, 9> y = s.x[static_cast<std::size_t>(s.order)];
  for (int k = s.order - 1; k >= 0; --k) {
    const auto& c = s.x[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < 9; ++i) y[i] = y[i] * h + c[i];
  }
  return {Vec3(y[0], y[1], y[2]), Vec3(y[3], y[4], y[5]), Vec3(y[6], y[7], y[8])};
}

double orbit_taylor_step(const OrbitTaylorSeries& s, double abs_tol, double rel_tol) {
  // The rule reads the norms 0, p − 1 and p, and the others only where one of the last two is zero
  // or not finite: those are formed only then.
  std::array<double, OrbitTaylorSeries::kMaxOrder + 1> norms{};
  const auto p = static_cast<std::size_t>(s.order);
  for (std::size_t k : {std::size_t{0}, p - 1, p}) norms[k] = max_norm(s.x[k]);
  auto regular = [](double c) { return c > 0.0 && c < std::numeric_limits<double>::infinity(); };
  if (!regular(norms[p - 1]) || !regular(norms[p])) {
    for (std::size_t k = 1; k + 1 < p; ++k) norms[k] = max_norm(s.x[k]);
  }
  return taylor_step_from_norms(norms.data(), s.order, abs_tol, rel_tol);
}

double orbit_tangent_step(const OrbitTaylorSeries& s, const OrbitTangentSeries& ts, double abs_tol,
                          double rel_tol) {
  std::array<double, OrbitTaylorSeries::kMaxOrder + 1> norms{};
  for (int k = 0; k <= s.order; ++k) {
    const auto i = static_cast<std::size_t>(k);
    double r = max_norm(s.x[i]);
    for (int c = 0; c < ts.columns && !std::isnan(r); ++c) {
      const double v = max_norm(ts.v[static_cast<std::size_t>(c)][i]);
      r = std::isnan(v) ? v : std::max(r, v);
    }
    norms[i] = r;
  }
  return taylor_step_from_norms(norms.data(), s.order, abs_tol, rel_tol);
}

}  // namespace detail

OrbitTaylorStepper::OrbitTaylorStepper(double abs_tol, double rel_tol, int order)
    : abs_tol_(abs_tol),
      rel_tol_(rel_tol),
      order_(order > 0 ? order : detail::taylor_order(std::min(abs_tol, rel_tol))) {
  if (!(abs_tol > 0) || !(rel_tol > 0)) {
    throw InputError("tol: method taylor needs tolerances > 0, found " + std::to_string(abs_tol));
  }
  detail::check_orbit_taylor_order(order_);
}

OrbitTaylorStepper::Key OrbitTaylorStepper::key_of(const CircularOrbitModel& model, double) {
  const Body& b = model.body();
  const Vec3 &I = b.inertia(), &k = b.gyrostat();
  return {I[0], I[1], I[2], k[0], k[1], k[2], model.orbit().rate, model.orbit().lambda_, 0.0, 0.0};
}

OrbitTaylorStepper::Key OrbitTaylorStepper::key_of(const EllipticOrbitModel& model, double nu) {
  const Body& b = model.body();
  const Vec3 &I = b.inertia(), &k = b.gyrostat();
  // The start anomaly plays no part in the equations; the anomaly of the point does.
  return {I[0], I[1], I[2], k[0], k[1], k[2], model.orbit().eccentricity, model.orbit().mean_motion,
          nu,   1.0};
}

}  // namespace newtop
