// Mass moments M_α = ∫ ρ^α dm of every mass model, exact (docs/model.md §3, docs/exact_field.md),
// stored for the body scaled by its radius r: M̃_α = ∫ (ρ/r)^α dm (mass units, |M̃_α| ≤ M), so that
// no degree overflows or underflows whatever the body's size.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "newtop/exact/multipole.hpp"
#include "table.hpp"

namespace newtop {
namespace {

using detail::Table;

/// Y ← Y / (1 − ℓ·h) truncated at degree d: Y_α += Σ_j ℓ_j Y_{α−e_j} in increasing α.
void divide_by_one_minus(Table& Y, const Vec3& l) {
  for (int i = 0; i <= Y.d; ++i) {
    for (int j = 0; i + j <= Y.d; ++j) {
      for (int k = 0; i + j + k <= Y.d; ++k) {
        Y(i, j, k) +=
            l.x() * Y.at(i - 1, j, k) + l.y() * Y.at(i, j - 1, k) + l.z() * Y.at(i, j, k - 1);
      }
    }
  }
}

double factorial(int n) { return std::tgamma(n + 1.0); }

/// The first moments from the model's accurate D (the body's scale r is a power of two, so D/r is
/// exact): the moment far away depends on them through D/R² against r²/R³.
void set_first_moment(Table& M, const Vec3& D) {
  if (M.d < 1) return;
  M(1, 0, 0) = D.x();
  M(0, 1, 0) = D.y();
  M(0, 0, 1) = D.z();
}

/// Polyhedron: tetrahedra (O, a, b, c) with ∫_T (h·ρ)^n dV = det n!/(n+3)! h_n(h·a, h·b, h·c), h_n
/// the complete homogeneous symmetric polynomial, so M_α = σ Σ det α!/(|α|+3)! [h^α] Π 1/(1 − h·v)
/// (vertices scaled by 1/r, and σ r³ = M/Ṽ with Ṽ the scaled volume).
void add_polyhedron(const Polyhedron& p, double r, Table& M) {
  Table Y(M.d);
  double det_sum = 0.0;
  for (const Triangle& t : p.faces()) {
    std::fill(Y.v.begin(), Y.v.end(), 0.0);
    Y(0, 0, 0) = 1.0;
    const Vec3 a = p.vertices()[t[0]] / r, b = p.vertices()[t[1]] / r, c = p.vertices()[t[2]] / r;
    for (const Vec3& v : {a, b, c}) divide_by_one_minus(Y, v);
    const double det = a.dot(b.cross(c));
    det_sum += det;
    for (std::size_t n = 0; n < Y.v.size(); ++n) M.v[n] += det * Y.v[n];
  }
  const double sigma_r3 = mass_properties(p).mass / (det_sum / 6.0);
  for (int i = 0; i <= M.d; ++i) {
    for (int j = 0; i + j <= M.d; ++j) {
      for (int k = 0; i + j + k <= M.d; ++k) {
        M(i, j, k) *=
            sigma_r3 * factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3);
      }
    }
  }
  set_first_moment(M, p.first_moment() / r);
}

/// ∫_{|u| ≤ 1} u^β du: zero unless every β_i is even; for β = 2k it is
/// 2 Γ(k1+½) Γ(k2+½) Γ(k3+½) / (Γ(|k| + 3/2) (2|k| + 3)).
double ball_moment(int b1, int b2, int b3) {
  if (b1 % 2 || b2 % 2 || b3 % 2) return 0.0;
  const double k1 = b1 / 2, k2 = b2 / 2, k3 = b3 / 2, k = k1 + k2 + k3;
  return 2.0 * std::tgamma(k1 + 0.5) * std::tgamma(k2 + 0.5) * std::tgamma(k3 + 0.5) /
         (std::tgamma(k + 1.5) * (2.0 * k + 3.0));
}

double binomial(int n, int k) { return factorial(n) / (factorial(k) * factorial(n - k)); }

/// Ellipsoid ρ = c + diag(a) u over the unit ball: binomial expansion per axis, in units of r.
void add_ellipsoid(const Ellipsoid& e, double r, Table& M) {
  const Vec3 a = e.semi_axes / r, c = e.center / r;
  const double w = mass_properties(e).mass * 3.0 / (4.0 * std::numbers::pi);  // σ abc
  auto term = [&](int axis, int n, int b) {
    return binomial(n, b) * std::pow(c[axis], n - b) * std::pow(a[axis], b);
  };
  for (int i = 0; i <= M.d; ++i)
    for (int j = 0; i + j <= M.d; ++j)
      for (int k = 0; i + j + k <= M.d; ++k) {
        double s = 0.0;
        for (int p = 0; p <= i; p += 2)
          for (int q = 0; q <= j; q += 2)
            for (int t = 0; t <= k; t += 2)
              s += term(0, i, p) * term(1, j, q) * term(2, k, t) * ball_moment(p, q, t);
        M(i, j, k) = w * s;
      }
}

/// Point masses: plain sums; the first moments from the accurate D = Σ m ρ.
void add_points(const PointMasses& pm, double r, Table& M) {
  for (std::size_t n = 0; n < pm.masses().size(); ++n) {
    const Vec3 x = pm.positions()[n] / r;
    for (int i = 0; i <= M.d; ++i)
      for (int j = 0; i + j <= M.d; ++j)
        for (int k = 0; i + j + k <= M.d; ++k) {
          M(i, j, k) +=
              pm.masses()[n] * std::pow(x.x(), i) * std::pow(x.y(), j) * std::pow(x.z(), k);
        }
  }
  set_first_moment(M, pm.first_moment() / r);
}

}  // namespace

MassMoments::MassMoments(const MassModel& model, int degree)
    : degree_(degree), max_radius_(newtop::max_radius(model)) {
  // The power of two in (r, 2r]: scaling by it is exact.
  int e = 0;
  std::frexp(max_radius_, &e);
  scale_ = max_radius_ > 0 ? std::ldexp(1.0, e) : 1.0;
  Table M(degree);
  struct Visitor {
    Table& M;
    double r;
    void operator()(const PointMasses& p) const { add_points(p, r, M); }
    void operator()(const Polyhedron& p) const { add_polyhedron(p, r, M); }
    void operator()(const Ellipsoid& e) const { add_ellipsoid(e, r, M); }
  };
  std::visit(Visitor{M, scale_}, model);
  m_ = std::move(M.v);
}

double MassMoments::operator()(int i, int j, int k) const {
  return scaled(i, j, k) * std::pow(scale_, i + j + k);
}

}  // namespace newtop
