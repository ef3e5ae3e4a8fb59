#pragma once
/// \file
/// Which integrable case applies to a model and initial state, and its closed-form or quadrature
/// solution behind one interface (docs/model.md §5, §6, §10; Brun's case on every level).

#include <string>
#include <variant>

#include "newtop/analysis/brun_case.hpp"
#include "newtop/analysis/brun_prym_inversion.hpp"
#include "newtop/analysis/euler_poinsot.hpp"
#include "newtop/analysis/lagrange_case.hpp"
#include "newtop/analysis/pendulum.hpp"

namespace newtop {

enum class AnalyticKind { euler_poinsot, pendulum, lagrange, brun, none };
std::string to_string(AnalyticKind k);

struct AnalyticDetection {
  AnalyticKind kind = AnalyticKind::none;
  std::string reason;   ///< why this case applies, or why none does
  bool solved = false;  ///< analytic_solution is available
};

/// The first case that applies, in the order Euler–Poinsot, plane pendulum, Lagrange, Brun.
AnalyticDetection detect_analytic_case(const QuadraticModel& model, const State& x0);

using AnalyticSolution =
    std::variant<EulerPoinsot, Pendulum, LagrangeCase, BrunCase, BrunPrymSolution>;

/// The solution of a solved case (euler_poinsot, pendulum, lagrange, brun: BrunCase on f = 0,
/// BrunPrymSolution on f ≠ 0); throws
/// InputError for none or an unsolved level.
AnalyticSolution analytic_solution(const QuadraticModel& model, const State& x0, AnalyticKind kind);

/// The state at time t.
State analytic_state(const AnalyticSolution& s, double t);

}  // namespace newtop
