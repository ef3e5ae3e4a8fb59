#pragma once
/// \file
/// What `newtop chaos` writes for a body (docs/chaos.md): the JSON object, the summary text and the
/// history CSV of phase::chaos's result.

#include <ostream>

#include "newtop/io/json.hpp"
#include "newtop/phase/chaos.hpp"

namespace newtop::io {

/// {lyapunov_max, spectrum (or null), megno, fli, t_end (reached), method, step (null for an
/// adaptive method), tol (adaptive), split (splitting methods), outcome, flow}.
Json to_json(const phase::ChaosResult& result, const phase::ChaosRequest& request);

/// The summary: the indicators, the spectrum, and the run (t, method, step or tol, outcome).
void write_chaos_text(std::ostream& os, const phase::ChaosResult& result,
                      const phase::ChaosRequest& request);

/// The history's header (t,lyapunov_max,megno_y,megno,fli[,lambda1..lambda6]) and one row.
void write_chaos_csv_header(std::ostream& os, bool spectrum);
void write_chaos_csv_row(std::ostream& os, const phase::ChaosSample& s);

}  // namespace newtop::io
