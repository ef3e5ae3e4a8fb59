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

// The input named when a product Π x_i^p_i of inputs overflows or underflows: the one whose
// factor |x|^p lies farthest from 1.
const char* dominant(std::initializer_list<std::pair<const char*, double>> log_factors) {
  const char* key = "";
  double worst = -1.0;
  for (const auto& [name, log_factor] : log_factors) {
    if (std::abs(log_factor) > worst) {
      worst = std::abs(log_factor);
      key = name;
    }
  }
  return key;
}

// A coefficient derived from non-zero inputs must be a finite normal number: an overflow would
// make the field infinite, an underflow would silently remove it.
void check_derived(const char* key, const char* what, double value, const std::string& inputs) {
  if (std::isfinite(value) && std::isnormal(value)) return;
  throw InputError(std::string(key) + ": " + what +
                   (std::isfinite(value) ? " underflows to " : " overflows to ") +
                   format_number(value) + " (" + inputs + ")");
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
  const double lambda = 3.0 * g / R;
  if (g != 0.0) {
    check_derived(dominant({{"g", std::log(std::abs(g))}, {"R", -std::log(R)}}), "lambda = 3g/R",
                  lambda, "g = " + format_number(g) + ", R = " + format_number(R));
  }
  return {g, lambda};
}

QuadraticField QuadraticField::from_mu_R(double mu, double R) {
  check_positive("mu", mu);
  check_positive("R", R);
  // μ/R² and 3μ/R³; where R² or R³ alone would overflow or underflow, by successive divisions.
  const double R2 = R * R, R3 = R2 * R;
  const double g = std::isnormal(R2) ? mu / R2 : mu / R / R;
  const double lambda =
      std::isnormal(R3) && std::isfinite(3.0 * mu) ? 3.0 * mu / R3 : 3.0 * (mu / R / R / R);
  const std::string inputs = "mu = " + format_number(mu) + ", R = " + format_number(R);
  const double log_mu = std::log(mu), log_R = std::log(R);
  check_derived(dominant({{"mu", log_mu}, {"R", -2 * log_R}}), "g = mu/R^2", g, inputs);
  check_derived(dominant({{"mu", log_mu}, {"R", -3 * log_R}}), "lambda = 3mu/R^3", lambda, inputs);
  return {g, lambda};
}

QuadraticField QuadraticField::uniform(double g) {
  check_finite("g", g);
  return {g, 0.0};
}

QuadraticField QuadraticField::brun(double N, double plane_offset) {
  check_finite("N", N);
  check_finite("plane_offset", plane_offset);
  const double g = -N * plane_offset;
  if (N != 0.0 && plane_offset != 0.0) {
    check_derived(dominant({{"N", std::log(std::abs(N))},
                            {"plane_offset", std::log(std::abs(plane_offset))}}),
                  "g = -N plane_offset", g,
                  "N = " + format_number(N) + ", plane_offset = " + format_number(plane_offset));
  }
  return {g, -N};
}

}  // namespace newtop
