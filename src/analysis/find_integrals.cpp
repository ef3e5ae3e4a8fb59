#include "newtop/analysis/find_integrals.hpp"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <random>

#include "newtop/model/integrals.hpp"

namespace newtop {
namespace {

using Point = std::array<double, 6>;  // (p, q, r, γ1, γ2, γ3)
using VectorField = std::function<Point(const Point&)>;

struct Candidate {
  std::string name;
  int degree;
  std::function<double(const Vec3&, const Vec3&)> f;
};

// A fitted candidate with a least-squares residual above this (relative) is not a polynomial of
// the search degree; exact polynomials fit to ~1e-14.
constexpr double kFitResidual = 1e-9;
// A vector whose distance from the null space is below this is an integral; one whose distance
// from the span of accepted names is above it is independent of them (rounding gives ~1e-12).
constexpr double kMembership = 1e-7;
// Coefficients below this fraction of the largest are printed as zero.
constexpr double kNegligibleCoefficient = 1e-10;
constexpr int kMaxDegree = 6;

double power(double x, int k) {
  double r = 1.0;
  for (int i = 0; i < k; ++i) r *= x;
  return r;
}

std::vector<Monomial> monomials_up_to(int D) {
  std::vector<Monomial> out;
  for (int d = 1; d <= D; ++d) {
    Monomial e{};
    // All exponent vectors of total degree d, in lexicographic order (p first).
    std::function<void(int, int)> rec = [&](int var, int left) {
      if (var == 5) {
        e[5] = left;
        out.push_back(e);
        return;
      }
      for (int k = left; k >= 0; --k) {
        e[var] = k;
        rec(var + 1, left - k);
      }
    };
    rec(0, d);
  }
  return out;
}

double eval(const Monomial& m, const Point& x) {
  double v = 1.0;
  for (int i = 0; i < 6; ++i) v *= power(x[i], m[i]);
  return v;
}

/// d/dt of the monomial along the vector field: Σ_v ∂μ/∂x_v ẋ_v.
double derivative(const Monomial& m, const Point& x, const Point& dx) {
  double s = 0.0;
  for (int v = 0; v < 6; ++v) {
    if (m[v] == 0) continue;
    Monomial e = m;
    --e[v];
    s += m[v] * eval(e, x) * dx[v];
  }
  return s;
}

std::vector<Point> random_points(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Point> pts(n);
  // Uniform in [−1, 1] from the top 53 bits: the same points on every platform.
  for (auto& p : pts) {
    for (double& c : p) c = 2.0 * static_cast<double>(rng() >> 11) * 0x1.0p-53 - 1.0;
  }
  return pts;
}

/// Least-squares fit of f in the basis {1, monomials} on the points; nullopt if not exact.
std::optional<Eigen::VectorXd> fit(const std::vector<Monomial>& mons, const std::vector<Point>& pts,
                                   const std::function<double(const Vec3&, const Vec3&)>& f) {
  const auto n = static_cast<Eigen::Index>(mons.size());
  Eigen::MatrixXd E(static_cast<Eigen::Index>(pts.size()), n + 1);
  Eigen::VectorXd y(E.rows());
  for (Eigen::Index i = 0; i < E.rows(); ++i) {
    const Point& x = pts[i];
    E(i, 0) = 1.0;
    for (Eigen::Index j = 0; j < n; ++j) E(i, j + 1) = eval(mons[j], x);
    y(i) = f(Vec3(x[0], x[1], x[2]), Vec3(x[3], x[4], x[5]));
  }
  const Eigen::VectorXd c = E.colPivHouseholderQr().solve(y);
  if ((E * c - y).norm() > kFitResidual * std::max(y.norm(), 1e-300)) return std::nullopt;
  return Eigen::VectorXd(c.tail(n));
}

/// Products of the base candidates with total degree ≤ D (each product once).
std::vector<Candidate> products(const std::vector<Candidate>& base, int D) {
  std::vector<Candidate> out;
  std::function<void(std::size_t, Candidate)> rec = [&](std::size_t from, Candidate c) {
    if (!c.name.empty()) out.push_back(c);
    for (std::size_t i = from; i < base.size(); ++i) {
      if (c.degree + base[i].degree > D) continue;
      Candidate next{
          c.name.empty() ? base[i].name : c.name + "*" + base[i].name, c.degree + base[i].degree,
          [f = c.f, g = base[i].f](const Vec3& w, const Vec3& y) { return f(w, y) * g(w, y); }};
      rec(i, next);
    }
  };
  rec(0, Candidate{"", 0, [](const Vec3&, const Vec3&) { return 1.0; }});
  return out;
}

/// Residual of v after projection on the orthonormal columns of Q.
double residual(const Eigen::MatrixXd& Q, const Eigen::VectorXd& v) {
  if (Q.cols() == 0) return 1.0;
  return (v - Q * (Q.transpose() * v)).norm() / v.norm();
}

Eigen::MatrixXd append_orthonormal(const Eigen::MatrixXd& Q, const Eigen::VectorXd& v) {
  Eigen::VectorXd u = v - Q * (Q.transpose() * v);
  u -= Q * (Q.transpose() * u);  // second pass: re-orthogonalisation
  Eigen::MatrixXd out(v.size(), Q.cols() + 1);
  out << Q, u.normalized();
  return out;
}

std::vector<double> tidy(const Eigen::VectorXd& c) {
  const Eigen::Index big = [&] {
    Eigen::Index i = 0;
    c.cwiseAbs().maxCoeff(&i);
    return i;
  }();
  const double scale = c(big);
  std::vector<double> out(c.size());
  for (Eigen::Index j = 0; j < c.size(); ++j) {
    const double v = c(j) / scale;
    out[j] = std::abs(v) < kNegligibleCoefficient ? 0.0 : v;
  }
  return out;
}

IntegralSearch search(const VectorField& field, const std::vector<Candidate>& base,
                      const SearchOptions& opt) {
  if (opt.degree < 1 || opt.degree > kMaxDegree) {
    throw InputError("degree: expected an integer in 1.." + std::to_string(kMaxDegree) +
                     ", found " + std::to_string(opt.degree));
  }
  IntegralSearch s;
  s.degree = opt.degree;
  s.monomials = monomials_up_to(opt.degree);
  const auto n = static_cast<Eigen::Index>(s.monomials.size());
  if (opt.points < 0) {
    throw InputError("points: expected 0 (3 x the monomials) or a positive count, found " +
                     std::to_string(opt.points));
  }
  const int npts = opt.points > 0 ? opt.points : 3 * static_cast<int>(n);
  const std::int64_t max_points = kMaxConditionEntries / n;
  if (npts > max_points) {
    throw InputError("points: expected at most " + std::to_string(max_points) + " for degree " +
                     std::to_string(opt.degree) + " (the condition matrix of points x " +
                     std::to_string(n) + " monomials is bounded at " +
                     std::to_string(kMaxConditionEntries) + " entries, 128 MiB), found " +
                     std::to_string(npts));
  }
  if (npts < n) {
    throw InputError("points: expected at least " + std::to_string(n) +
                     " (the number of "
                     "monomials), found " +
                     std::to_string(npts));
  }
  const std::vector<Point> pts = random_points(npts, opt.seed);
  Eigen::MatrixXd M(npts, n);
  Eigen::VectorXd scale = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < npts; ++i) {
    const Point dx = field(pts[i]);
    for (Eigen::Index j = 0; j < n; ++j) {
      M(i, j) = derivative(s.monomials[j], pts[i], dx);
      scale(j) += std::pow(eval(s.monomials[j], pts[i]), 2);
    }
  }
  // Each monomial scaled to unit norm over the points (its values, not its derivative: a monomial
  // that is itself an integral has a derivative column of pure rounding, which must stay small).
  scale = scale.cwiseSqrt();
  M = M * scale.cwiseInverse().asDiagonal();
  Eigen::BDCSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues() / svd.singularValues()(0);
  s.singular_values.assign(sv.data(), sv.data() + sv.size());
  s.rank = static_cast<int>((sv.array() > opt.threshold).count());
  s.gap = s.rank < n && s.rank > 0 && sv(s.rank) > 0 ? sv(s.rank - 1) / sv(s.rank)
                                                     : std::numeric_limits<double>::infinity();
  const Eigen::MatrixXd null = svd.matrixV().rightCols(n - s.rank);  // scaled coordinates

