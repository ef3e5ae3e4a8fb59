// The analyses of the library on Python objects (docs/python.md, "The analyses"): equilibria,
// stability, chaos, section and analytic take a Model and a State (or arrays) and return typed
// results whose numeric fields are numpy arrays, the numbers of the command line bit for bit.

#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "analysis_results.hpp"
#include "bindings.hpp"
#include "newtop/analysis/analytic_comparison.hpp"
#include "newtop/analysis/brun_prym_inversion.hpp"
#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability_report.hpp"
#include "newtop/model/state_checks.hpp"
#include "newtop/phase/chaos.hpp"
#include "newtop/phase/section.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// Rows of k doubles as an (N, k) array (N × 0 when empty).
template <class Row>
py::array_t<double> table(const std::vector<Row>& rows, py::ssize_t k,
                          const std::function<void(const Row&, double*)>& fill) {
  py::array_t<double> a({static_cast<py::ssize_t>(rows.size()), k});
  double* p = a.mutable_data();
  for (const Row& r : rows) {
    fill(r, p);
    p += k;
  }
  return a;
}

template <class Row>
py::array_t<double> vectors(const std::vector<Row>& rows,
                            const std::function<Vec3(const Row&)>& f) {
  return table<Row>(rows, 3, [&](const Row& r, double* p) {
    const Vec3 v = f(r);
    p[0] = v[0], p[1] = v[1], p[2] = v[2];
  });
}

template <class Row>
py::array_t<double> scalars(const std::vector<Row>& rows,
                            const std::function<double(const Row&)>& f) {
  py::array_t<double> a(static_cast<py::ssize_t>(rows.size()));
  double* p = a.mutable_data();
  for (const Row& r : rows) *p++ = f(r);
  return a;
}

// ---- equilibria ---------------------------------------------------------------------------

void bind_equilibria(py::module_& m) {
  using E = Equilibrium;
  py::class_<EquilibriumSet>(m, "Equilibria",
                             "Every equilibrium at rest (docs/model.md §7), sorted by kappa: the "
                             "result of newtop.equilibria(model), as `newtop equilibria --json`.")
      .def_property_readonly("count", [](const EquilibriumSet& s) { return s.equilibria.size(); })
      .def_property_readonly(
          "gamma",
          [](const EquilibriumSet& s) {
            return vectors<E>(s.equilibria, [](const E& e) { return e.gamma; });
          },
          "(K, 3): gamma of each equilibrium")
      .def_property_readonly(
          "kappa",
          [](const EquilibriumSet& s) {
            return scalars<E>(s.equilibria, [](const E& e) { return e.kappa; });
          },
          "(K,): kappa = gamma.dV/dgamma")
      .def_property_readonly(
          "potential",
          [](const EquilibriumSet& s) {
            return scalars<E>(s.equilibria, [](const E& e) { return e.potential; });
          },
          "(K,): V(gamma)")
      .def_property_readonly(
          "hessian_eigenvalues",
          [](const EquilibriumSet& s) {
            return table<E>(s.equilibria, 2, [](const E& e, double* p) {
              p[0] = e.hessian[0], p[1] = e.hessian[1];
            });
          },
          "(K, 2): eigenvalues of the Hessian of V on the sphere, ascending")
      .def_property_readonly(
          "staude_residual",
          [](const EquilibriumSet& s) {
            return scalars<E>(s.equilibria, [](const E& e) { return e.staude_residual; });
          },
          "(K,): gamma.(I gamma x r0) (the quadratic field; nan otherwise)")
      .def_property_readonly(
          "type",
          [](const EquilibriumSet& s) {
            std::vector<std::string> t;
            for (const E& e : s.equilibria) t.emplace_back(to_string(e.type));
            return t;
          },
          "'minimum', 'saddle', 'maximum' or 'degenerate' for each")
      .def_readonly("every_orientation", &EquilibriumSet::every_orientation)
      .def_property_readonly("circles",
                             [](const EquilibriumSet& s) {
                               py::list l;
                               for (const auto& c : s.circles) {
                                 py::dict d;
                                 d["axis"] = std::string(1, "xyz"[c.axis]);
                                 d["gamma_axis"] = c.gamma_axis;
                                 d["kappa"] = c.kappa;
                                 d["potential"] = c.potential;
                                 l.append(d);
                               }
                               return l;
                             })
      .def_readonly("minima", &EquilibriumSet::minima)
      .def_readonly("saddles", &EquilibriumSet::saddles)
      .def_readonly("maxima", &EquilibriumSet::maxima)
      .def_readonly("degenerate", &EquilibriumSet::degenerate)
      .def_property_readonly("euler_characteristic", &EquilibriumSet::euler_characteristic)
      .def_property_readonly("count_rule_holds", &EquilibriumSet::count_rule_holds)
      .def("__len__", [](const EquilibriumSet& s) { return s.equilibria.size(); })
      .def("__repr__", [](const EquilibriumSet& s) {
        return "Equilibria(count=" + std::to_string(s.equilibria.size()) +
               ", minima=" + std::to_string(s.minima) + ", saddles=" + std::to_string(s.saddles) +
               ", maxima=" + std::to_string(s.maxima) + ")";
      });
  m.def(
      "_equilibria", [](const Model& model) { return find_equilibria(model); }, py::arg("model"),
      py::call_guard<py::gil_scoped_release>());
}

