#pragma once
// Reports shared by the subcommands: JSON objects and human summaries.

#include <optional>
#include <ostream>
#include <string>

#include "newtop/integrate/run.hpp"
#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/io/scenario.hpp"

namespace newtop::app {

/// The drift of the Casimirs over a run, relative: max |γ·γ − γ0·γ0| / γ0·γ0 and
/// max |m·γ − m0·γ0| / max |m|. It bounds the state's relative error from below (δ(γ·γ) ≈ 2γ·δγ),
/// so beyond kThreshold = 1e-6 the state is certainly wrong in its sixth digit, and the run is
/// flagged. A splitting method keeps both at round-off (~1e-13 over 1e6 steps). An adaptive method
/// at tolerance τ drifts linearly in time, by 0.1–4 τ per unit of time on the examples (brun,
/// lagrange_like, heavy_top, coulomb at τ = 1e-4 … 1e-12 over T = 100 and 1e4): the warning fires
/// where τ·T approaches 1e-6 (τ = 1e-8 over 1e4) and never at the default 1e-12 before T ~ 1e6.
struct CasimirCheck {
  static constexpr double kThreshold = 1e-6;
  double geometric = 0.0;
  double area = 0.0;
  bool exceeded() const { return !(geometric <= kThreshold && area <= kThreshold); }
  /// One line for stderr.
  std::string warning() const;
};

struct SimulationReport {
  const io::Scenario& scenario;
  const MethodSettings& method;
  const Outcome& outcome;
  IntegralValues initial, final_values, max_drift;
  std::optional<std::string> csv_path;
  CasimirCheck casimir{};
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
