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

/// Writes j indented by 2, one object per run, with −0 written as 0 (nlohmann-json writes −0.0;
/// the sign of a zero is never information in newtop's results).
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
