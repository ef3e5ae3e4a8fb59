// Sweep files (docs/sweep.md): reading and checking, and the points of the grid or zip.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include "../io/file_check.hpp"
#include "../io/toml_parse.hpp"
#include "../io/toml_reader.hpp"
#include "newtop/core/grid.hpp"
#include "newtop/io/suggest.hpp"
#include "newtop/sweep/sweep.hpp"
#include "sweep_points.hpp"

namespace newtop::sweep {
namespace {

/// At most this many points (a CSV of 10⁸ rows is already 10 GB).
constexpr double kMaxPoints = 1e8;
/// At most this many values over all axes (1.6 GB): a zip of two axes of 10⁸ values, of K axes
/// 2·10⁸/K values each. A grid of at most 10⁸ points never comes near it.
constexpr double kMaxValues = 2e8;

const std::vector<std::string> kTopKeys{"scenario",  "quantities", "combine", "axes",
                                        "stability", "integrate",  "level"};
const std::vector<std::string> kAxisKeys{"key", "start", "stop", "count", "scale", "values"};

/// start, stop, count and scale (linear or log) of one [[axes]] entry, or its values; admit(n)
/// checks the number of values before they are made (it throws for too many).
std::vector<double> axis_values(io::TableReader& r, const std::function<void(std::size_t)>& admit) {
  if (r.has("values")) {
    r.only({"key", "values"}, kAxisKeys, "values");
    std::vector<double> v = r.numbers("values");
    admit(v.size());
    return v;
  }
  const double start = r.number("start");
  const double stop = r.number("stop");
  const std::int64_t count = r.integer("count", 1, static_cast<std::int64_t>(kMaxPoints));
  const std::string scale = r.has("scale") ? r.string("scale") : "linear";
  if (scale != "linear" && scale != "log") {
    r.fail("scale", "expected \"linear\" or \"log\", found \"" + scale + "\"");
  }
  if (scale == "linear" && !std::isfinite(stop - start)) {
    r.fail("stop", "expected stop - start finite (a range of doubles), found start = " +
                       format_number(start) + ", stop = " + format_number(stop));
  }
  if (count == 1 && start != stop) {
    r.fail("count", "expected count >= 2 for start != stop, found 1");
  }
  if (scale == "log" && !(start > 0 && stop > 0)) {
    r.fail(start > 0 ? "stop" : "start", "expected a number > 0 with scale = \"log\", found " +
                                             format_number(start > 0 ? stop : start));
  }
  admit(static_cast<std::size_t>(count));
  std::vector<double> v(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    // Computed from the index (never accumulated), the ends exact; a linear axis gives the decimal
    // points the user means where they are representable (0.9, not 0.8999999999999999).
    const double f = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
    v[static_cast<std::size_t>(i)] =
        i == count - 1   ? stop
        : scale == "log" ? std::exp(std::log(start) + f * (std::log(stop) - std::log(start)))
                         : grid_value(start, stop, count, i);
  }
  v.front() = start;
  return v;
}

}  // namespace

const std::vector<std::string>& known_quantities() {
  static const std::vector<std::string> q{"stability",   "drift",          "equilibria",
                                          "final_state", "megno",          "lyapunov_max",
                                          "debra_delp",  "synchronous_odd"};
  return q;
}

const char* to_string(BaseModel m) {
  switch (m) {
    case BaseModel::circular_orbit:
      return "circular orbit";
    case BaseModel::elliptic_orbit:
      return "elliptic orbit";
    case BaseModel::fixed_point:
      break;
  }
  return "fixed point";
}

std::size_t point_count(const SweepFile& s) {
  if (s.axes.empty()) return 1;
  if (s.combine == Combine::zip) return s.axes.front().values.size();
  std::size_t n = 1;
  for (const Axis& a : s.axes) n *= a.values.size();
  return n;
}

std::vector<double> point_values(const SweepFile& s, std::size_t index) {
  std::vector<double> v(s.axes.size());
  if (s.combine == Combine::zip) {
    for (std::size_t k = 0; k < s.axes.size(); ++k) v[k] = s.axes[k].values[index];
    return v;
  }
  for (std::size_t k = s.axes.size(); k-- > 0;) {  // the last axis varies fastest
    const std::size_t n = s.axes[k].values.size();
    v[k] = s.axes[k].values[index % n];
    index /= n;
  }
  return v;
}

}  // namespace newtop::sweep

