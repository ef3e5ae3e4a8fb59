#pragma once
// Reports shared by the subcommands: JSON objects and human summaries.

#include <optional>
#include <ostream>
#include <string>

#include "newtop/integrate/methods.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::app {

struct SimulationReport {
  const io::Scenario& scenario;
  const MethodSettings& method;
  const Outcome& outcome;
  IntegralValues initial, final_values, max_drift;
  std::optional<std::string> csv_path;
};

io::Json simulation_json(const SimulationReport& r);
void print_simulation_summary(std::ostream& os, const SimulationReport& r);

/// Body and field parameters as the program understood them (principal axes).
io::Json model_json(const Model& m);
void print_model(std::ostream& os, const Model& m);

}  // namespace newtop::app
