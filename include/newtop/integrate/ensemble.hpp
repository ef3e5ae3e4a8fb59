#pragma once
/// \file
/// The ensemble stepper: many trajectories of one quadratic-field model (docs/model.md §3) advanced
/// in lockstep by a Lie–Poisson splitting method (splitting.hpp), in structure-of-arrays form, one
/// trajectory per lane of a SIMD register (AVX-512: 8 doubles, AVX2: 4, portable: 2), the
/// instruction set chosen at run time from what the CPU has.
///
/// Guarantee: every point's result is bit-identical to SplittingStepper::step applied to it alone
/// with the same table, ordering, model and step, whatever its lane, the ensemble's size or the
/// instruction set. The kernels do the scalar sub-flows' operations in the same order, without
/// fused multiply-adds, and hand the rare lane outside the short Taylor series of the rotation
/// angles (θ² > 1e-4) to the scalar functions themselves. This holds when the library is compiled
/// without contraction of a·b + c into a fused multiply-add in the scalar stepper, which is the
/// case for x86-64 builds without -mfma/-march=native (tests/integrate/test_ensemble.cpp checks
/// it).

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/integrate/splitting.hpp"
#include "newtop/model/basic_model.hpp"

namespace newtop {

namespace phase {
class EnsembleTangentStepper;
}

/// The points of an ensemble in structure-of-arrays form, body frame: point i is
/// m = (m[0][i], m[1][i], m[2][i]) and γ = (gamma[0][i], gamma[1][i], gamma[2][i]).
struct EnsembleState {
  std::array<std::vector<double>, 3> m;
  std::array<std::vector<double>, 3> gamma;

  EnsembleState() = default;
  explicit EnsembleState(std::span<const State> states);

  std::size_t size() const { return m[0].size(); }
  State operator[](std::size_t i) const;
  void set(std::size_t i, const State& x);
  void push_back(const State& x);
};

/// The instruction sets of the ensemble kernels.
enum class SimdPath { portable, avx2, avx512 };

/// "portable", "avx2", "avx512".
std::string_view simd_path_name(SimdPath path);
/// Whether this build has the path and this CPU can run it (portable: always; avx2: AVX2 and FMA;
/// avx512: AVX-512F).
bool simd_path_available(SimdPath path);
/// The widest available path.
SimdPath best_simd_path();
/// The number of points a kernel of the path advances at once (an ensemble of any size is padded
/// to a multiple; the padding never changes a point's result).
std::size_t simd_block(SimdPath path);

/// One quadratic-field model per point of an ensemble (a sweep over the body's or the field's
/// numbers), prepared for one ordering of the split: each point's constants of the split and the
/// kick (split_frame: rates, k/I, 1/I_r; M g r0, λ, I), held per lane by the stepper.
///
/// The grouping rule: a model's working frame follows its body (by_moment orders the axes by
/// increasing moment; the spin split runs one more rotation when the reference axis has k ≠ 0),
/// and the lanes of one kernel run one program of stages; so the points are grouped by (working
/// axes, that rotation), and the stepper runs each group on its own. Within a group each lane does
/// its point's scalar operations on its own constants, so each point's result is
/// SplittingStepper's on its own model, bit for bit, whatever the other points.
class EnsembleModels {
 public:
  EnsembleModels(std::span<const QuadraticModel> models, const SplitOrdering& ordering);

  std::size_t size() const { return models_.size(); }
  const SplitOrdering& ordering() const { return ordering_; }
  /// The number of groups (distinct working frames).
  std::size_t groups() const { return groups_.size(); }

 private:
  friend class EnsembleStepper;
  friend class phase::EnsembleTangentStepper;
  struct Group {
    SplitFrame frame;                 // the group's axes, signs and gyrostat_ref
    std::vector<std::size_t> points;  // by position in the ensemble
    std::size_t padded = 0;           // points, padded to a multiple of every kernel's block
    std::vector<double> constants;    // per lane, padded: constant c of lane j at c padded + j
  };
  SplitOrdering ordering_;
  std::vector<QuadraticModel> models_;
  std::vector<Group> groups_;
};

/// Advances an EnsembleState by a composition table (any table whose ordering splits the free body
/// into axes or spin rotations, or the exact free-body flow, which is taken lane by lane through
/// the scalar flow). Holds a workspace: one stepper per thread.
class EnsembleStepper {
 public:
  /// The table's default ordering (default_ordering), as SplittingStepper(table).
  explicit EnsembleStepper(const CompositionTable& table, SimdPath path = best_simd_path());
  /// Throws InputError if the path is not available or the ordering does not fit the table.
  EnsembleStepper(const CompositionTable& table, SplitOrdering ordering,
                  SimdPath path = best_simd_path());

  int order() const { return order_; }
  SimdPath path() const { return path_; }
  const SplitOrdering& ordering() const { return ordering_; }

  /// `steps` steps of size h of every point of x (x's points are independent; the model is
  /// shared).
  void advance(const QuadraticModel& model, EnsembleState& x, double h, std::int64_t steps);
  /// The same with a model per point (models.size() == x.size() and the stepper's ordering;
  /// InputError otherwise): point i of x is advanced on model i, bit-identical to
  /// SplittingStepper::step on that model alone.
  void advance(const EnsembleModels& models, EnsembleState& x, double h, std::int64_t steps);

 private:
  int order_;
  SplitOrdering ordering_;
  SimdPath path_;
  std::vector<double> a_, b_;      // the step's coefficients (splitting_coefficients)
  std::vector<double> workspace_;  // six padded arrays in the working frame
};

}  // namespace newtop