namespace newtop::sweep {
namespace {

/// The quantity option an axis may sweep ("stability.omega"); other keys are scenario keys.
bool is_option_key(const std::string& key) { return key == "stability.omega"; }

void read_stability(io::TableReader& top, SweepFile& s) {
  const toml::table* t = top.table("stability");
  if (!t) return;
  io::TableReader r(*t, s.source, "stability");
  r.check_keys({"axis", "omega"});
  if (r.has("axis")) {
    const std::string a = r.string("axis");
    if (a != "x" && a != "y" && a != "z") r.fail("axis", "expected x, y or z, found '" + a + "'");
    s.stability.axis = a[0] - 'x';
  }
  if (r.has("omega")) {
    if (!s.stability.axis) r.fail("omega", "needs axis = \"x\", \"y\" or \"z\" (which axis spins)");
    s.stability.omega = r.number("omega");
  }
  r.finish();
}

void read_integrate(io::TableReader& top, SweepFile& s) {
  const toml::table* t = top.table("integrate");
  if (!t) return;
  io::TableReader r(*t, s.source, "integrate");
  r.check_keys({"method", "step", "tol", "t_end"});
  s.integrate.method = r.optional_string("method");
  s.integrate.step = r.optional_number("step");
  s.integrate.tol = r.optional_number("tol");
  s.integrate.t_end = r.optional_number("t_end");
  if (s.integrate.step && s.integrate.tol) r.fail("tol", "give either step or tol, not both");
  r.finish();
}

void read_level(io::TableReader& top, SweepFile& s) {
  const toml::table* t = top.table("level");
  if (!t) return;
  io::TableReader r(*t, s.source, "level");
  r.check_keys({"energy", "solve", "sign"});
  EnergyLevel level;
  level.energy = r.number("energy");
  const std::string solve = r.has("solve") ? r.string("solve") : "omega3";
  if (solve != "omega1" && solve != "omega2" && solve != "omega3") {
    r.fail("solve", "expected omega1, omega2 or omega3, found '" + solve + "'");
  }
  level.component = solve.back() - '1';
  const std::string sign = r.has("sign") ? r.string("sign") : "+";
  if (sign != "+" && sign != "-") r.fail("sign", "expected \"+\" or \"-\", found '" + sign + "'");
  level.sign = sign == "+" ? 1.0 : -1.0;
  r.finish();
  for (const std::string& q : s.quantities) {
    if (q == "stability" || q == "equilibria") {
      top.fail("level",
               "applies to the trajectory quantities (drift, final_state, megno, "
               "lyapunov_max), found the quantity '" +
                   q + "'");
    }
  }
  s.level = level;
}

/// The base's model from its [orbit] kind (a malformed base is reported when its points are
/// built).
BaseModel base_model(const std::string& text) {
  if (!io::is_orbit_scenario_text(text)) return BaseModel::fixed_point;
  const toml::table doc = io::parse_toml(text, "");
  const std::optional<std::string> kind = doc["orbit"]["kind"].value<std::string>();
  return kind == "elliptic" ? BaseModel::elliptic_orbit : BaseModel::circular_orbit;
}

[[noreturn]] void zip_mismatch(const SweepFile& s, const Axis& first, const std::string& key,
                               std::size_t n) {
  throw InputError(s.source + ": combine = \"zip\": expected axes of equal length, found " +
                   std::to_string(first.values.size()) + " values of '" + first.key + "' and " +
                   std::to_string(n) + " of '" + key + "'");
}

[[noreturn]] void too_many_points(const SweepFile& s, double points) {
  throw InputError(s.source + ": [[axes]]: expected at most " + format_number(kMaxPoints) +
                   " points, found " + format_number(points));
}

void read_axes(const toml::table& doc, SweepFile& s) {
  const toml::node* n = doc.get("axes");
  if (!n) return;
  const toml::array* list = n->as_array();
  if (!list || !list->is_array_of_tables()) {
    io::TableReader(doc, s.source, "")
        .fail("axes", "expected [[axes]] tables, found " + io::describe(*n));
  }
  double points = 1;  // the grid's points over the axes read so far
  double values = 0;  // the values of the axes read so far
  for (std::size_t i = 0; i < list->size(); ++i) {
    io::TableReader r(*list->get(i)->as_table(), s.source, "axes[" + std::to_string(i + 1) + "]");
    r.check_keys(kAxisKeys);
    Axis a{r.string("key"), {}};
    for (const Axis& b : s.axes) {
      if (b.key == a.key) r.fail("key", "expected each key once, found '" + a.key + "' again");
    }
    // The sizes are checked before the values are made: axes whose points are refused never
    // allocate them (three axes of 10⁸ values would take 2.4 GB), and the values of all axes
    // together are bounded (a zip of K axes of N values holds K N of them).
    a.values = axis_values(r, [&](std::size_t length) {
      if (s.combine == Combine::zip && !s.axes.empty() && length != s.axes.front().values.size()) {
        zip_mismatch(s, s.axes.front(), a.key, length);
      }
      points *= static_cast<double>(length);
      if (s.combine == Combine::grid && points > kMaxPoints) too_many_points(s, points);
      values += static_cast<double>(length);
      if (values > kMaxValues) {
        throw InputError(s.source + ": [[axes]]: expected at most " + format_number(kMaxValues) +
                         " values over all axes, found " + format_number(values) + " by '" + a.key +
                         "'");
      }
    });
    r.finish();
    s.axes.push_back(std::move(a));
  }
}

/// The base scenario's model (fixed point, circular or elliptic orbit) from its text, and the
/// quantities and keys that apply to it (check_model).
void set_base_model(SweepFile& s) {
  s.model = base_model(s.base_text);
  check_model(s);
}

}  // namespace

SweepFile read_sweep(const std::string& path) {
  SweepFile s = parse_sweep(io::read_regular_file(path, io::kMaxTomlBytes, "sweep file"), path);
  const std::filesystem::path base_path(s.base_source);
  s.base_source = base_path.is_absolute()
                      ? s.base_source
                      : (std::filesystem::path(path).parent_path() / base_path).string();
  s.base_text = io::read_regular_file(s.base_source, io::kMaxTomlBytes, "scenario file");
  set_base_model(s);
  return s;
}

SweepFile parse_sweep(const std::string& text, const std::string& path) {
  SweepFile s;
  s.source = path;
  s.text = text;
  const toml::table doc = io::parse_toml(s.text, path);
  io::TableReader top(doc, path, "");
  for (const auto& [key, node] : doc) {
    const std::string k(key.str());
    if (std::find(kTopKeys.begin(), kTopKeys.end(), k) != kTopKeys.end()) continue;
    std::string list;
    for (const auto& n : kTopKeys) list += (list.empty() ? "" : ", ") + n;
    const auto close = io::closest_name(k, kTopKeys);
    top.fail_at(node, k,
                "unknown key in a sweep file" + (close ? " — did you mean '" + *close + "'?"
                                                       : " (expected one of: " + list + ")"));
  }
  s.base_source = top.string("scenario");
  s.quantities = top.strings("quantities");
  for (const std::string& q : s.quantities) {
    const auto& known = known_quantities();
    if (std::find(known.begin(), known.end(), q) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      top.fail("quantities", "expected any of " + list + ", found '" + q + "'");
    }
    if (std::count(s.quantities.begin(), s.quantities.end(), q) > 1) {
      top.fail("quantities", "expected each quantity once, found '" + q + "' twice");
    }
  }
  const std::string combine = top.has("combine") ? top.string("combine") : "grid";
  if (combine != "grid" && combine != "zip") {
    top.fail("combine", "expected \"grid\" or \"zip\", found \"" + combine + "\"");
  }
  s.combine = combine == "zip" ? Combine::zip : Combine::grid;
  read_axes(doc, s);
  read_stability(top, s);
  read_integrate(top, s);
  read_level(top, s);
  for (const Axis& a : s.axes) {
    if (a.key.rfind("stability.", 0) == 0 && !is_option_key(a.key)) {
      throw InputError(path + ": [[axes]] key '" + a.key +
                       "': expected stability.omega or a scenario key");
    }
    if (is_option_key(a.key) && !s.stability.axis) {
      throw InputError(path + ": [[axes]] key 'stability.omega': needs [stability] axis");
    }
    if (is_option_key(a.key) &&
        std::find(s.quantities.begin(), s.quantities.end(), "stability") == s.quantities.end()) {
      throw InputError(path + ": [[axes]] key 'stability.omega': needs the quantity 'stability'");
    }
  }
  for (const Axis& a : s.axes) {  // the ratios set the three moments: not with one of them
    if ((a.key == "body.k_R" || a.key == "body.k_Y") &&
        std::any_of(s.axes.begin(), s.axes.end(),
                    [](const Axis& b) { return b.key.rfind("body.inertia", 0) == 0; })) {
      throw InputError(path + ": [[axes]] key '" + a.key +
                       "': expected the inertia ratios or the moments body.inertia[i], found both");
    }
  }
  return s;
}

SweepFile load_sweep(const std::string& path) {
  SweepFile s = read_sweep(path);
  check_points(s);
  return s;
}

SweepFile make_sweep(const std::string& text, const std::string& base_source,
                     const std::string& base_text) {
  SweepFile s = parse_sweep(text, "sweep");
  s.base_source = base_source;
  s.base_text = base_text;
  set_base_model(s);
  check_points(s);
  return s;
}

}  // namespace newtop::sweep
