#include "newtop/analysis/field_scan.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace newtop {
namespace {

/// A unit vector normalised in double precision has |γ| within a few ε of 1.
constexpr double kUnitTolerance = 16 * std::numeric_limits<double>::epsilon();

FieldSample difference(const FieldSample& a, const FieldSample& b) {
  const FieldValues &x = a.values, &y = b.values;
  return {{x.potential - y.potential, x.grad_gamma - y.grad_gamma, x.dV_dR - y.dV_dR,
           x.moment - y.moment, x.force - y.force},
          a.hessian - b.hessian};
}

FieldSample rotated(const FieldSample& s, const Mat3& P) {
  const FieldValues& v = s.values;
  return {{v.potential, P * v.grad_gamma, v.dV_dR, P * v.moment, P * v.force},
          P * s.hessian * P.transpose()};
}

}  // namespace

FieldComparison compare_field(const std::shared_ptr<const MassModel>& mass_model, const Body& body,
                              double mu, double R, const Vec3& gamma) {
  const Mat3& P = body.principal_axes();
  const ExactField x = ExactField::make(mass_model, mu, R, P);
  const MultipoleField q = MultipoleField::make(*mass_model, 3, mu, R, P);
  FieldComparison c;
  c.gamma = gamma;
  c.exact = {field_values(x, gamma), hessian_gamma(body, x, gamma)};
  c.approx = {field_values(q, gamma), hessian_gamma(body, q, gamma)};
  c.difference = difference(c.exact, c.approx);
  return c;
}

FieldComparison in_input_frame(const FieldComparison& c, const Mat3& P) {
  return {P * c.gamma, rotated(c.exact, P), rotated(c.approx, P), rotated(c.difference, P)};
}

FieldScan scan_field_R(const std::shared_ptr<const MassModel>& mass_model, const Body& body,
                       double mu, double R1, double R2, int n, const Vec3& gamma) {
  if (!(R1 > 0) || !(R2 > R1) || n < 2) {
    throw InputError("R: expected R1:R2:N with 0 < R1 < R2 and N >= 2, found " + format_number(R1) +
                     ":" + format_number(R2) + ":" + std::to_string(n));
  }
  FieldScan s;
  for (int i = 0; i < n; ++i) {
    const double r = R1 * std::pow(R2 / R1, static_cast<double>(i) / (n - 1));
    const FieldComparison c = compare_field(mass_model, body, mu, r, gamma);
    s.R.push_back(r);
    s.potential_error.push_back(std::abs(c.exact.values.potential - c.approx.values.potential));
    s.moment_error.push_back((c.exact.values.moment - c.approx.values.moment).norm());
    s.moment_relative_error.push_back(s.moment_error.back() / c.exact.values.moment.norm());
  }
  s.slope_potential = loglog_slope(s.R, s.potential_error);
  s.slope_moment = loglog_slope(s.R, s.moment_error);
  return s;
}

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

FieldReport field_report(const Model& model, const Vec3& gamma_input, std::optional<double> R,
                         const std::optional<RadiusRange>& scan) {
  const std::shared_ptr<const MassModel>& mass_model = model.mass_model();
  if (!mass_model) throw InputError("model: expected a model built on a mass model, found none");
  const FieldKind kind = model.kind();
  if (kind == FieldKind::quadratic && !R) {
    throw InputError("R: expected the distance of the centre for a quadratic model, found none");
  }
  if (!gamma_input.allFinite() || !(std::abs(gamma_input.norm() - 1.0) <= kUnitTolerance)) {
    throw InputError("gamma: expected a unit vector, found " + format_vector(gamma_input) +
                     " (|gamma| = " + format_number(gamma_input.norm()) + ")");
  }
  const CentreParameters centre = centre_parameters(model);
  FieldReport r;
  r.mu = kind == FieldKind::quadratic ? 1.0 : centre.mu;  // only R given: a centre of unit μ
  r.R = R.value_or(centre.R);
  const Body& body = model.body();
  const Mat3& P = body.principal_axes();
  const Vec3& given = gamma_input;
  r.gamma = P.transpose() * given;  // the mass model's frame → principal axes
  r.principal = compare_field(mass_model, body, r.mu, r.R, r.gamma);
  r.input = in_input_frame(r.principal, P);
  r.input.gamma = given;  // as given, not rotated there and back
  r.truncation = truncation_error(MultipoleField::make(*mass_model, 3, r.mu, r.R, P), r.gamma);
  if (scan) r.scan = scan_field_R(mass_model, body, r.mu, scan->R1, scan->R2, scan->n, r.gamma);
  return r;
}

}  // namespace newtop
