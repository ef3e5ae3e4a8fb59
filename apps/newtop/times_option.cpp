#include "times_option.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "newtop/core/types.hpp"

namespace newtop::app {

std::vector<double> parse_times(const std::string& option, const std::string& text) {
  std::vector<double> t;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto first = item.find_first_not_of(" \t");
    item = first == std::string::npos
               ? ""
               : item.substr(first, item.find_last_not_of(" \t") - first + 1);
    double v = std::nan("");
    try {
      std::size_t used = 0;
      v = std::stod(item, &used);
      if (used != item.size()) v = std::nan("");
    } catch (const std::exception&) {
    }
    if (!std::isfinite(v)) {
      throw InputError(option + ": expected comma-separated finite times, found '" + item + "'");
    }
    t.push_back(v);
  }
  if (t.empty()) throw InputError(option + ": expected at least one time, found none");
  return t;
}

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