// ---- stability ----------------------------------------------------------------------------

int axis_index(const py::object& axis) {
  if (py::isinstance<py::str>(axis)) {
    const std::string s = axis.cast<std::string>();
    if (s == "x") return 0;
    if (s == "y") return 1;
    if (s == "z") return 2;
    throw InputError("axis: expected x, y or z, found '" + s + "'");
  }
  return axis.cast<int>();
}

void bind_stability(py::module_& m) {
  using R = StabilityReport;
  py::class_<R>(m, "StabilityReport",
                "Linear and energy-Casimir stability of one fixed point (docs/model.md §7-§9): "
                "the result of newtop.stability(model, ...), as `newtop stability --json`.")
      .def_readonly("state", &R::state)
      .def_property_readonly(
          "eigenvalues",
          [](const R& r) {
            py::array_t<std::complex<double>> a(
                static_cast<py::ssize_t>(r.spectrum.eigenvalues.size()));
            std::copy(r.spectrum.eigenvalues.begin(), r.spectrum.eigenvalues.end(),
                      a.mutable_data());
            return a;
          },
          "(4,) complex: the eigenvalues on the symplectic leaf, sorted")
      .def_property_readonly("max_real_part", [](const R& r) { return r.spectrum.max_real_part; })
      .def_property_readonly("linearly_stable",
                             [](const R& r) { return r.spectrum.linearly_stable; })
      .def_property_readonly(
          "lyapunov_stable", [](const R& r) { return r.spectrum.lyapunov_stable; },
          "True (energy-Casimir proves it), False (unstable), None")
      .def_readonly("threshold_omega_formula", &R::threshold_formula)
      .def_readonly("threshold_omega_numeric", &R::threshold_numeric)
      .def_readonly("formula_note", &R::formula_note,
                    "why Beletsky's formula does not apply (empty when it does)")
      .def_property_readonly("axis",
                             [](const R& r) -> std::optional<std::string> {
                               if (!r.axis) return std::nullopt;
                               return std::string(1, "xyz"[*r.axis]);
                             })
      .def_property_readonly("gamma", [](const R& r) { return r.state.gamma; })
      .def_readonly("residual", &R::residual)
      .def_property_readonly("polish", [](const R& r) {
        py::dict d;
        d["residual_given"] = r.polish.residual_given;
        d["correction"] = r.polish.correction;
        d["iterations"] = r.polish.iterations;
        return d;
      });
  m.def(
      "_stability",
      [](const Model& model, std::optional<int> equilibrium, std::optional<State> state,
         const py::object& axis, std::optional<double> omega) {
        const int given = (equilibrium ? 1 : 0) + (state ? 1 : 0) + (axis.is_none() ? 0 : 1);
        if (given != 1) {
          throw InputError("equilibrium, state, axis: expected exactly one of them, found " +
                           std::to_string(given));
        }
        if (omega && axis.is_none()) {
          throw InputError("omega: needs axis='x'|'y'|'z' to say which axis spins");
        }
        if (!axis.is_none()) {
          const int k = axis_index(axis);
          const py::gil_scoped_release unlocked;
          return stability_of_axis(model, k, omega.value_or(0.0));
        }
        const py::gil_scoped_release unlocked;
        if (equilibrium) return stability_of_equilibrium(model, *equilibrium);
        return stability_of_state(model, *state);
      },
      py::arg("model"), py::kw_only(), py::arg("equilibrium") = py::none(),
      py::arg("state") = py::none(), py::arg("axis") = py::none(), py::arg("omega") = py::none());
}

