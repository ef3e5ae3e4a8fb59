#include <cmath>
#include <string>

#include "newtop/model/state_checks.hpp"

namespace newtop {
namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

}  // namespace

double gamma_norm(const Vec3& gamma) {
  const double largest = gamma.cwiseAbs().maxCoeff();
  if (largest == 0.0) return 0.0;
  return largest * (gamma / largest).norm();
}

void check_unit_gamma(const Vec3& gamma) {
  if (!finite(gamma)) {
    throw InputError("gamma: expected finite numbers, found " + format_vector(gamma));
  }
  if (gamma.cwiseAbs().maxCoeff() == 0.0) {
    throw InputError("gamma: expected a unit vector, found [0, 0, 0]");
  }
  const double norm = gamma_norm(gamma);
  if (std::abs(norm - 1.0) > kUnitGammaTolerance) {
    throw InputError("gamma: expected a unit vector (|gamma| = 1 to 1e-12), found |gamma| = " +
                     format_number(norm));
  }
}

Vec3 normalized_gamma(const Vec3& gamma) {
  if (!finite(gamma)) {
    throw InputError("gamma: expected finite numbers, found " + format_vector(gamma));
  }
  const double largest = gamma.cwiseAbs().maxCoeff();
  if (largest == 0.0) throw InputError("gamma: expected a unit vector, found [0, 0, 0]");
  const Vec3 unit_scaled = gamma / largest;
  return unit_scaled / unit_scaled.norm();
}

void validate(const State& x) {
  if (!finite(x.m)) throw InputError("m: expected finite numbers, found " + format_vector(x.m));
  check_unit_gamma(x.gamma);
}

}  // namespace newtop
