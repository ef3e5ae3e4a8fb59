#pragma once
/// \file
/// The Euler–Poinsot case: the free rigid body (λ = 0, M g r0 = 0, k = 0). Its exact motion
/// (Jacobi elliptic functions for m(t), Euler angles about the fixed angular momentum for γ(t))
/// lives in newtop/integrate/free_body_flow.hpp, where the splitting steppers use it as a sub-flow.

#include "newtop/integrate/free_body_flow.hpp"

namespace newtop {

/// True when the model is a free body: no torque (λ = 0 and M g r0 = 0) and no gyrostat (k = 0).
bool euler_poinsot_holds(const QuadraticModel& model);

}  // namespace newtop
