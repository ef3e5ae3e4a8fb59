#pragma once
// Comma-separated times on the command line (`--times 0.5,1,2`).

#include <string>
#include <vector>

#include "newtop/integrate/output_times.hpp"
#include "newtop/io/option_lists.hpp"

namespace newtop::app {

/// The finite times of a comma-separated list (newtop/io/option_lists.hpp).
using io::parse_times;

/// The end of a run through these times from t0: the time farthest from t0 (all must lie on one
/// side of it).
double times_end(const std::string& option, const std::vector<double>& times, double t0);

/// The times sorted in the direction of the run from t0 to t_end, as OutputTimes (which checks
/// them: inside the run, no repeats).
OutputTimes output_times_option(const std::string& option, const std::string& text, double t0,
                                double t_end);

}  // namespace newtop::app
