#pragma once
// The parts of the module newtop._newtop, each in its own file.

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/model/model.hpp"

namespace newtop::python {

/// Body, QuadraticField, Model, State, Scenario and the model's functions (model.cpp).
void bind_model(pybind11::module_& m);

/// MassModel and the exact and multipole models on it (mass_models.cpp); after bind_model.
void bind_mass_models(pybind11::module_& m);

/// integrate(): a run into numpy arrays (trajectory.cpp).
void bind_trajectory(pybind11::module_& m);

/// integrate_ensemble(), chaos_ensemble(): many trajectories through the Taylor ensemble
/// (ensemble.cpp).
void bind_ensemble(pybind11::module_& m);

/// equilibria, stability, chaos, section and analytic on Python objects (analyses.cpp).
void bind_analyses(pybind11::module_& m);

/// The method as the command line resolves it: a name, or the default for a step (splitting6) or
/// a tolerance (taylor on the quadratic field, dop853 on the others); one of step and tol.
MethodSettings method_settings(const Model& model, const std::optional<std::string>& name,
                               std::optional<double> step, std::optional<double> tol);

/// {"energy", "area", "geometric"[, "brun"][, "lagrange"]} of the integrals (model.cpp).
pybind11::dict integrals_dict(const IntegralValues& v);

/// _simulation_summary, _write_trajectory_csv (simulate.cpp).
void bind_simulate(pybind11::module_& m);

/// view(): the 3D page of a trajectory CSV (view.cpp).
void bind_view(pybind11::module_& m);

/// rotations and field on Python objects (fields.cpp).
void bind_fields(pybind11::module_& m);
/// _sweep: a sweep without files (sweep.cpp).
void bind_sweep(pybind11::module_& m);
/// resonance_family, rotation_family, equilibrium_family (continuation.cpp).
void bind_continuation(pybind11::module_& m);

}  // namespace newtop::python
