#include "times_option.hpp"

#include <algorithm>
#include <cmath>

#include "newtop/core/types.hpp"

namespace newtop::app {

double times_end(const std::string& option, const std::vector<double>& times, double t0) {
  const auto [lo, hi] = std::minmax_element(times.begin(), times.end());
  if (*lo<t0&& * hi> t0) {
    throw InputError(option + ": expected times on one side of t0 = " + format_number(t0) +
                     ", found " + format_number(*lo) + " and " + format_number(*hi));
  }
  return *hi > t0 ? *hi : *lo;
}

OutputTimes output_times_option(const std::string& option, const std::string& text, double t0,
                                double t_end) {
  std::vector<double> t = parse_times(option, text);
  if (t_end >= t0) {
    std::sort(t.begin(), t.end());
  } else {
    std::sort(t.begin(), t.end(), std::greater<>());
  }
  return OutputTimes::list(std::move(t), t0, t_end);
}

}  // namespace newtop::app