  // Recognise known integrals: fitted, scaled, accepted when in the null space and new.
  Eigen::MatrixXd named(n, 0);
  for (const Candidate& c : products(base, opt.degree)) {
    if (named.cols() == null.cols()) break;
    const auto coef = fit(s.monomials, pts, c.f);
    if (!coef) continue;
    const Eigen::VectorXd v = coef->cwiseProduct(scale);
    if (v.norm() == 0.0 || residual(null, v) > kMembership) continue;
    if (residual(named, v) < kMembership) continue;
    named = append_orthonormal(named, v);
    s.integrals.push_back({c.name, tidy(*coef)});
  }
  // The rest of the null space, orthogonal to the named part.
  Eigen::MatrixXd Q = named;
  for (Eigen::Index j = 0; j < null.cols() && Q.cols() < null.cols(); ++j) {
    const Eigen::VectorXd v = null.col(j);
    if (residual(Q, v) < kMembership) continue;
    Eigen::VectorXd u = v - Q * (Q.transpose() * v);
    Q = append_orthonormal(Q, u);
    s.integrals.push_back({std::nullopt, tidy(u.cwiseQuotient(scale))});
  }
  return s;
}

template <Field F>
VectorField vector_field(const BasicModel<F>& model) {
  return [&model](const Point& x) {
    const Vec3 w(x[0], x[1], x[2]), g(x[3], x[4], x[5]);
    const State s = state_from_omega(model.body, w, g);
    const State d = rhs(model, s);
    const Vec3 wdot = d.m.cwiseQuotient(model.body.inertia());  // ṁ = I ω̇ (k constant)
    return Point{wdot[0], wdot[1], wdot[2], d.gamma[0], d.gamma[1], d.gamma[2]};
  };
}

template <Field F>
std::vector<Candidate> common_candidates(const BasicModel<F>& model, int energy_degree) {
  const Body& b = model.body;
  return {
      {"energy", energy_degree,
       [&model](const Vec3& w, const Vec3& g) {
         return energy(model, state_from_omega(model.body, w, g));
       }},
      {"area", 2, [&b](const Vec3& w, const Vec3& g) { return area(state_from_omega(b, w, g)); }},
      {"geometric", 2, [](const Vec3&, const Vec3& g) { return g.squaredNorm(); }},
  };
}

}  // namespace

