#include "newtop/exact/multipole.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace newtop {
namespace {

// Orders above this gain nothing in double precision for a centre outside the body and make
// the (degree+1)³ tables needlessly large.
constexpr int kMaxOrder = 30;

/// Dense (d+1)³ table, zero where i + j + k > d.
struct Table {
  int d;
  std::vector<double> v;
  explicit Table(int degree)
      : d(degree), v(static_cast<std::size_t>((degree + 1) * (degree + 1) * (degree + 1)), 0.0) {}
  double& operator()(int i, int j, int k) {
    return v[(static_cast<std::size_t>(i) * (d + 1) + j) * (d + 1) + k];
  }
  double at(int i, int j, int k) const {
    if (i < 0 || j < 0 || k < 0) return 0.0;
    return v[(static_cast<std::size_t>(i) * (d + 1) + j) * (d + 1) + k];
  }
};

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

/// Polyhedron: tetrahedra (O, a, b, c) with ∫_T (h·ρ)^n dV = det n!/(n+3)! h_n(h·a, h·b, h·c), h_n
/// the complete homogeneous symmetric polynomial, so M_α = σ Σ det α!/(|α|+3)! [h^α] Π 1/(1 − h·v).
void add_polyhedron(const Polyhedron& p, Table& M) {
  Table Y(M.d);
  for (const Triangle& t : p.faces()) {
    std::fill(Y.v.begin(), Y.v.end(), 0.0);
    Y(0, 0, 0) = 1.0;
    for (int c = 0; c < 3; ++c) divide_by_one_minus(Y, p.vertices()[t[c]]);
    const Vec3 &a = p.vertices()[t[0]], &b = p.vertices()[t[1]], &c = p.vertices()[t[2]];
    const double det = a.dot(b.cross(c));
    for (std::size_t n = 0; n < Y.v.size(); ++n) M.v[n] += det * Y.v[n];
  }
  for (int i = 0; i <= M.d; ++i) {
    for (int j = 0; i + j <= M.d; ++j) {
      for (int k = 0; i + j + k <= M.d; ++k) {
        M(i, j, k) *=
            p.density() * factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3);
      }
    }
  }
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

/// Ellipsoid ρ = c + diag(a) u over the unit ball: binomial expansion per axis.
void add_ellipsoid(const Ellipsoid& e, Table& M) {
  const Vec3 &a = e.semi_axes, &c = e.center;
  const double w = e.density * a.prod();
  auto term = [&](int axis, int n, int b) {
    return binomial(n, b) * std::pow(c[axis], n - b) * std::pow(a[axis], b);
  };
  for (int i = 0; i <= M.d; ++i)
    for (int j = 0; i + j <= M.d; ++j)
      for (int k = 0; i + j + k <= M.d; ++k) {
        double s = 0.0;
        for (int p = 0; p <= i; p += 2)
          for (int q = 0; q <= j; q += 2)
            for (int r = 0; r <= k; r += 2)
              s += term(0, i, p) * term(1, j, q) * term(2, k, r) * ball_moment(p, q, r);
        M(i, j, k) = w * s;
      }
}

void add_points(const PointMasses& pm, Table& M) {
  for (std::size_t n = 0; n < pm.masses().size(); ++n) {
    const Vec3& x = pm.positions()[n];
    for (int i = 0; i <= M.d; ++i)
      for (int j = 0; i + j <= M.d; ++j)
        for (int k = 0; i + j + k <= M.d; ++k) {
          M(i, j, k) +=
              pm.masses()[n] * std::pow(x.x(), i) * std::pow(x.y(), j) * std::pow(x.z(), k);
        }
  }
}

}  // namespace

MassMoments::MassMoments(const MassModel& model, int degree)
    : degree_(degree), max_radius_(newtop::max_radius(model)) {
  Table M(degree);
  struct Visitor {
    Table& M;
    void operator()(const PointMasses& p) const { add_points(p, M); }
    void operator()(const Polyhedron& p) const { add_polyhedron(p, M); }
    void operator()(const Ellipsoid& e) const { add_ellipsoid(e, M); }
  };
  std::visit(Visitor{M}, model);
  m_ = std::move(M.v);
}

