#pragma once
// The results of chaos and section as the module holds them (analyses.cpp binds them; the
// scenario forms in scenario_analyses.cpp fill them too).

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "newtop/model/model.hpp"
#include "newtop/phase/chaos.hpp"
#include "newtop/phase/section.hpp"

namespace newtop::python {

struct ChaosOut {
  phase::ChaosResult result;
  std::string method;
  std::vector<phase::ChaosSample> history;
};

/// The chaos run of `method` from (t0, state) to t_end; with `history` every step's indicators.
ChaosOut run_chaos(const MethodSettings& method, const Model& model, const State& state, double t0,
                   double t_end, const IntegrateOptions& options, bool spectrum, bool history);

struct SectionOut {
  std::vector<phase::Crossing> crossings;
  std::vector<Status> outcomes;  ///< one per start
  double max_residual = 0.0;     ///< max |g| at the crossings
  std::string stopped_by;        ///< crossings, cap or t_end (as `newtop section --json`)
  Body body;
  std::string surface;
};

/// The section of each start in turn with the request (each orbit labelled by its index).
SectionOut run_sections(const Model& model, const std::vector<State>& starts,
                        phase::SectionRequest request);

/// _chaos_scenario and _section_scenario: the analyses on a Scenario with its [integrate]
/// settings overridden as on the command line (scenario_analyses.cpp).
void bind_scenario_analyses(pybind11::module_& m);

}  // namespace newtop::python
