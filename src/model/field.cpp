#include "newtop/model/field.hpp"

#include <cmath>

namespace newtop {
namespace {

void check_finite(const char* name, double x) {
  if (!std::isfinite(x)) {
    throw InputError(std::string(name) + ": expected a finite number, found " + format_number(x));
  }
}

void check_positive(const char* name, double x) {
  if (!std::isfinite(x) || !(x > 0)) {
    throw InputError(std::string(name) + ": expected a finite number > 0, found " +
                     format_number(x));
  }
}

}  // namespace

QuadraticField QuadraticField::coulomb(double g, double lambda) {
  check_finite("g", g);
  check_finite("lambda", lambda);
  return {g, lambda};
}

QuadraticField QuadraticField::from_g_R(double g, double R) {
  check_finite("g", g);
  check_positive("R", R);
  return {g, 3.0 * g / R};
}

QuadraticField QuadraticField::from_mu_R(double mu, double R) {
  check_positive("mu", mu);
  check_positive("R", R);
  return {mu / (R * R), 3.0 * mu / (R * R * R)};
}

QuadraticField QuadraticField::uniform(double g) {
  check_finite("g", g);
  return {g, 0.0};
}

QuadraticField QuadraticField::brun(double N, double plane_offset) {
  check_finite("N", N);
  check_finite("plane_offset", plane_offset);
  return {-N * plane_offset, -N};
}

}  // namespace newtop
