#pragma once
// Internal: the [mass_model] section of a scenario file.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "newtop/exact/mass_models.hpp"
#include "newtop/model/body.hpp"
#include "toml_reader.hpp"

namespace newtop::io {

/// Largest mesh or point-mass file a scenario may name (a mesh of some millions of faces).
inline constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{256} << 20;

/// Every key [mass_model] can hold.
const std::vector<std::string>& mass_model_keys();

/// A mass model and the key of [mass_model] that defines its geometry (points, file, semi_axes
/// or dimensions), named when a quantity derived from it is out of range.
struct MassModelSection {
  std::shared_ptr<const MassModel> model;
  std::string key;
  std::vector<std::string> files;  ///< the files read (resolved paths), none for inline models
};

/// Reads [mass_model]: kind = "points" (points = [[m, x, y, z], …] or file = "points.csv"),
/// "polyhedron" (file, density or mass, scale, reorient), "ellipsoid" (semi_axes, density or mass,
/// center) or "box" (dimensions, density or mass, center). Without kind, a key that belongs to one
/// model only (points, scale, reorient, semi_axes, dimensions) says which it is. A file is taken
/// relative to the scenario file's folder `base` and must be a regular file of at most
/// kMaxModelFileBytes (a TetGen pair: both files) before it is read.
MassModelSection read_mass_model(TableReader& r, const std::string& base);

/// Compares a body given in [body] with the one of the mass model (principal moments, mass, centre
/// of mass, in the user's frame, to relative kAgreement); throws InputError listing the
/// differences.
void check_agreement(TableReader& body_section, const Body& from_file, const Body& from_model);

}  // namespace newtop::io
