#pragma once
/// \file
/// Orbit scenarios (docs/scenario.md, "Orbit scenarios"; docs/orbit.md): a body turning about its
/// centre of mass, which moves on a circular or elliptic Kepler orbit given by an [orbit]
/// section. Such a file has no [field] (the field is the orbit's).

#include <optional>
#include <string>
#include <variant>

#include "newtop/io/scenario.hpp"
#include "newtop/orbit/orbit_model.hpp"

namespace newtop::io {

/// A parsed and validated orbit scenario; vectors in the body's principal axes.
struct OrbitScenario {
  std::string source;
  Body body;
  std::variant<CircularOrbit, EllipticOrbit> orbit;
  OrbitState initial;
  IntegrateSection integrate;  ///< t0, t_end in time on either orbit
  OutputSection output;
  /// μ and the radius (circular) or semi-major axis (elliptic) when the file gives them (not for
  /// `rate`): the units they imply and the unit-mix warnings (orbit.hpp).
  std::optional<double> mu, radius;

  bool circular() const { return std::holds_alternative<CircularOrbit>(orbit); }
  /// The orbit's rate at t0: ω0, or ν̇(ν0) on an ellipse.
  double rate_at_start() const;
};

/// True when the scenario text has a top-level [orbit] table (false for malformed TOML: the
/// ordinary reader then reports the error).
bool is_orbit_scenario_text(const std::string& text);

/// Reads the file and says whether it is an orbit scenario; throws InputError when it cannot be
/// read.
bool is_orbit_scenario(const std::string& path);

/// Reads and validates an orbit scenario; throws InputError with a one-line message
/// `FILE:LINE:COL: [section] key: expected …, found …`.
OrbitScenario load_orbit_scenario(const std::string& path);

OrbitScenario parse_orbit_scenario(const std::string& text, const std::string& source);

}  // namespace newtop::io
