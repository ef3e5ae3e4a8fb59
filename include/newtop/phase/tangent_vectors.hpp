#pragma once
/// \file
/// Tangent vectors δx = (δm, δγ) ∈ R⁶ of a state, as the columns of a matrix (tangent.hpp), and
/// which methods have a tangent map.

#include <Eigen/Core>

#include "newtop/integrate/method_settings.hpp"

namespace newtop::phase {

/// Tangent vectors as columns (at most 6, fixed storage).
using Tangent = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;

/// Throws InputError unless the settings name a method with a tangent map (validate()'s checks
/// too): a splitting method needs the axes or the spin split of the free body.
void check_tangent_method(const MethodSettings& settings);

/// Throws InputError naming `split` unless the free body is split into axis rotations or a spin
/// and rotations (the splits the tangent map is written for; not the exact flow).
void check_tangent_split(FreeBodySplit split);

/// Throws InputError naming `split` unless it is the axes split (the one the ensemble tangent
/// stepper's kernels are written for).
void check_ensemble_tangent_split(FreeBodySplit split);

}  // namespace newtop::phase