std::vector<double> inverse_distance_taylor(const Vec3& x, int degree) {
  Table c(degree);
  const double r2 = x.squaredNorm();
  c(0, 0, 0) = 1.0 / std::sqrt(r2);
  for (int n = 1; n <= degree; ++n) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const int k = n - i - j;
        const double lin =
            x.x() * c.at(i - 1, j, k) + x.y() * c.at(i, j - 1, k) + x.z() * c.at(i, j, k - 1);
        const double quad = c.at(i - 2, j, k) + c.at(i, j - 2, k) + c.at(i, j, k - 2);
        c(i, j, k) = -((2.0 * n - 1.0) * lin + (n - 1.0) * quad) / (r2 * n);
      }
    }
  }
  return std::move(c.v);
}

MultipoleField MultipoleField::make(const MassModel& model, int order, double mu, double R,
                                    const Mat3& axes) {
  if (order < 1 || order > kMaxOrder) {
    throw InputError("order: expected an integer in [1, " + std::to_string(kMaxOrder) +
                     "], found " + std::to_string(order));
  }
  const ExactField checked =
      ExactField::make(std::make_shared<const MassModel>(model), mu, R, axes);
  return {std::make_shared<const MassMoments>(model, order), order, checked.mu, checked.R, axes};
}

namespace {

struct Sums {
  double V = 0.0, next = 0.0;
  Vec3 grad_x = Vec3::Zero();  // ∇_x of Σ M_α c_α(x)
};

Sums sums(const MultipoleField& f, const Vec3& x) {
  const int p = f.order, d = p;
  const std::vector<double> c = inverse_distance_taylor(x, d);
  auto C = [&](int i, int j, int k) {
    return c[(static_cast<std::size_t>(i) * (d + 1) + j) * (d + 1) + k];
  };
  const MassMoments& M = *f.moments;
  Sums s;
  for (int i = 0; i <= p; ++i)
    for (int j = 0; i + j <= p; ++j)
      for (int k = 0; i + j + k <= p; ++k) {
        const double m = M(i, j, k);
        if (i + j + k == p) {
          s.next += m * C(i, j, k);
          continue;
        }
        s.V += m * C(i, j, k);
        s.grad_x +=
            m * Vec3((i + 1) * C(i + 1, j, k), (j + 1) * C(i, j + 1, k), (k + 1) * C(i, j, k + 1));
      }
  return s;
}

}  // namespace

Attraction multipole_attraction(const MassMoments& M, int order, const Vec3& x) {
  const int d = order;
  const std::vector<double> c = inverse_distance_taylor(-x, d);
  auto C = [&](int i, int j, int k) {
    return c[(static_cast<std::size_t>(i) * (d + 1) + j) * (d + 1) + k];
  };
  Attraction a;
  Vec3 grad_c = Vec3::Zero();  // ∇ of Σ M_α c_α at −x
  for (int i = 0; i < order; ++i)
    for (int j = 0; i + j < order; ++j)
      for (int k = 0; i + j + k < order; ++k) {
        const double m = M(i, j, k);
        a.potential += m * C(i, j, k);
        grad_c +=
            m * Vec3((i + 1) * C(i + 1, j, k), (j + 1) * C(i, j + 1, k), (k + 1) * C(i, j, k + 1));
      }
  a.gradient = -grad_c;
  return a;
}

FieldValues field_values(const MultipoleField& f, const Vec3& gamma) {
  const Vec3 gm = f.axes * gamma;
  const Sums s = sums(f, f.R * gm);
  return complete(-f.mu * s.V, -f.mu * f.R * (f.axes.transpose() * s.grad_x),
                  -f.mu * gm.dot(s.grad_x), gamma, f.R);
}

double potential(const Body& /*body*/, const MultipoleField& f, const Vec3& gamma) {
  return field_values(f, gamma).potential;
}

Vec3 grad_gamma(const Body& /*body*/, const MultipoleField& f, const Vec3& gamma) {
  return field_values(f, gamma).grad_gamma;
}

TruncationError truncation_error(const MultipoleField& f, const Vec3& gamma) {
  const Sums s = sums(f, f.R * (f.axes * gamma));
  const double r = f.moments->max_radius(), M = f.moments->mass();
  return {f.mu * std::abs(s.next), f.mu * M * std::pow(r / f.R, f.order) / (f.R - r)};
}

}  // namespace newtop
