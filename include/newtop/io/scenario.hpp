#pragma once
/// \file
/// Scenario files (TOML, docs/scenario.md): body, field, initial state, integration and output.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "newtop/integrate/method_settings.hpp"
#include "newtop/model/attitude.hpp"
#include "newtop/model/model.hpp"

namespace newtop::io {

/// [integrate] as written in the file; each entry optional so that the command line can override.
struct IntegrateSection {
  std::optional<std::string> method;
  std::optional<double> step;
  std::optional<double> tol;
  std::optional<double> t_end;
  double t0 = 0.0;
  std::optional<std::int64_t> max_steps;
  /// The split of the free body for the splitting methods: "axes", "spin" or "exact"
  /// (FreeBodySplit); the method's default ordering when absent.
  std::optional<std::string> split;
};

/// [output] as written in the file.
struct OutputSection {
  std::optional<std::string> file;
  std::int64_t every = 1;
  /// Rows at t0 + k·dt instead of every `every`-th step (finite, > 0; not with `every`).
  std::optional<double> dt;
};

/// A parsed and validated scenario. Vectors are in the body's principal axes (converted from the
/// user's frame when the body was given by a full inertia tensor).
struct Scenario {
  std::string source;  ///< file name used in messages
  /// The model of the run: its body and its field (quadratic, exact or multipole); with a
  /// [mass_model], the body is the mass model's (principal axes as for inertia_tensor).
  Model model;
  State initial;
  /// The attitude at t0 (body → inertial) of the principal axes, the frame of `initial`, when
  /// [initial] gives one (quaternion, rotation_matrix, euler_321 or euler_313, which give that of
  /// the file's frame: R = R_file P, P the principal axes in the file's frame).
  std::optional<Quaternion> attitude;
  IntegrateSection integrate;
  OutputSection output;
  /// Every file the scenario was read from: the scenario itself and a [mass_model] file (an output
  /// must never replace one of them).
  std::vector<std::string> input_files;
};

/// Reads and validates a scenario file. Throws InputError with a one-line message
/// `FILE:LINE:COL: [section] key: expected …, found …` (or `FILE: …` where no position applies).
Scenario load_scenario(const std::string& path);

/// Parses scenario text; `source` names it in messages.
Scenario parse_scenario(const std::string& text, const std::string& source);

/// Command-line overrides of [integrate].
struct IntegrateOverrides {
  std::optional<std::string> method;
  std::optional<double> step;
  std::optional<double> tol;
  std::optional<double> t_end;
  std::optional<std::string> split;
};

/// The method to run: `--method` or the file's method if given; otherwise a step selects the
/// default splitting method and a tolerance the default adaptive one (default_adaptive_method of
/// the model's field; the command line's step or tolerance wins over the file's). Tolerance `tol`
/// sets both absolute and relative tolerance. Throws InputError when neither a step nor a tolerance
/// is available for the chosen method. The split of the free body (`--split`, or the file's split
/// when the method run is a splitting method) sets the ordering: the method's default ordering with
/// that split; `--split` with a method that is not a splitting method, and the exact split with a
/// gyrostat (k ≠ 0), are bad input.
MethodSettings resolve_method(const Scenario& s, const IntegrateOverrides& o);

/// t_end from the command line or the file; throws InputError if neither gives one.
double resolve_t_end(const Scenario& s, const IntegrateOverrides& o);

}  // namespace newtop::io
