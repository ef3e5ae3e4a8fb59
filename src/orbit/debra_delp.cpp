#include "newtop/orbit/debra_delp.hpp"

#include <cmath>
#include <numbers>

namespace newtop {

const char* to_string(DebraDelpRegion r) {
  switch (r) {
    case DebraDelpRegion::lagrange:
      return "lagrange";
    case DebraDelpRegion::debra_delp:
      return "debra_delp";
    case DebraDelpRegion::unstable:
      break;
  }
  return "unstable";
}

DebraDelpRegion debra_delp_closed_form(double k_R, double k_Y) {
  const bool pitch = k_R > k_Y;
  const double p = k_R * k_Y;
  const bool roll_yaw = p > 0 && 1 + 3 * k_R + p > 4 * std::sqrt(p);
  if (!(pitch && roll_yaw)) return DebraDelpRegion::unstable;
  return k_R > 0 ? DebraDelpRegion::lagrange : DebraDelpRegion::debra_delp;
}

Eigen::Vector4d debra_delp_characteristic(double k_R, double k_Y) {
  const double k_P = (k_R - k_Y) / (1 - k_R * k_Y);
  const double b1 = 1 + 3 * k_R + k_R * k_Y, b0 = 4 * k_R * k_Y;
  // (σ + 3k_P)(σ² + b1 σ + b0)
  return {3 * k_P * b0, b0 + 3 * k_P * b1, b1 + 3 * k_P, 1.0};
}

Vec3 inertia_from_ratios(double k_R, double k_Y) {
  for (const auto& [name, k] : {std::pair{"k_R", k_R}, std::pair{"k_Y", k_Y}}) {
    if (!(std::abs(k) < 1)) {
      throw InputError(std::string(name) +
                       ": expected a number in (-1, 1) (a physical body), found " +
                       format_number(k));
    }
  }
  const double d = 1 - k_R * k_Y;
  return {(1 - k_Y) / d, 1.0, (1 - k_R) / d};
}

namespace {

/// A zero or repeated root of σ³ + a2 σ² + a1 σ + a0 (σ = s², c the polynomial in s).
bool degenerate(const Eigen::Matrix<double, 7, 1>& c) {
  const double a0 = c[0], a1 = c[2], a2 = c[4];
  const double terms[] = {18 * a2 * a1 * a0, -4 * a2 * a2 * a2 * a0, a2 * a2 * a1 * a1,
                          -4 * a1 * a1 * a1, -27 * a0 * a0};
  double disc = 0, disc_scale = 0;
  for (double t : terms) {
    disc += t;
    disc_scale += std::abs(t);
  }
  const double scale = 1 + std::abs(a1) + std::abs(a2);
  return std::abs(a0) <= kDebraDelpDegeneracy * scale ||
         std::abs(disc) <= kDebraDelpDegeneracy * disc_scale;
}

}  // namespace

DebraDelpPoint debra_delp_point(double k_R, double k_Y) {
  const Body body = Body::from_principal(inertia_from_ratios(k_R, k_Y), 1.0, Vec3::Zero());
  const CircularOrbitModel model(body, CircularOrbit::from_rate(1.0));
  const OrbitState rest = relative_rest_state(model, Vec3::UnitZ(), Vec3::UnitY());
  const RelativeSpectrum sp = relative_equilibrium_stability(model, rest);
  DebraDelpPoint p;
  p.k_R = k_R;
  p.k_Y = k_Y;
  p.closed_form = debra_delp_closed_form(k_R, k_Y);
  p.computed = sp.verdict == OrbitStability::lyapunov     ? DebraDelpRegion::lagrange
               : sp.verdict == OrbitStability::gyroscopic ? DebraDelpRegion::debra_delp
                                                          : DebraDelpRegion::unstable;
  p.boundary = degenerate(sp.characteristic);
  p.max_real_part = sp.max_real_part;
  p.characteristic = sp.characteristic;
  return p;
}

std::vector<DebraDelpPoint> debra_delp_scan(double k_R_lo, double k_R_hi, int n_R, double k_Y_lo,
                                            double k_Y_hi, int n_Y) {
  if (n_R < 1 || n_Y < 1) {
    throw InputError("scan: expected counts >= 1, found " + std::to_string(n_R) + " x " +
                     std::to_string(n_Y));
  }
  auto at = [](double lo, double hi, int n, int i) {
    return n == 1 ? lo : lo + (hi - lo) * i / (n - 1);
  };
  // Check the corners first: no work is done on a grid that leaves the square.
  inertia_from_ratios(k_R_lo, k_Y_lo);
  inertia_from_ratios(k_R_hi, k_Y_hi);
  std::vector<DebraDelpPoint> out;
  out.reserve(static_cast<std::size_t>(n_R) * n_Y);
  for (int i = 0; i < n_R; ++i) {
    for (int j = 0; j < n_Y; ++j) {
      out.push_back(debra_delp_point(at(k_R_lo, k_R_hi, n_R, i), at(k_Y_lo, k_Y_hi, n_Y, j)));
    }
  }
  return out;
}

}  // namespace newtop

namespace newtop {

std::array<LibrationMode, 3> libration_modes(const Body& body, const OrbitState& s, double rate) {
  Eigen::Index p = 0, y = 0;
  s.normal.cwiseAbs().maxCoeff(&p);
  s.gamma.cwiseAbs().maxCoeff(&y);
  const Eigen::Index r = 3 - p - y;  // the third axis (p ≠ y for a physical state)
  const Vec3& I = body.inertia();
  const double A = I[r], B = I[p], C = I[y];
  const double kR = (B - C) / A, kY = (B - A) / C, kP = (A - C) / B;
  const double b = 1 + 3 * kR + kR * kY, c = 4 * kR * kY;
  const std::complex<double> root = std::sqrt(std::complex<double>(b * b - 4 * c));
  auto mode = [&](const char* name, std::complex<double> sigma) {
    LibrationMode m{name, sigma};
    m.oscillating = sigma.imag() == 0.0 && sigma.real() < 0.0;
    if (m.oscillating) {
      m.frequency = rate * std::sqrt(-sigma.real());
      m.period = 2 * std::numbers::pi / m.frequency;
    }
    return m;
  };
  return {mode("pitch", -3 * kP), mode("roll-yaw", 0.5 * (-b + root)),
          mode("roll-yaw", 0.5 * (-b - root))};
}

}  // namespace newtop
