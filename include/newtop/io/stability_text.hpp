#pragma once
/// \file
/// The human summary of `newtop stability` (docs/cli.md): the report of a fixed point and the
/// table of a scan along Ω, written from their JSON (analysis_json.hpp) so that the text and the
/// JSON always say the same.

#include <ostream>
#include <string>

#include "newtop/io/json.hpp"

namespace newtop::io {

/// The report of to_json(StabilityReport, body): the polish (when Newton moved the state), the
/// state, the eigenvalues on the leaf, the verdicts and, for a spin axis, the thresholds
/// (`formula_note` where Beletsky's formula does not apply).
void write_stability_text(std::ostream& os, const Json& report, const std::string& formula_note);

/// The table of to_json(std::vector<ScanPoint>): Ω, the max real part and both verdicts per row.
void write_omega_scan_text(std::ostream& os, const Json& scan);

}  // namespace newtop::io
