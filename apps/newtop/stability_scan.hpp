#pragma once
// The stability diagrams of `newtop stability`: along Ω (--scan-omega, JSON and CSV) and over two
// parameters (--scan, CSV). CSV booleans are 1/0 and no cell is empty (docs/cli.md).

#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "newtop/io/json.hpp"
#include "newtop/io/option_lists.hpp"
#include "newtop/io/output.hpp"
#include "newtop/model/model.hpp"

namespace newtop::app {

/// The ranges of --scan-omega and --scan (newtop/io/option_lists.hpp).
using io::kMaxGridPoints;
using io::parse_grid;
using io::parse_range;
using io::Range;

/// Stability along Ω about `axis`: the JSON list, and the CSV
/// `omega,max_real_part,linearly_stable,energy_casimir_stable` to `out` when given (opened by the
/// caller before any work, committed here).
io::Json omega_scan(const QuadraticModel& model, int axis, const Range& r, io::AtomicFile* out);

/// The two-parameter diagram to the CSV `out` (opened by the caller before any work, committed
/// here): `P1,P2,max_real_part,verdict`, verdict stable, unstable or nonphysical (max_real_part
/// nan there).
void grid_scan(const QuadraticModel& model, int axis, double omega0,
               const std::pair<Range, Range>& grid, io::AtomicFile& out);

/// The --scan-omega list as a table of the human summary.
void print_omega_scan(std::ostream& os, const io::Json& scan);

/// "stable", "unstable" or "inconclusive" (nullopt) for a Lyapunov verdict.
std::string verdict_text(const std::optional<bool>& v);
std::optional<bool> optional_bool(const io::Json& v);
io::Json optional_json(const std::optional<bool>& v);
io::Json optional_json(const std::optional<double>& v);

}  // namespace newtop::app
