#include "newtop/analysis/analytic.hpp"

#include "newtop/analysis/brun_level.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop {

std::string to_string(AnalyticKind k) {
  switch (k) {
    case AnalyticKind::euler_poinsot:
      return "euler_poinsot";
    case AnalyticKind::pendulum:
      return "pendulum";
    case AnalyticKind::lagrange:
      return "lagrange";
    case AnalyticKind::brun:
      return "brun";
    case AnalyticKind::none:
      return "none";
  }
  return "none";
}

AnalyticDetection detect_analytic_case(const QuadraticModel& model, const State& x0) {
  if (euler_poinsot_holds(model)) {
    return {AnalyticKind::euler_poinsot, "free body: lambda = 0, M g r0 = 0, k = 0", true};
  }
  std::string why_not_plane;
  if (pendulum_holds(model, x0, &why_not_plane)) {
    return {AnalyticKind::pendulum, "plane motion: z0 = 0, k1 = k2 = 0, p = q = gamma3 = 0", true};
  }
  if (lagrange_case_holds(model)) {
    return {AnalyticKind::lagrange, "Lagrange-like case: A = B, x0 = y0 = 0, k1 = k2 = 0", true};
  }
  if (brun_holds(model)) {
    if (brun_level_solvable(model, x0)) {
      return {AnalyticKind::brun,
              "Brun's case (r0 = 0, k = 0) on the level f = m.gamma = 0: sphero-conic "
              "separation (Weber, Kharlamova), genus-2 Abel-Jacobi inversion",
              true};
    }
    try {
      brun_level(model, x0);
    } catch (const InputError& e) {
      return {AnalyticKind::brun,
              std::string("Brun's case (r0 = 0, k = 0), unsolved: ") + e.what()};
    }
    return {AnalyticKind::brun,
            "Brun's case (r0 = 0, k = 0) on a level f != 0 (f = m.gamma): the motion is linear on "
            "the Prym variety of the spectral curve; the state at time t by inverting the "
            "Abel-Prym map (t reduced modulo the torus lattice)",
            true};
  }
  return {AnalyticKind::none,
          "no integrable case: not a free body (lambda or M g r0 nonzero), not a plane motion (" +
              why_not_plane +
              "), not Lagrange (needs A = B, x0 = y0 = 0), not Brun (needs "
              "M g r0 = 0 and k = 0)"};
}

AnalyticSolution analytic_solution(const QuadraticModel& model, const State& x0,
                                   AnalyticKind kind) {
  switch (kind) {
    case AnalyticKind::euler_poinsot:
      return euler_poinsot(model.body, x0);
    case AnalyticKind::pendulum:
      return pendulum(model, x0);
    case AnalyticKind::lagrange:
      return lagrange_case(model, x0);
    case AnalyticKind::brun:
      if (brun_level_solvable(model, x0)) return brun_case(model, x0);
      return brun_prym_solution(model, x0);
    case AnalyticKind::none:
      break;
  }
  throw InputError("case: no analytic solution is implemented for case " + to_string(kind));
}

State analytic_state(const AnalyticSolution& s, double t) {
  struct Visitor {
    double t;
    State operator()(const EulerPoinsot& e) const { return free_body_state(e, t); }
    State operator()(const Pendulum& p) const { return pendulum_state(p, t); }
    State operator()(const LagrangeCase& l) const { return lagrange_state(l, t); }
    State operator()(const BrunCase& b) const { return brun_state(b, t); }
    State operator()(const BrunPrymSolution& b) const { return brun_prym_state_at(b, t).state; }
  };
  return std::visit(Visitor{t}, s);
}

}  // namespace newtop
