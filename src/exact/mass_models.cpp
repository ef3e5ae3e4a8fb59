#include "newtop/exact/mass_models.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace newtop {
namespace {

void check_finite_vector(const char* name, const Vec3& v) {
  if (!v.allFinite()) {
    throw InputError(std::string(name) + ": expected finite numbers, found " + format_vector(v));
  }
}

}  // namespace

Polyhedron make_box(const Vec3& dimensions, double density, const Vec3& center) {
  check_finite_vector("dimensions", dimensions);
  if (!(dimensions.minCoeff() > 0)) {
    throw InputError("dimensions: expected three lengths > 0, found " + format_vector(dimensions));
  }
  check_finite_vector("center", center);
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

MassProperties mass_properties(const Polyhedron& p) {
  // Tetrahedron (O, a, b, c): volume det/6, ∫ρ dV = det/24 (a + b + c),
  // ∫ρρᵀ dV = det/120 (aaᵀ + bbᵀ + ccᵀ + (a + b + c)(a + b + c)ᵀ).
  // (The first moment is Polyhedron::first_moment(), the same sum in double-double.)
  double vol = 0.0;
  Mat3 second = Mat3::Zero();
  for (const Triangle& t : p.faces()) {
    const Vec3 &a = p.vertices()[t[0]], &b = p.vertices()[t[1]], &c = p.vertices()[t[2]];
    const double det = a.dot(b.cross(c));
    const Vec3 s = a + b + c;
    vol += det;
    second += det * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  const double sigma = p.density();
  MassProperties mp;
  mp.mass = sigma * vol / 6.0;
  mp.center_of_mass = p.first_moment() / mp.mass;
  const Mat3 S = sigma * second / 120.0;
  mp.inertia_tensor = S.trace() * Mat3::Identity() - S;
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

GravityGradient gravity_gradient(const MassModel& m, const Vec3& x, int threads) {
  struct Visitor {
    const Vec3& x;
    int threads;
    GravityGradient operator()(const PointMasses& p) const { return gravity_gradient(p, x); }
    GravityGradient operator()(const Polyhedron& p) const {
      return gravity_gradient(p, x, threads);
    }
    GravityGradient operator()(const Ellipsoid& e) const { return gravity_gradient(e, x); }
  };
  return std::visit(Visitor{x, threads}, m);
}

MomentAndDerivative moment_with_derivative(const MassModel& m, const Vec3& x, const Vec3& u,
                                           int threads) {
  if (const auto* p = std::get_if<PointMasses>(&m)) return moment_with_derivative(*p, x, u);
  return {attraction(m, x, threads).moment, gravity_gradient(m, x, threads).moment_jacobian * u};
}

}  // namespace newtop
