#pragma once
/// \file
/// The exact field of a mass model against its quadratic model (`newtop field`, docs/model.md
/// §2–§3): V, ∂V/∂γ, ∂V/∂R, L, F and ∂²V/∂γ² of both at one orientation, in the principal axes and
/// in the mass model's own (input) frame, and the error of the quadratic model against R.

#include <memory>
#include <optional>
#include <vector>

#include "newtop/exact/exact_field.hpp"
#include "newtop/exact/multipole.hpp"
#include "newtop/model/model.hpp"

namespace newtop {

/// The field's values at γ and its Hessian ∂²V/∂γ².
struct FieldSample {
  FieldValues values;
  Mat3 hessian = Mat3::Zero();
};

/// The exact field, its quadratic model (the multipole expansion of order 3 with the same centre),
/// their difference (exact − approx), at one γ and R.
struct FieldComparison {
  Vec3 gamma = Vec3::UnitZ();  ///< in the frame of the values
  FieldSample exact, approx, difference;
};

/// The comparison at γ (principal axes of `body`, the body of `mass_model` with axes P =
/// body.principal_axes()) for a centre μ at distance R.
FieldComparison compare_field(const std::shared_ptr<const MassModel>& mass_model, const Body& body,
                              double mu, double R, const Vec3& gamma);

/// The same comparison with every vector and matrix in the input frame of the mass model (v ↦ P v,
/// H ↦ P H Pᵀ); scalars unchanged.
FieldComparison in_input_frame(const FieldComparison& c, const Mat3& P);

/// The error of the quadratic model over n ≥ 2 distances R1·(R2/R1)^(i/(n−1)) (0 < R1 < R2),
/// with the log–log slopes of the errors (least squares).
struct FieldScan {
  std::vector<double> R, potential_error, moment_error, moment_relative_error;
  double slope_potential = 0.0, slope_moment = 0.0;
};
FieldScan scan_field_R(const std::shared_ptr<const MassModel>& mass_model, const Body& body,
                       double mu, double R1, double R2, int n, const Vec3& gamma);

/// What `newtop field` reports for a model built on a mass model: the centre (μ, R), γ in the
/// principal axes, the comparison there and in the mass model's frame (input.gamma the γ given),
/// the truncation error of the quadratic model, and the R-scan when asked.
struct FieldReport {
  double mu = 1.0, R = 0.0;
  Vec3 gamma = Vec3::UnitZ();  ///< principal axes
  FieldComparison principal, input;
  TruncationError truncation;
  std::optional<FieldScan> scan;
};

/// The R-scan of field_report: n distances from R1 to R2 (scan_field_R).
struct RadiusRange {
  double R1, R2;
  int n;
};

/// The field of `model` (which must have a mass model) at the direction `gamma_input` (a unit
/// vector in the mass model's frame, as io::parse_gamma gives it) for the centre of the model's
/// exact or multipole field, or at distance `R` (a quadratic model needs R; μ = 1 then). Throws
/// InputError naming what is missing.
FieldReport field_report(const Model& model, const Vec3& gamma_input, std::optional<double> R,
                         const std::optional<RadiusRange>& scan = std::nullopt);

/// Least-squares slope of log y against log x.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace newtop
