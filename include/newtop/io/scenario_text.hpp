#pragma once
/// \file
/// The scenario file of a model and a state built in code (docs/scenario.md), as TOML text: what
/// a sweep over a model with no file runs on (newtop.sweep in Python), and what a user may save to
/// run the program on the same model.

#include <string>

#include "newtop/model/model.hpp"

namespace newtop::io {

/// [body], [mass_model], [field] and [initial] of `model` and `x0` (17 significant digits), read
/// back by parse_scenario into the same model:
/// - the quadratic field (on a body of principal moments, a full inertia tensor or a mass model):
///   [body] in its principal axes (inertia, mass, center_of_mass, gyrostat), [field] g and
///   lambda, [initial] omega and gamma in the principal axes: the dynamics of the model read back
///   are those of `model` bit for bit (the state's m = I omega + k is formed again from omega);
/// - the exact and multipole fields of point masses or an ellipsoid: [mass_model] as built,
///   [field] kind, mu, R (and order), the gyrostat and [initial] in the mass model's frame (P v
///   for the principal axes P; where P is not the identity the vectors read back agree with the
///   model's to round-off, not bit for bit).
/// Throws InputError (naming `base`) for a model that has no such text: the exact or multipole
/// field of a polyhedron (a mesh is read from its file; give the scenario file that names it).
std::string scenario_text(const Model& model, const State& x0);

}  // namespace newtop::io
