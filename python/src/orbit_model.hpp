#pragma once
// The orbit model as one Python class (docs/python.md, "Satellites on an orbit"): a body on a
// circular or an elliptic Kepler orbit (newtop/orbit/orbit_model.hpp), with the μ and radius it was
// built from when given.

#include <pybind11/pybind11.h>

#include <optional>
#include <variant>

#include "newtop/io/orbit_scenario.hpp"
#include "newtop/orbit/orbit_model.hpp"

namespace newtop::python {

struct OrbitModel {
  std::variant<CircularOrbitModel, EllipticOrbitModel> model;
  std::optional<double> mu, radius;  ///< radius: R (circular) or a (elliptic)

  bool circular() const { return std::holds_alternative<CircularOrbitModel>(model); }
  const Body& body() const {
    return std::visit([](const auto& x) -> const Body& { return x.body(); }, model);
  }
  const CircularOrbitModel& circular_model() const;  ///< InputError naming the kind otherwise

  /// The scenario's model (its body and orbit).
  static OrbitModel of(const io::OrbitScenario& sc);
};

/// OrbitModel, OrbitState, OrbitScenario; load_scenario and parse_scenario reading orbit files too
/// (orbit.cpp); after bind_model.
void bind_orbit(pybind11::module_& m);

/// integrate() on an OrbitModel or an OrbitScenario (orbit_run.cpp); after bind_trajectory.
void bind_orbit_run(pybind11::module_& m);

/// The relative equilibria, their stability and the DeBra–Delp diagram (orbit_analyses.cpp).
void bind_orbit_analyses(pybind11::module_& m);

/// section and chaos on an OrbitScenario (orbit_phase.cpp).
void bind_orbit_phase(pybind11::module_& m);

/// The libration report (orbit_libration.cpp).
void bind_orbit_libration(pybind11::module_& m);

}  // namespace newtop::python
