#pragma once
// Internal: the [mass_model] section of a scenario file.

#include <memory>
#include <string>

#include "newtop/exact/mass_models.hpp"
#include "newtop/model/body.hpp"
#include "toml_reader.hpp"

namespace newtop::io {

/// Reads [mass_model]: kind = "points" (points = [[m, x, y, z], …] or file = "points.csv"),
/// "polyhedron" (file, density or mass, scale, reorient), "ellipsoid" (semi_axes, density or mass,
/// center) or "box" (dimensions, density or mass, center). Relative file names are taken from the
/// scenario file's folder `base`.
std::shared_ptr<const MassModel> read_mass_model(TableReader& r, const std::string& base);

/// Compares a body given in [body] with the one of the mass model (principal moments, mass, centre
/// of mass, in the user's frame, to relative kAgreement); throws InputError listing the
/// differences.
void check_agreement(TableReader& body_section, const Body& from_file, const Body& from_model);

}  // namespace newtop::io