double potential(const Body& /*body*/, const PolynomialPotential& v, const Vec3& gamma) {
  double s = 0.0;
  for (const auto& t : v.terms) {
    s += t.coefficient * power(gamma[0], t.power[0]) * power(gamma[1], t.power[1]) *
         power(gamma[2], t.power[2]);
  }
  return s;
}

Vec3 grad_gamma(const Body& /*body*/, const PolynomialPotential& v, const Vec3& gamma) {
  Vec3 g = Vec3::Zero();
  for (const auto& t : v.terms) {
    for (int i = 0; i < 3; ++i) {
      if (t.power[i] == 0) continue;
      double d = t.coefficient * t.power[i];
      for (int j = 0; j < 3; ++j) d *= power(gamma[j], t.power[j] - (i == j ? 1 : 0));
      g[i] += d;
    }
  }
  return g;
}

int degree(const PolynomialPotential& v) {
  int d = 0;
  for (const auto& t : v.terms) d = std::max(d, t.power[0] + t.power[1] + t.power[2]);
  return d;
}

std::string to_string(const Monomial& m) {
  static const char* names[6] = {"p", "q", "r", "gamma1", "gamma2", "gamma3"};
  std::string s;
  for (int i = 0; i < 6; ++i) {
    if (m[i] == 0) continue;
    if (!s.empty()) s += "*";
    s += names[i];
    if (m[i] > 1) s += "^" + std::to_string(m[i]);
  }
  return s.empty() ? "1" : s;
}

IntegralSearch find_integrals(const QuadraticModel& model, const SearchOptions& options) {
  auto base = common_candidates(model, 2);
  if (brun_holds(model)) {
    base.push_back({"brun", 2, [&model](const Vec3& w, const Vec3& g) {
                      return brun(model, state_from_omega(model.body, w, g));
                    }});
  }
  if (lagrange_holds(model)) {
    base.push_back({"lagrange", 1, [&model](const Vec3& w, const Vec3& g) {
                      return lagrange(model, state_from_omega(model.body, w, g));
                    }});
  }
  return search(vector_field(model), base, options);
}

IntegralSearch find_integrals(const BasicModel<PolynomialPotential>& model,
                              const SearchOptions& options) {
  auto base = common_candidates(model, std::max(2, degree(model.field)));
  const Body& b = model.body;
  if (b.A() == b.B() && b.gyrostat().x() == 0.0 && b.gyrostat().y() == 0.0) {
    base.push_back({"lagrange", 1, [&b](const Vec3& w, const Vec3& g) {
                      return state_from_omega(b, w, g).m.z();
                    }});
  }
  return search(vector_field(model), base, options);
}

std::optional<std::vector<double>> polynomial_coefficients(
    const std::vector<Monomial>& monomials,
    const std::function<double(const Vec3& omega, const Vec3& gamma)>& f) {
  const auto pts = random_points(3 * static_cast<int>(monomials.size()) + 10, 7);
  const auto c = fit(monomials, pts, f);
  if (!c) return std::nullopt;
  return std::vector<double>(c->data(), c->data() + c->size());
}

double distance_from_integrals(const IntegralSearch& s, const std::vector<double>& coefficients) {
  const auto n = static_cast<Eigen::Index>(s.monomials.size());
  Eigen::MatrixXd Q(n, 0);
  for (const auto& i : s.integrals) {
    Q = append_orthonormal(Q, Eigen::Map<const Eigen::VectorXd>(i.coefficients.data(), n));
  }
  return residual(Q, Eigen::Map<const Eigen::VectorXd>(coefficients.data(), n));
}

}  // namespace newtop
