#pragma once
// The parts of the module newtop._newtop, each in its own file.

#include <pybind11/pybind11.h>

namespace newtop::python {

/// Body, QuadraticField, Model, State, Scenario and the model's functions (model.cpp).
void bind_model(pybind11::module_& m);

/// MassModel and the exact and multipole models on it (mass_models.cpp); after bind_model.
void bind_mass_models(pybind11::module_& m);

/// integrate(): a run into numpy arrays (trajectory.cpp).
void bind_trajectory(pybind11::module_& m);

/// _run_command_line(): the command line in-process, for the per-subcommand functions of the
/// package (command_line.cpp).
void bind_command_line(pybind11::module_& m);

/// resonance_family, rotation_family, equilibrium_family (continuation.cpp).
void bind_continuation(pybind11::module_& m);

}  // namespace newtop::python
