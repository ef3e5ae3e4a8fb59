#pragma once
// newtop continue (continue.cpp): the arguments, the computed family and its report
// (continue_output.cpp).

#include <optional>
#include <string>
#include <vector>

#include "newtop/analysis/continuation.hpp"
#include "newtop/io/output.hpp"
#include "newtop/orbit/resonance_continuation.hpp"

namespace newtop::app {

/// The command line (docs/cli.md, continue).
struct ContinueArgs {
  std::string scenario, family, parameter, range;
  std::optional<std::string> resonance, line, second, second_range, out;
  bool json = false;
  bool switch_branches = false;  // --switch
  std::optional<int> mode;       // --mode (periodic)
};

/// A located event's locus in the second key (--second) and the family from a located flip or
/// branch point (--switch).
using Boundary = FamilyBoundary;
using Branch = FamilyBranch;

/// The family computed, the names of its values, the boundaries and the branches.
struct Run {
  Family family;
  std::vector<std::string> names;  // of FamilyPoint::values
  std::vector<Boundary> boundaries;
  std::vector<Branch> branches;
};

/// The fixed-point scenario's equilibrium at rest in a body or field key, and the Lyapunov family
/// of a stable one in the energy (continue_fixed.cpp).
Run run_rest(const ContinueArgs& a, double p0, double p1);
Run run_periodic(const ContinueArgs& a, double p0, double p1);

/// Throws the InputError refusing --parameter for --family: `allowed` names what it accepts.
[[noreturn]] void refuse_key(const ContinueArgs& a, const std::string& allowed);

/// Writes the CSV into `file` (when given) and commits it, then prints the JSON or the summary.
int report(const ContinueArgs& a, const Run& r, double p0, double p1, io::AtomicFile* file);

}  // namespace newtop::app