// ---- chaos --------------------------------------------------------------------------------

void bind_chaos(py::module_& m) {
  using S = phase::ChaosSample;
  py::class_<ChaosOut>(m, "ChaosResult",
                       "Chaos indicators from the tangent map (docs/chaos.md): the result of "
                       "newtop.chaos(model, state, t_end), as `newtop chaos --json`.")
      .def_property_readonly("lyapunov_max",
                             [](const ChaosOut& c) { return c.result.indicators.lyapunov_max; })
      .def_property_readonly("megno", [](const ChaosOut& c) { return c.result.indicators.megno; })
      .def_property_readonly("megno_y",
                             [](const ChaosOut& c) { return c.result.indicators.megno_y; })
      .def_property_readonly("fli", [](const ChaosOut& c) { return c.result.indicators.fli; })
      .def_property_readonly(
          "spectrum",
          [](const ChaosOut& c) -> std::optional<py::array_t<double>> {
            const auto& s = c.result.indicators.spectrum;
            if (!s) return std::nullopt;
            py::array_t<double> a(6);
            std::copy(s->begin(), s->end(), a.mutable_data());
            return a;
          },
          "(6,) in Benettin's column order, or None without spectrum=True")
      .def_property_readonly("t_end", [](const ChaosOut& c) { return c.result.outcome.t; })
      .def_property_readonly(
          "outcome",
          [](const ChaosOut& c) { return std::string(to_string(c.result.outcome.status)); })
      .def_property_readonly("steps", [](const ChaosOut& c) { return c.result.outcome.steps; })
      .def_readonly("method", &ChaosOut::method)
      .def_property_readonly(
          "history",
          [](const ChaosOut& c) -> py::object {
            if (c.history.empty()) return py::none();
            py::dict d;
            d["t"] = scalars<S>(c.history, [](const S& s) { return s.t; });
            d["lyapunov_max"] = scalars<S>(c.history, [](const S& s) { return s.lyapunov_max; });
            d["megno_y"] = scalars<S>(c.history, [](const S& s) { return s.megno_y; });
            d["megno"] = scalars<S>(c.history, [](const S& s) { return s.megno; });
            d["fli"] = scalars<S>(c.history, [](const S& s) { return s.fli; });
            if (c.history.front().spectrum) {
              d["spectrum"] = table<S>(c.history, 6, [](const S& s, double* p) {
                std::copy(s.spectrum->begin(), s.spectrum->end(), p);
              });
            }
            return d;
          },
          "with history=True: the indicators after every step (arrays), else None");
  m.def(
      "_chaos",
      [](const Model& model, const State& state, double t_end, double t0,
         const std::optional<std::string>& method, std::optional<double> step,
         std::optional<double> tol, bool spectrum, std::optional<std::int64_t> max_steps,
         bool history) {
        IntegrateOptions o;
        if (max_steps) o.max_steps = *max_steps;
        return run_chaos(method_settings(model, method, step, tol), model, state, t0, t_end, o,
                         spectrum, history);
      },
      py::arg("model"), py::arg("state"), py::arg("t_end"), py::kw_only(), py::arg("t0") = 0.0,
      py::arg("method") = py::none(), py::arg("step") = py::none(), py::arg("tol") = py::none(),
      py::arg("spectrum") = false, py::arg("max_steps") = py::none(), py::arg("history") = false);
}

