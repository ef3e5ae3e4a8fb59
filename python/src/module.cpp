// newtop._newtop: the library from Python (docs/python.md). Bad input raises ValueError with the
// one-line message of the command line.

#include "bindings.hpp"
#include "newtop/core/types.hpp"
#include "orbit_model.hpp"

PYBIND11_MODULE(_newtop, m) {
  m.doc() =
      "newtop: a rigid body about a fixed point in the field of a distant Newtonian centre "
      "(Euler-Poisson equations, spec sections 1-7). Vectors are numpy arrays of length 3 in the "
      "body's principal axes; units are the scenario's.";
  pybind11::register_exception<newtop::InputError>(m, "InputError", PyExc_ValueError);
  newtop::python::bind_model(m);
  newtop::python::bind_mass_models(m);
  newtop::python::bind_trajectory(m);
  newtop::python::bind_ensemble(m);
  newtop::python::bind_analyses(m);
  newtop::python::bind_fields(m);
  newtop::python::bind_sweep(m);
  newtop::python::bind_simulate(m);
  newtop::python::bind_view(m);
  newtop::python::bind_continuation(m);
  newtop::python::bind_orbit(m);
  newtop::python::bind_orbit_run(m);
  newtop::python::bind_orbit_analyses(m);
  newtop::python::bind_orbit_phase(m);
  newtop::python::bind_orbit_libration(m);
}
