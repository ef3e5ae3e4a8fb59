// The lists of the command line (option_lists.hpp): each parser refuses anything but the list it
// documents, in one line naming the option.

#include "newtop/io/option_lists.hpp"

#include <cmath>
#include <sstream>

#include "newtop/analysis/stability_spin.hpp"

namespace newtop::io {

template <class... T>
std::optional<std::tuple<T...>> read_colon_values(const std::string& text) {
  std::istringstream is(text);
  std::tuple<T...> values;
  bool ok = true;
  std::size_t k = 0;
  auto read = [&](auto& v) {
    char colon = ':';
    if (ok && k++ > 0) ok = static_cast<bool>(is >> colon) && colon == ':';
    if (ok) ok = static_cast<bool>(is >> v);
  };
  std::apply([&](auto&... v) { (read(v), ...); }, values);
  std::string rest;
  if (!ok || (is >> rest)) return std::nullopt;
  return values;
}

template std::optional<std::tuple<double, double, int>> read_colon_values<double, double, int>(
    const std::string&);
template std::optional<std::tuple<double, double>> read_colon_values<double, double>(
    const std::string&);
template std::optional<std::tuple<int, int>> read_colon_values<int, int>(const std::string&);

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

Vec3 parse_gamma(const std::string& text) {
  std::stringstream ss(text);
  std::string tok;
  std::vector<double> v;
  while (std::getline(ss, tok, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(tok, &used));
      if (used != tok.size()) throw std::invalid_argument(tok);
    } catch (const std::exception&) {
      throw InputError("--gamma: expected three numbers g1,g2,g3, found \"" + text + "\"");
    }
  }
  if (v.size() != 3)
    throw InputError("--gamma: expected three numbers g1,g2,g3, found \"" + text + "\"");
  const Vec3 g(v[0], v[1], v[2]);
  if (!g.allFinite() || g.norm() == 0.0) {
    throw InputError("--gamma: expected a finite non-zero vector, found " + format_vector(g));
  }
  return g.normalized();
}

RadiusScan parse_radius_scan(const std::string& text) {
  RadiusScan s{};
  const auto v = read_colon_values<double, double, int>(text);
  if (v) std::tie(s.R1, s.R2, s.n) = *v;
  if (!v || !(s.R1 > 0) || !(s.R2 > s.R1) || s.n < 2 || s.n > kMaxScanPoints) {
    throw InputError("--scan-R: expected R1:R2:N with 0 < R1 < R2 and 2 <= N <= " +
                     std::to_string(kMaxScanPoints) + ", found \"" + text + "\"");
  }
  return s;
}

Range parse_range(const std::string& flag, const std::string& text, bool named) {
  Range r{"omega", 0, 0, 0};
  std::string spec = text;
  if (named) {
    const auto eq = text.find('=');
    if (eq != std::string::npos) r.name = text.substr(0, eq);
    spec = eq == std::string::npos ? "" : text.substr(eq + 1);
  }
  const auto v = read_colon_values<double, double, int>(spec);
  if (v) std::tie(r.lo, r.hi, r.n) = *v;
  if (!v || r.n < 1 || r.n > kMaxScanPoints || !std::isfinite(r.lo) || !std::isfinite(r.hi)) {
    throw InputError(flag + ": expected " + (named ? "NAME=LO:HI:N" : "LO:HI:N") +
                     " (two finite numbers and a count from 1 to " +
                     std::to_string(kMaxScanPoints) + "), found '" + text + "'");
  }
  if (named && r.name != "omega" && r.name != "lambda" && r.name != "A" && r.name != "B" &&
      r.name != "C") {
    throw InputError(flag + ": expected a parameter omega, lambda, A, B or C, found '" + r.name +
                     "'");
  }
  return r;
}

std::pair<Range, Range> parse_grid(const std::string& spec) {
  const auto comma = spec.find(',');
  if (comma == std::string::npos) {
    throw InputError("--scan: expected P1=LO:HI:N,P2=LO:HI:M, found '" + spec + "'");
  }
  const Range r1 = parse_range("--scan", spec.substr(0, comma), true);
  const Range r2 = parse_range("--scan", spec.substr(comma + 1), true);
  if (static_cast<long long>(r1.n) * r2.n > kMaxGridPoints) {
    throw InputError("--scan: expected at most " + std::to_string(kMaxGridPoints) +
                     " grid points N*M, found " + std::to_string(r1.n) + "*" +
                     std::to_string(r2.n));
  }
  return {r1, r2};
}

std::vector<SpinOrbitResonance> parse_resonances(const std::string& text) {
  std::vector<SpinOrbitResonance> list;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto pq = read_colon_values<int, int>(item);
    if (!pq) {
      throw InputError("--resonances: expected a list p:q,p:q,… of integers, found '" + item + "'");
    }
    try {
      list.push_back(resonance(std::get<0>(*pq), std::get<1>(*pq)));
    } catch (const InputError& e) {
      throw InputError(std::string("--resonances: ") + e.what());
    }
  }
  if (list.empty()) throw InputError("--resonances: expected a list p:q,…, found ''");
  return list;
}

SpinScan parse_spin(const std::string& text) {
  SpinScan s{};
  const auto v = read_colon_values<double, double, int>(text);
  if (v) std::tie(s.lo, s.hi, s.n) = *v;
  if (!v || !std::isfinite(s.lo) || !std::isfinite(s.hi) || s.n < 1 || s.n > 10000 || s.hi < s.lo) {
    throw InputError(
        "--spin: expected LO:HI:N with LO <= HI finite spin rates and 1 <= N <= "
        "10000, found '" +
        text + "'");
  }
  return s;
}

std::pair<RatioAxis, RatioAxis> parse_ratio_scan(const std::string& text) {
  auto fail = [&] {
    throw InputError("--scan: expected k_R=LO:HI:N,k_Y=LO:HI:M (|k| < 1, counts >= 1), found '" +
                     text + "'");
  };
  const auto comma = text.find(',');
  if (comma == std::string::npos) fail();
  auto one = [&](const std::string& part, const std::string& name) {
    if (part.rfind(name + "=", 0) != 0) fail();
    RatioAxis a;
    const auto v = read_colon_values<double, double, int>(part.substr(name.size() + 1));
    if (v) std::tie(a.lo, a.hi, a.n) = *v;
    if (!v || a.n < 1 || !(std::abs(a.lo) < 1) || !(std::abs(a.hi) < 1)) fail();
    return a;
  };
  const std::pair<RatioAxis, RatioAxis> axes{one(text.substr(0, comma), "k_R"),
                                             one(text.substr(comma + 1), "k_Y")};
  if (static_cast<long long>(axes.first.n) * axes.second.n > kMaxGridPoints) {
    throw InputError("--scan: expected at most " + std::to_string(kMaxGridPoints) +
                     " grid points N*M, found " + std::to_string(axes.first.n) + "*" +
                     std::to_string(axes.second.n));
  }
  return axes;
}

}  // namespace newtop::io
