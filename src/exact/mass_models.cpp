#include "newtop/exact/mass_models.hpp"

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <string>

namespace newtop {
namespace {

void check_finite(const char* name, const Vec3& v) {
  if (!v.allFinite()) {
    throw InputError(std::string(name) + ": expected finite numbers, found " + format_vector(v));
  }
}

/// Inertia tensor of a point mass m at c about O: m(|c|² 1 − c cᵀ).
Mat3 parallel_axis(double m, const Vec3& c) {
  return m * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
}

}  // namespace

PointMasses::PointMasses(std::vector<double> masses, std::vector<Vec3> positions)
    : masses_(std::move(masses)), positions_(std::move(positions)) {
  if (masses_.empty() || masses_.size() != positions_.size()) {
    throw InputError("points: expected at least one point mass [m, x, y, z], found " +
                     std::to_string(masses_.size()) + " masses and " +
                     std::to_string(positions_.size()) + " positions");
  }
  for (std::size_t i = 0; i < masses_.size(); ++i) {
    if (!std::isfinite(masses_[i]) || !(masses_[i] > 0)) {
      throw InputError("points: point " + std::to_string(i) + ": expected a mass > 0, found " +
                       format_number(masses_[i]));
    }
    if (!positions_[i].allFinite()) {
      throw InputError("points: point " + std::to_string(i) +
                       ": expected finite coordinates, found " + format_vector(positions_[i]));
    }
  }
}

Ellipsoid Ellipsoid::make(const Vec3& semi_axes, double density, const Vec3& center) {
  check_finite("semi_axes", semi_axes);
  if (!(semi_axes.minCoeff() > 0)) {
    throw InputError("semi_axes: expected three lengths > 0, found " + format_vector(semi_axes));
  }
  if (!std::isfinite(density) || !(density > 0)) {
    throw InputError("density: expected a finite number > 0, found " + format_number(density));
  }
  check_finite("center", center);
  return {semi_axes, density, center};
}

Polyhedron make_box(const Vec3& dimensions, double density, const Vec3& center) {
  check_finite("dimensions", dimensions);
  if (!(dimensions.minCoeff() > 0)) {
    throw InputError("dimensions: expected three lengths > 0, found " + format_vector(dimensions));
  }
  check_finite("center", center);
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i) {
    const Vec3 s((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
    v.push_back(center + s.cwiseProduct(dimensions));
  }
  // Two outward triangles per face (vertex i has bits x = 1, y = 2, z = 4).
  std::vector<Triangle> f{{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                          {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return Polyhedron::make(std::move(v), std::move(f), density);
}

MassProperties mass_properties(const PointMasses& p) {
  MassProperties mp;
  Vec3 first = Vec3::Zero();
  for (std::size_t i = 0; i < p.masses().size(); ++i) {
    mp.mass += p.masses()[i];
    first += p.masses()[i] * p.positions()[i];
    mp.inertia_tensor += parallel_axis(p.masses()[i], p.positions()[i]);
  }
  mp.center_of_mass = first / mp.mass;
  return mp;
}

MassProperties mass_properties(const Polyhedron& p) {
  // Tetrahedron (O, a, b, c): volume det/6, ∫ρ dV = det/24 (a + b + c),
  // ∫ρρᵀ dV = det/120 (aaᵀ + bbᵀ + ccᵀ + (a + b + c)(a + b + c)ᵀ).
  double vol = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  for (const Triangle& t : p.faces()) {
    const Vec3 &a = p.vertices()[t[0]], &b = p.vertices()[t[1]], &c = p.vertices()[t[2]];
    const double det = a.dot(b.cross(c));
    const Vec3 s = a + b + c;
    vol += det;
    first += det * s;
    second += det * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  const double sigma = p.density();
  MassProperties mp;
  mp.mass = sigma * vol / 6.0;
  mp.center_of_mass = (sigma * first / 24.0) / mp.mass;
  const Mat3 S = sigma * second / 120.0;
  mp.inertia_tensor = S.trace() * Mat3::Identity() - S;
  return mp;
}

MassProperties mass_properties(const Ellipsoid& e) {
  const Vec3 s2 = e.semi_axes.cwiseAbs2();
  MassProperties mp;
  mp.mass = e.density * 4.0 / 3.0 * std::numbers::pi * e.semi_axes.prod();
  mp.center_of_mass = e.center;
  const Vec3 Jc = mp.mass / 5.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
  mp.inertia_tensor = Mat3(Jc.asDiagonal()) + parallel_axis(mp.mass, e.center);
  return mp;
}

MassProperties mass_properties(const MassModel& m) {
  return std::visit([](const auto& x) { return mass_properties(x); }, m);
}

double max_radius(const MassModel& m) {
  struct Visitor {
    double operator()(const PointMasses& p) const {
      double r = 0.0;
      for (const Vec3& x : p.positions()) r = std::max(r, x.norm());
      return r;
    }
    double operator()(const Polyhedron& p) const {
      double r = 0.0;
      for (const Vec3& x : p.vertices()) r = std::max(r, x.norm());
      return r;
    }
    double operator()(const Ellipsoid& e) const { return e.center.norm() + e.semi_axes.maxCoeff(); }
  };
  return std::visit(Visitor{}, m);
}

Attraction attraction(const PointMasses& p, const Vec3& x) {
  Attraction a;
  for (std::size_t i = 0; i < p.masses().size(); ++i) {
    const Vec3 d = p.positions()[i] - x;
    const double r = d.norm();
    a.potential += p.masses()[i] / r;
    a.gradient += (p.masses()[i] / (r * r * r)) * d;
  }
  return a;
}

Attraction attraction(const Ellipsoid& e, const Vec3& x) {
  using boost::math::ellint_rd;
  using boost::math::ellint_rf;
  const Vec3 u = x - e.center;
  const Vec3 s2 = e.semi_axes.cwiseAbs2();
  // λ: the largest root of Σ u_i²/(a_i² + λ) = 1 outside the ellipsoid, 0 inside. The potential is
  // stationary in λ, so its error enters only at second order.
  double lambda = 0.0;
  if (u.cwiseAbs2().cwiseQuotient(s2).sum() > 1.0) {
    auto f = [&](double l) { return (u.array().square() / (s2.array() + l)).sum() - 1.0; };
    std::uintmax_t iters = 200;
    const auto root = boost::math::tools::toms748_solve(
        f, 0.0, u.squaredNorm(), boost::math::tools::eps_tolerance<double>(52), iters);
    lambda = 0.5 * (root.first + root.second);
  }
  const Vec3 q = s2 + Vec3::Constant(lambda);
  const double k = std::numbers::pi * e.density * e.semi_axes.prod();
  const Vec3 rd(ellint_rd(q.y(), q.z(), q.x()), ellint_rd(q.z(), q.x(), q.y()),
                ellint_rd(q.x(), q.y(), q.z()));
  Attraction a;
  a.potential = k * (2.0 * ellint_rf(q.x(), q.y(), q.z()) - 2.0 / 3.0 * u.cwiseAbs2().dot(rd));
  a.gradient = -(4.0 / 3.0) * k * u.cwiseProduct(rd);
  return a;
}

Attraction attraction(const MassModel& m, const Vec3& x, int threads) {
  struct Visitor {
    const Vec3& x;
    int threads;
    Attraction operator()(const PointMasses& p) const { return attraction(p, x); }
    Attraction operator()(const Polyhedron& p) const { return attraction(p, x, threads); }
    Attraction operator()(const Ellipsoid& e) const { return attraction(e, x); }
  };
  return std::visit(Visitor{x, threads}, m);
}

}  // namespace newtop
