#pragma once
/// \file
/// Pseudo-arclength continuation of a family F(u, p) = 0, u ∈ ℝⁿ, p a parameter (Keller 1977;
/// Doedel's AUTO; Dhooge, Govaerts & Kuznetsov's MATCONT), with bifurcation test functions located
/// along the family (docs/continuation.md).
///
/// Predictor: X = (u, p) moves by h along the unit tangent t, the null vector of [F_u F_p] oriented
/// as the previous one (so the family is followed through folds, where p turns back). Corrector:
/// Newton's method on F(X) = 0, t·(X − X_pred) = 0. The step grows after a quick convergence and
/// shrinks after a slow one, a failed one, or a turn of the tangent above max_angle (curvature).
/// Between two accepted points where a test function changes sign, its zero is found by TOMS 748
/// (Boost.Math) along the chord, each trial point corrected onto the family on the hyperplane
/// orthogonal to the chord: the event's parameter is located to round-off, not to the step.

#include <Eigen/Core>
#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace newtop {

/// The kinds of event: a fold (the family turns back, a multiplier or eigenvalue +1 / 0), a flip
/// (a multiplier −1: the period-doubled family starts there), a branch point (another family
/// crosses: a pitchfork or a transcritical point) and a Krein collision (two pairs of imaginary
/// eigenvalues or unit multipliers meet and leave the axis/circle: a Hamiltonian–Hopf point).
enum class BifurcationType { fold, flip, branch_point, krein };

/// "fold", "flip", "branch_point", "krein".
const char* to_string(BifurcationType t);

/// One point of a family with what the family's `evaluate` says about it.
struct FamilyPoint {
  double parameter = 0.0;
  Eigen::VectorXd values;  ///< the solution's defining values (u unless `evaluate` sets them)
  double period = 0.0;     ///< the period (periodic families); 0 otherwise
  /// Floquet multipliers (periodic families) or eigenvalues (equilibria, rotations).
  std::vector<std::complex<double>> multipliers;
  std::string stability;           ///< the family's verdict ("stable", "unstable", …)
  std::vector<double> tests;       ///< the family's test functions, in the order of `TestFunction`s
  double tangent_parameter = 0.0;  ///< dp/ds, the fold's test function
};

/// A bifurcation located on the family.
struct BifurcationEvent {
  BifurcationType type = BifurcationType::fold;
  double value = 0.0;  ///< the parameter there
  FamilyPoint point;   ///< the solution there, its multipliers or eigenvalues
};

/// A test function of the family: its kind; the value is computed by the family's `evaluate`
/// (FamilyPoint::tests). A zero between two points is an event when `confirm` (if given) accepts
/// the located point: e.g. a Krein collision only where the colliding eigenvalues are imaginary.
struct TestFunction {
  BifurcationType type = BifurcationType::branch_point;
  std::function<bool(const FamilyPoint&)> confirm;
};

/// The family to continue.
struct ContinuationProblem {
  int unknowns = 0;  ///< n ≥ 0 (n = 0: the family is known explicitly in p)
  /// F(u, p), n components.
  std::function<Eigen::VectorXd(const Eigen::VectorXd& u, double p)> residual;
  /// [F_u F_p], n × (n + 1); empty: central finite differences of `residual`.
  std::function<Eigen::MatrixXd(const Eigen::VectorXd& u, double p)> jacobian;
  /// Period, multipliers, stability and test function values at a solution.
  std::function<FamilyPoint(const Eigen::VectorXd& u, double p)> evaluate;
  std::vector<TestFunction> tests;  ///< the fold (dp/ds) is always tested besides these
  /// Also test det [F_u F_p; tᵀ] (appended to FamilyPoint::tests), which changes sign where
  /// another family crosses (a branch point) but not at a fold (AUTO's test for algebraic
  /// problems); set by continue_branch.
  bool branch_points = false;
};

struct ContinuationSettings {
  double initial_step = 0.01;  ///< arclength in (u, p)
  double min_step = 1e-8;
  double max_step = 0.05;
  double max_angle = 0.2;  ///< radians between successive tangents before the step is halved
  int max_points = 5000;
  int max_newton = 8;
  double tolerance = 1e-12;   ///< max |F| and max |ΔX| of the corrector
  double switch_step = 1e-3;  ///< continue_branch: the first step off the branch point
};

/// The family from p0 towards p_end (p0 ≠ p_end): the points in arclength order, the located
/// events, and why it ended.
struct Family {
  std::vector<FamilyPoint> points;
  std::vector<BifurcationEvent> events;
  /// "range" (reached p_end, the last point exactly there), "left_range" (turned back past p0),
  /// "step_underflow" (the corrector failed at min_step), "max_points"; a branch also
  /// "branch_point" (it met another family: the branch-point test changed sign on it).
  std::string end;
};

/// Continues the family from the solution u0 at p0 (polished first by Newton's method at fixed p;
/// InputError when that fails or an input is not finite).
Family continue_family(const ContinuationProblem& problem, const Eigen::VectorXd& u0, double p0,
                       double p_end, const ContinuationSettings& settings = {});

/// Branch switching (Keller 1977; AUTO's ISW = −1, MATCONT's BP continuation): the family that
/// leaves the branch point (u*, p*) of `problem` along `direction` (n + 1 values, a null vector
/// of [F_u F_p] there: for a pitchfork, as at a flip in the doubled period or at a symmetry
/// breaking, (v, 0) with v the critical eigenvector). The first point is the branch point itself;
/// the second, the branch point moved by settings.switch_step along `direction` and corrected on
/// the hyperplane orthogonal to it; from there the branch is continued like a family, with its
/// events and det [F_u F_p; tᵀ] as a branch-point test, until it reaches p_min or p_max (the last
/// point exactly there, `range`) or meets another family (`branch_point`: the located branch point
/// is its last event). InputError for a bad input or when the first corrector fails.
Family continue_branch(const ContinuationProblem& problem, const Eigen::VectorXd& u_star,
                       double p_star, const Eigen::VectorXd& direction, double p_min, double p_max,
                       const ContinuationSettings& settings = {});

}  // namespace newtop
