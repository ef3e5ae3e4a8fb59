#pragma once
// The stability diagrams of `newtop stability`: along Ω (--scan-omega, JSON and CSV) and over two
// parameters (--scan, CSV). CSV booleans are 1/0 and no cell is empty (docs/cli.md).

#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "newtop/io/json.hpp"
#include "newtop/io/output.hpp"
#include "newtop/model/model.hpp"

namespace newtop::app {

/// N equally spaced values of a parameter from lo to hi (lo alone when N = 1).
struct Range {
  std::string name;
  double lo, hi;
  int n;
  double at(int k) const { return n == 1 ? lo : lo + (hi - lo) * k / (n - 1); }
};

/// "LO:HI:N" (or "NAME=LO:HI:N" when `named`, NAME in omega, lambda, A, B, C), N from 1 to
/// kMaxScanPoints; `flag` names the option in messages.
Range parse_range(const std::string& flag, const std::string& text, bool named);

/// --scan "P1=LO:HI:N,P2=LO:HI:M" with N·M ≤ kMaxGridPoints.
std::pair<Range, Range> parse_grid(const std::string& spec);

/// Grid points of --scan at most: 1e6 eigenvalue problems take seconds and the CSV ~60 MB.
inline constexpr long long kMaxGridPoints = 1000000;

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
