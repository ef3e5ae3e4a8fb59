#pragma once
// integrate_ensemble() on orbit models (orbit_ensemble.cpp), called by ensemble.cpp's
// integrate_ensemble when it is given OrbitModels.

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>

#include "orbit_model.hpp"

namespace newtop::python {

/// Whether the argument is an OrbitModel or a sequence whose first item is one.
bool is_orbit_models(const pybind11::object& models);

/// The end of each satellite's run through the orbit's Taylor ensemble: a dict of t (N; and nu on
/// an ellipse), m, omega, gamma, normal (N x 3), outcome, steps, order. `t_eval`: whether times
/// were asked for (refused: the end of each run only).
pybind11::dict orbit_integrate_ensemble(const pybind11::object& model_or_models,
                                        const pybind11::object& states, double t_end, double tol,
                                        double t0, std::optional<std::int64_t> max_steps,
                                        bool t_eval);

}  // namespace newtop::python
