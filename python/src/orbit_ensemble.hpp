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

/// The chaos indicators of each satellite through the orbit's Taylor ensemble's chaos runs: a
/// dict of megno, lyapunov_max, fli (N) and outcome, each the bits of newtop.chaos(model, state,
/// t_end, tol=tol, method='taylor', t0=t0).
pybind11::dict orbit_chaos_ensemble(const pybind11::object& model_or_models,
                                    const pybind11::object& states, double t_end, double tol,
                                    double t0, std::optional<std::int64_t> max_steps);

}  // namespace newtop::python
