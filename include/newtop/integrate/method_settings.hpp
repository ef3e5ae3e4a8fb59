#pragma once
/// \file
/// Methods by name, for scenario files and the command line: what each is and the settings of a
/// run. Declarations only (no stepper), so that readers of scenarios need not compile the
/// integrators; methods.hpp runs them.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "newtop/integrate/composition_tables.hpp"

namespace newtop {

enum class MethodKind { splitting, fixed_rk, adaptive };

struct MethodInfo {
  std::string_view name;
  MethodKind kind;
  int order;
  std::string_view description;
};

/// Every method newtop can run: the splitting compositions, rk4, dopri5, rkf78, dop853, taylor
/// (order 0 in MethodInfo: Taylor's order follows the tolerance).
std::span<const MethodInfo> methods();
/// The method with this name; throws InputError listing the known names if there is none.
const MethodInfo& method_info(std::string_view name);

/// Default method when only a step is given: the splitting method with the best work–precision
/// at moderate accuracy (docs/performance.md).
inline constexpr std::string_view kDefaultFixedMethod = "splitting6";
/// Default method when only a tolerance is given and the field is not the quadratic one: the
/// adaptive method with the best work–precision of those that run every field
/// (docs/performance.md).
inline constexpr std::string_view kDefaultAdaptiveMethod = "dop853";
/// Default method when only a tolerance is given, on the quadratic field: Taylor's method, the
/// fastest to a given state error in every regime measured, with and without its tangent map
/// (docs/performance.md, docs/chaos.md).
inline constexpr std::string_view kDefaultQuadraticAdaptiveMethod = "taylor";

/// The default adaptive method of a run (the two above).
constexpr std::string_view default_adaptive_method(bool quadratic_field) {
  return quadratic_field ? kDefaultQuadraticAdaptiveMethod : kDefaultAdaptiveMethod;
}

/// What to run: a method by name with its step (fixed-step methods) or tolerances (adaptive).
struct MethodSettings {
  MethodSettings() = default;
  /// `{"splitting6", 0.01}` (a fixed step) or `{"dop853", 0.0, 1e-10, 1e-10}` (tolerances): the
  /// members in order, the rest at their defaults.
  MethodSettings(std::string name_, double step_ = 0.0, double abs_tol_ = 1e-12,
                 double rel_tol_ = 1e-12, std::optional<SplitOrdering> ordering_ = std::nullopt)
      : name(std::move(name_)),
        step(step_),
        abs_tol(abs_tol_),
        rel_tol(rel_tol_),
        ordering(std::move(ordering_)) {}

  std::string name{kDefaultFixedMethod};
  double step = 0.0;
  double abs_tol = 1e-12;
  double rel_tol = 1e-12;
  /// Splitting methods: the ordering of the split; default_ordering(table) when absent.
  std::optional<SplitOrdering> ordering;
};

/// The split of the free body by name: "axes", "spin" or "exact" (FreeBodySplit); throws
/// InputError naming `field` otherwise.
FreeBodySplit free_body_split(std::string_view name, std::string_view field);

/// The name of a split ("axes", "spin", "exact").
std::string_view to_string(FreeBodySplit split);

/// The split of the free body a splitting method runs with: its ordering's, or its table's default.
FreeBodySplit free_body_split(const MethodSettings& settings);

/// Checks the settings (known name, a step > 0 for fixed-step methods, tolerances > 0 for adaptive
/// ones); throws InputError naming the field.
void validate(const MethodSettings& settings);

}  // namespace newtop
