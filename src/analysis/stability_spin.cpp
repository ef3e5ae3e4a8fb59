#include "newtop/analysis/stability_spin.hpp"

#include <cmath>
#include <limits>

namespace newtop {
namespace {

void check_axis(int axis) {
  if (axis < 0 || axis > 2) {
    throw InputError("axis: expected 0, 1 or 2 (x, y, z), found " + std::to_string(axis));
  }
}

bool linearly_stable_at(const QuadraticModel& model, int axis, double Omega) {
  return spin_stability(model, axis, Omega).linearly_stable;
}

}  // namespace

const char* to_string(AxisClass c) {
  switch (c) {
    case AxisClass::least:
      return "least";
    case AxisClass::middle:
      return "middle";
    case AxisClass::largest:
      break;
  }
  return "largest";
}

AxisClass axis_class(const Body& body, int axis) {
  check_axis(axis);
  const Vec3 m = spin_frame_moments(body, axis);  // (A, B, C) with C the spin axis
  const int above = (m.z() > m.x()) + (m.z() > m.y());
  const int below = (m.z() < m.x()) + (m.z() < m.y());
  if (above == 2 || (above == 1 && below == 0)) return AxisClass::largest;
  if (below == 2 || (below == 1 && above == 0) || above == 0) return AxisClass::least;
  return AxisClass::middle;
}

State principal_spin(const Body& body, int axis, double Omega) {
  check_axis(axis);
  const Vec3 e = Vec3::Unit(axis);
  return state_from_omega(body, Omega * e, e);
}

Vec3 spin_frame_moments(const Body& body, int axis) {
  check_axis(axis);
  const Vec3& I = body.inertia();
  return {I[(axis + 1) % 3], I[(axis + 2) % 3], I[axis]};
}

Eigen::Vector3d beletsky_polynomial(const Body& body, double lambda, int axis, double Omega) {
  const Vec3 m = spin_frame_moments(body, axis);
  const double A = m.x(), B = m.y(), C = m.z();
  const double a = (C - B) / A, b = (C - A) / B, w2 = Omega * Omega;
  return {1.0, -((a + b) * lambda - (1 + a * b) * w2), a * b * (lambda - w2) * (lambda - w2)};
}

std::optional<double> beletsky_threshold(const Body& body, double lambda, int axis) {
  const Vec3 m = spin_frame_moments(body, axis);
  const double A = m.x(), B = m.y(), C = m.z();
  const double a = (C - B) / A, b = (C - A) / B;
  if (!(lambda > 0) || a < 0 || b < 0 || a + b == 0) return std::nullopt;
  return std::sqrt(lambda) * (std::sqrt(a) + std::sqrt(b)) / (1 + std::sqrt(a * b));
}

Eigen::Matrix<double, 5, 1> axis_spin_polynomial(const QuadraticModel& model, int axis,
                                                 double Omega) {
  const Vec3 m = spin_frame_moments(model.body, axis);
  const double A = m.x(), B = m.y(), C = m.z();
  const double lambda = model.field.lambda_, w2 = Omega * Omega;
  const double kz = model.body.mass() * model.field.g * model.body.center_of_mass()[axis];
  const double beta =
      lambda * (A * (A - C) + B * (B - C)) + w2 * ((A - C) * (B - C) + A * B) - kz * (A + B);
  const double c = ((A - C) * (w2 - lambda) + kz) * ((B - C) * (w2 - lambda) + kz);
  Eigen::Matrix<double, 5, 1> p;
  p << c, 0.0, beta, 0.0, A * B;
  return p;
}

Spectrum spin_stability(const QuadraticModel& model, int axis, double Omega) {
  return linear_stability(model, principal_spin(model.body, axis, Omega));
}

double spin_omega_range(const QuadraticModel& model) {
  const Vec3& I = model.body.inertia();
  const double b = model.body.mass() * std::abs(model.field.g) * model.body.center_of_mass().norm();
  const double range = 8 * (std::sqrt(std::abs(model.field.lambda_) * I.maxCoeff() / I.minCoeff()) +
                            std::sqrt(b * I.maxCoeff()) / I.minCoeff());
  return range > 0 ? range : 1.0;
}

std::optional<double> numeric_threshold(const QuadraticModel& model, int axis, int samples) {
  const double top = spin_omega_range(model);
  if (!linearly_stable_at(model, axis, top)) return std::nullopt;
  // Last sample that is unstable; above it the samples are stable.
  int last_unstable = -1;
  for (int k = samples - 1; k >= 0; --k) {
    if (!linearly_stable_at(model, axis, top * k / samples)) {
      last_unstable = k;
      break;
    }
  }
  if (last_unstable < 0) return std::nullopt;
  double lo = top * last_unstable / samples, hi = top * (last_unstable + 1) / samples;
  // Bisection to round-off: the interval halves until its ends are adjacent doubles.
  while (hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi) {
    const double mid = 0.5 * (lo + hi);
    (linearly_stable_at(model, axis, mid) ? hi : lo) = mid;
  }
  return hi;
}

std::vector<ScanPoint> scan_omega(const QuadraticModel& model, int axis, double w1, double w2,
                                  int n) {
  if (n < 1 || n > kMaxScanPoints) {
    throw InputError("scan: expected 1 to " + std::to_string(kMaxScanPoints) + " points, found " +
                     std::to_string(n));
  }
  if (!std::isfinite(w1) || !std::isfinite(w2)) {
    throw InputError("scan: expected finite ends of the Omega range, found " + format_number(w1) +
                     ", " + format_number(w2));
  }
  std::vector<ScanPoint> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double w = n == 1 ? w1 : w1 + (w2 - w1) * k / (n - 1);
    const Spectrum s = spin_stability(model, axis, w);
    out.push_back({w, s.max_real_part, s.linearly_stable, s.lyapunov_stable});
  }
  return out;
}

void check_spin_parameter(const std::string& what, const std::string& name) {
  if (name != "omega" && name != "lambda" && name != "A" && name != "B" && name != "C") {
    throw InputError(what + ": expected a parameter omega, lambda, A, B or C, found '" + name +
                     "'");
  }
}

std::optional<Spectrum> spin_stability_at(const QuadraticModel& base, int axis, double omega,
                                          const std::vector<SpinParameter>& parameters) {
  Vec3 I = base.body.inertia();
  double lambda = base.field.lambda_, w = omega;
  for (const auto& [name, v] : parameters) {
    check_spin_parameter("parameter", name);
    if (name == "omega") w = v;
    if (name == "lambda") lambda = v;
    if (name == "A") I.x() = v;
    if (name == "B") I.y() = v;
    if (name == "C") I.z() = v;
  }
  try {
    const QuadraticModel m{Body::from_principal(I, base.body.mass(), base.body.center_of_mass()),
                           QuadraticField::coulomb(base.field.g, lambda)};
    return spin_stability(m, axis, w);
  } catch (const InputError&) {
    return std::nullopt;  // e.g. the triangle inequality fails at this point
  }
}

const char* to_string(GridVerdict v) {
  switch (v) {
    case GridVerdict::stable:
      return "stable";
    case GridVerdict::unstable:
      return "unstable";
    case GridVerdict::nonphysical:
      return "nonphysical";
  }
  return "nonphysical";
}

}  // namespace newtop