// ---- section ------------------------------------------------------------------------------

void bind_section(py::module_& m) {
  using C = phase::Crossing;
  py::class_<SectionOut>(m, "Section",
                         "The crossings of a Poincare section (docs/section.md), in order of "
                         "orbit and time: the result of newtop.section(model, states, t_end).")
      .def_readonly("surface", &SectionOut::surface)
      .def_property_readonly("count", [](const SectionOut& s) { return s.crossings.size(); })
      .def_property_readonly("orbit",
                             [](const SectionOut& s) {
                               py::array_t<int> a(static_cast<py::ssize_t>(s.crossings.size()));
                               int* p = a.mutable_data();
                               for (const C& c : s.crossings) *p++ = c.orbit;
                               return a;
                             })
      .def_property_readonly("t",
                             [](const SectionOut& s) {
                               return scalars<C>(s.crossings, [](const C& c) { return c.t; });
                             })
      .def_property_readonly("m",
                             [](const SectionOut& s) {
                               return vectors<C>(s.crossings, [](const C& c) { return c.x.m; });
                             })
      .def_property_readonly("gamma",
                             [](const SectionOut& s) {
                               return vectors<C>(s.crossings, [](const C& c) { return c.x.gamma; });
                             })
      .def_property_readonly("omega",
                             [](const SectionOut& s) {
                               return vectors<C>(s.crossings,
                                                 [&](const C& c) { return omega(s.body, c.x); });
                             })
      .def_property_readonly("outcomes",
                             [](const SectionOut& s) {
                               std::vector<std::string> o;
                               for (Status x : s.outcomes) o.emplace_back(to_string(x));
                               return o;
                             })
      .def_readonly("stopped_by", &SectionOut::stopped_by,
                    "crossings (every orbit), cap (a run without t_end hit max_steps) or t_end")
      .def_readonly("max_surface_residual", &SectionOut::max_residual);
  m.def(
      "_section",
      [](const Model& model, const std::vector<State>& states, double t_end,
         const std::string& surface, std::int64_t crossings, const std::string& direction,
         double t0, const std::optional<std::string>& method, std::optional<double> step,
         std::optional<double> tol, std::optional<std::int64_t> max_steps) {
        const phase::Surface sf = phase::parse_surface(surface, "surface");
        phase::require_body_surface(sf, "surface");
        const phase::Direction dir = phase::parse_direction(direction, "direction");
        if (crossings < 1) {
          throw InputError("crossings: expected an integer >= 1, found " +
                           std::to_string(crossings));
        }
        phase::SectionRequest q;
        q.method = method_settings(model, method, step, tol);
        check_time_span(t0, t_end);
        q.surface = sf;
        q.direction = dir;
        q.max_crossings = crossings;
        q.t0 = t0;
        q.t_end = t_end;
        if (max_steps) q.options.max_steps = *max_steps;
        return run_sections(model, states, q);
      },
      py::arg("model"), py::arg("states"), py::arg("t_end"), py::kw_only(),
      py::arg("surface") = "gamma3 = 0", py::arg("crossings") = 1000, py::arg("direction") = "up",
      py::arg("t0") = 0.0, py::arg("method") = py::none(), py::arg("step") = py::none(),
      py::arg("tol") = py::none(), py::arg("max_steps") = py::none());
}

// ---- analytic -----------------------------------------------------------------------------

struct AnalyticOut {
  AnalyticDetection detection;
  std::optional<double> period;
  AnalyticComparison comparison;
  Body body;
};

