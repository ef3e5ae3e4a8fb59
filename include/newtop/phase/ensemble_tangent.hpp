#pragma once
/// \file
/// The ensemble tangent stepper: TangentSplittingStepper (tangent.hpp) for many points of one
/// quadratic-field model at once, in the SIMD lanes of the ensemble stepper
/// (newtop/integrate/ensemble.hpp), each point with the same number (1 to 6) of tangent vectors.
///
/// Guarantee: each point's state is bit-identical to TangentSplittingStepper's, and so are its
/// tangent vectors through the rotations; the kick forms (∂L/∂γ) δγ as γ × (λ I δγ) − (∂V/∂γ) × δγ
/// instead of through the 3 × 3 matrix, so the tangent vectors agree with the scalar stepper's to
/// round-off (tests/phase/test_ensemble_tangent.cpp bounds it); with one tangent vector the scalar
/// kick forms it without the matrix too (moment_derivative), and the tangent vector is
/// bit-identical as well (tested). A point's results, state and
/// tangent vectors, do not depend on its lane, the ensemble's size or the instruction set (bit for
/// bit).

#include <cstdint>
#include <vector>

#include "newtop/integrate/ensemble.hpp"
#include "newtop/phase/tangent.hpp"

namespace newtop::phase {

class EnsembleTangentStepper {
 public:
  /// The axes split only, as TangentSplittingStepper (InputError otherwise, or for a path this
  /// build or CPU lacks).
  EnsembleTangentStepper(const CompositionTable& table, const SplitOrdering& ordering,
                         SimdPath path = best_simd_path());

  int order() const { return order_; }
  SimdPath path() const { return path_; }

  /// `steps` steps of size h of every point of x and its tangent vectors V[i] (V.size() ==
  /// x.size(), every V[i] with the same number of columns, 1 to 6; InputError otherwise).
  void advance(const QuadraticModel& model, EnsembleState& x, std::vector<Tangent>& V, double h,
               std::int64_t steps);
  /// The same with a model per point (EnsembleModels prepared for the stepper's ordering; its
  /// groups share the order of the axis rotations): point i on model i, with the guarantee above
  /// on its own model.
  void advance(const EnsembleModels& models, EnsembleState& x, std::vector<Tangent>& V, double h,
               std::int64_t steps);

 private:
  int order_;
  SplitOrdering ordering_;
  SimdPath path_;
  std::vector<double> a_, b_;
  std::vector<double> workspace_;
  std::vector<double> constants_;  // per lane, with a model per point
};

}  // namespace newtop::phase
