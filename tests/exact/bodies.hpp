#pragma once
// Test bodies of the exact field with their high-precision references (reference.hpp): point
// masses with and without a centre of mass at O, a centred and an offset box (polyhedron), a
// centred and an offset ellipsoid.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "newtop/exact/mass_models.hpp"
#include "reference.hpp"

namespace newtop::test {

/// A reference rounded to double.
struct Values {
  double potential;
  Vec3 grad_gamma, moment;
  Mat3 hessian, moment_jacobian;
};

template <class T>
Values lower_all(const Reference<T>& r) {
  return {static_cast<double>(r.potential), lower(r.grad_gamma), lower(r.moment), lower(r.hessian),
          lower(r.moment_jacobian)};
}

struct Case {
  std::string name;
  std::shared_ptr<const MassModel> model;
  /// Reference values in 50 or 100 digits at (μ, R, γ), γ in the model's frame.
  std::function<Values(double, double, const Vec3&)> reference;
  bool symmetric;  ///< every odd mass moment zero: the quadratic model is exact to (r/R)²
};

/// The six-point spacecraft of a gravity-gradient unit test (I = diag(500, 800, 350), r0 = 0).
inline const std::vector<double> kLeoMasses{162.5, 162.5, 12.5, 12.5, 237.5, 237.5};
inline const std::vector<Vec3> kLeoPoints{Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
                                          Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
inline const std::vector<double> kFourMasses{1.0, 2.0, 0.5, 1.5};
inline const std::vector<Vec3> kFourPoints{Vec3(1, 0, 0.3), Vec3(-0.4, 0.8, 0), Vec3(0, -0.5, 1),
                                           Vec3(0.2, 0.1, -0.7)};

inline std::vector<Case> cases() {
  const Vec3 d(1.0, 2.0, 3.0), c(0.3, -0.2, 0.5), a(1.0, 2.0, 3.0);
  return {
      {"six points (LEO)", std::make_shared<const MassModel>(PointMasses(kLeoMasses, kLeoPoints)),
       [](double mu, double R, const Vec3& g) {
         return lower_all(point_masses<Real50>(kLeoMasses, kLeoPoints, mu, R, g));
       },
       true},
      {"four points, r0 != 0",
       std::make_shared<const MassModel>(PointMasses(kFourMasses, kFourPoints)),
       [](double mu, double R, const Vec3& g) {
         return lower_all(point_masses<Real50>(kFourMasses, kFourPoints, mu, R, g));
       },
       false},
      {"box 1x2x3", std::make_shared<const MassModel>(make_box(d, 2.0)),
       [d](double mu, double R, const Vec3& g) {
         return lower_all(box<Real100>(-0.5 * d, 0.5 * d, 2.0, mu, R, g));
       },
       true},
      {"offset box", std::make_shared<const MassModel>(make_box(d, 2.0, c)),
       [d, c](double mu, double R, const Vec3& g) {
         return lower_all(box<Real100>(c - 0.5 * d, c + 0.5 * d, 2.0, mu, R, g));
       },
       false},
      {"ellipsoid 1,2,3", std::make_shared<const MassModel>(Ellipsoid::make(a, 2.0)),
       [a](double mu, double R, const Vec3& g) {
         return lower_all(ellipsoid<Real50>(a, Vec3::Zero(), 2.0, mu, R, g));
       },
       true},
      {"offset ellipsoid", std::make_shared<const MassModel>(Ellipsoid::make(a, 2.0, c)),
       [a, c](double mu, double R, const Vec3& g) {
         return lower_all(ellipsoid<Real50>(a, c, 2.0, mu, R, g));
       },
       false},
  };
}

}  // namespace newtop::test