void bind_analytic(py::module_& m) {
  using A = AnalyticOut;
  py::class_<A>(m, "AnalyticResult",
                "An integrable case's closed form at the sample times beside rkf78 at tol 1e-13 "
                "(docs/integrable.md): the result of newtop.analytic(model, state, times).")
      .def_property_readonly("case", [](const A& a) { return to_string(a.detection.kind); })
      .def_property_readonly("reason", [](const A& a) { return a.detection.reason; })
      .def_readonly("period", &A::period, "the period of the solution, or None")
      .def_property_readonly("t",
                             [](const A& a) {
                               return py::array_t<double>(
                                   static_cast<py::ssize_t>(a.comparison.times.size()),
                                   a.comparison.times.data());
                             })
      .def_property_readonly(
          "omega",
          [](const A& a) {
            return vectors<State>(a.comparison.analytic,
                                  [&](const State& s) { return omega(a.body, s); });
          },
          "(N, 3): the closed form")
      .def_property_readonly("gamma",
                             [](const A& a) {
                               return vectors<State>(a.comparison.analytic,
                                                     [](const State& s) { return s.gamma; });
                             })
      .def_property_readonly("m",
                             [](const A& a) {
                               return vectors<State>(a.comparison.analytic,
                                                     [](const State& s) { return s.m; });
                             })
      .def_property_readonly(
          "numeric_omega",
          [](const A& a) {
            const Vec3 nan = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
            return vectors<std::optional<State>>(
                a.comparison.numeric,
                [&](const std::optional<State>& s) { return s ? omega(a.body, *s) : nan; });
          },
          "(N, 3): the reference (nan where it did not reach the time)")
      .def_property_readonly(
          "numeric_gamma",
          [](const A& a) {
            const Vec3 nan = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
            return vectors<std::optional<State>>(
                a.comparison.numeric,
                [&](const std::optional<State>& s) { return s ? s->gamma : nan; });
          })
      .def_property_readonly("max_abs_error", [](const A& a) { return a.comparison.max_abs_error; })
      .def_property_readonly("reference_outcome", [](const A& a) {
        return std::string(to_string(a.comparison.reference.status));
      });
  m.def(
      "_analytic",
      [](const Model& model, const State& state, std::vector<double> times,
         std::optional<std::int64_t> max_steps) {
        if (model.kind() != FieldKind::quadratic) {
          throw InputError(
              std::string("model: the closed forms need the quadratic field, found the ") +
              to_string(model.kind()) + " field");
        }
        validate(state);
        for (double t : times) {
          if (!(std::isfinite(t) && t >= 0)) {
            throw InputError("times: expected finite times >= 0, found " + format_number(t));
          }
        }
        std::sort(times.begin(), times.end());
        const QuadraticModel& q = model.quadratic();
        AnalyticOut out{detect_analytic_case(q, state), std::nullopt, {}, model.body()};
        if (!out.detection.solved) {
          throw InputError("state: no closed form: " + to_string(out.detection.kind) + " (" +
                           out.detection.reason + ")");
        }
        const AnalyticSolution sol = analytic_solution(q, state, out.detection.kind);
        out.period = solution_period(sol);
        IntegrateOptions o;
        if (max_steps) o.max_steps = *max_steps;
        const py::gil_scoped_release unlocked;
        out.comparison = compare_analytic(q, state, sol, times, o);
        return out;
      },
      py::arg("model"), py::arg("state"), py::arg("times"), py::kw_only(),
      py::arg("max_steps") = py::none());
  m.def(
      "brun_state_at",
      [](const Model& model, const State& state, double t) {
        if (model.kind() != FieldKind::quadratic) {
          throw InputError(std::string("model: Brun's case needs the quadratic field, found the ") +
                           to_string(model.kind()) + " field");
        }
        validate(state);
        const py::gil_scoped_release unlocked;
        return brun_state_at(model.quadratic(), state, t);
      },
      "The state at time t on Brun's level f = m.gamma != 0 of `state` (the Abel-Prym inversion, "
      "docs/integrable.md): no integration along the way.",
      py::arg("model"), py::arg("state"), py::arg("t"));
}

}  // namespace

void bind_analyses(py::module_& m) {
  bind_equilibria(m);
  bind_stability(m);
  bind_chaos(m);
  bind_section(m);
  bind_analytic(m);
  bind_scenario_analyses(m);
}

}  // namespace newtop::python
