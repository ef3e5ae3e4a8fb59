#pragma once
/// \file
/// Umbrella header: every module of the library — model, exact fields, integration (the compiled
/// entry points and the steppers of one's own: splitting, Taylor), analysis, phase space (sections,
/// chaos), orbit — without Boost.Odeint or Boost.Math. The templates that run the Runge–Kutta
/// methods on a BasicModel<F> (newtop/integrate/methods.hpp, runge_kutta.hpp, dop853.hpp,
/// newtop/phase/section_run.hpp, chaos_run.hpp) are included on their own by those who build
/// their own runs; io/ and sweep/ come with newtop::io (find_package(newtop COMPONENTS io)).

#include "newtop/version.hpp"

#include "newtop/core/types.hpp"
#include "newtop/model/attitude.hpp"
#include "newtop/model/body.hpp"
#include "newtop/model/field.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/model/model.hpp"
#include "newtop/model/state_checks.hpp"

#include "newtop/exact/exact_field.hpp"
#include "newtop/exact/mass_models.hpp"
#include "newtop/exact/multipole.hpp"
#include "newtop/exact/polyhedron.hpp"

#include "newtop/integrate/composition_tables.hpp"
#include "newtop/integrate/concepts.hpp"
#include "newtop/integrate/driver.hpp"
#include "newtop/integrate/free_body_flow.hpp"
#include "newtop/integrate/method_settings.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/integrate/splitting.hpp"
#include "newtop/integrate/taylor.hpp"

#include "newtop/analysis/analytic.hpp"
#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/euler_poinsot.hpp"
#include "newtop/analysis/find_integrals.hpp"
#include "newtop/analysis/lagrange_attitude.hpp"
#include "newtop/analysis/lagrange_case.hpp"
#include "newtop/analysis/pendulum.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/analysis/stability.hpp"
#include "newtop/analysis/stability_spin.hpp"

#include "newtop/phase/chaos.hpp"
#include "newtop/phase/section.hpp"
#include "newtop/phase/surface.hpp"

#include "newtop/orbit/debra_delp.hpp"
#include "newtop/orbit/libration.hpp"
#include "newtop/orbit/orbit.hpp"
#include "newtop/orbit/orbit_equilibria.hpp"
#include "newtop/orbit/orbit_integrate.hpp"
#include "newtop/orbit/orbit_model.hpp"
#include "newtop/orbit/orbit_section.hpp"
#include "newtop/orbit/orbit_stability.hpp"
#include "newtop/orbit/spin_orbit.hpp"
