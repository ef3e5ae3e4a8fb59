#pragma once
// Reports shared by the subcommands: JSON objects and human summaries.

#include <optional>
#include <ostream>
#include <string>

#include "newtop/integrate/run.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"
#include "newtop/model/integrals.hpp"

namespace newtop::app {

/// One line for stderr: the Casimirs drifted beyond CasimirDrift::kThreshold.
std::string casimir_warning(const CasimirDrift& c);

struct SimulationReport {
  const io::Scenario& scenario;
  const MethodSettings& method;
  const Outcome& outcome;
  IntegralValues initial, final_values, max_drift;
  std::optional<std::string> csv_path;
  CasimirDrift casimir{};
};

io::Json simulation_json(const SimulationReport& r);
void print_simulation_summary(std::ostream& os, const SimulationReport& r);

/// The units of the numbers a report gives. newtop is unit-free: by default they are "those of the
/// scenario (newtop is unit-free)". Every JSON object print_json writes carries them as "units"
/// (unless the command set its own "units"), and every human summary ends with the line
/// "units: " + units() (printed by run_newtop after a command that wrote a summary). A command
/// that knows more (an orbit scenario's μ and R) says so with set_units before it reports.
const std::string& units();
void set_units(std::string text);
/// The default: "those of the scenario (newtop is unit-free)".
inline constexpr const char* kUnitFree = "those of the scenario (newtop is unit-free)";
/// Writes the line "units: " + units() now, where a summary wants it before the end (a table
/// follows); run_newtop then does not repeat it.
void print_units_line(std::ostream& os);
/// Whether print_units_line has written the line in this run (set_units resets it).
bool units_line_printed();

/// Writes j indented by 2, one object per run, with −0 written as 0 (nlohmann-json writes −0.0;
/// the sign of a zero is never information in newtop's results), and "units" (units()) added to
/// an object that has none.
void print_json(std::ostream& os, io::Json j);

/// j with every −0 replaced by 0 (for summaries that print parts of a JSON object).
io::Json without_negative_zeros(io::Json j);

/// Body (principal axes) and, for the quadratic field, g and lambda, as the program understood
/// them.
io::Json model_json(const Model& m);
/// The field of the run: {"kind": "quadratic", "g", "lambda"} or {"kind": "exact" | "multipole",
/// "mu", "R"[, "order"]}, with "mass_model" (its kind) where the body derives from one.
io::Json field_json(const Model& m);
/// One line naming the field: "g = …   lambda = …" or "exact (mu = …, R = …, mass model: …)".
std::string field_line(const Model& m);
/// The body and a line "field     …" (field_line).
void print_model(std::ostream& os, const Model& m);
/// An analysis of the quadratic model only, asked of a model in another field: InputError naming
/// the field (exit 2).
void require_quadratic(const Model& m, const std::string& source, const std::string& what);

}  // namespace newtop::app
