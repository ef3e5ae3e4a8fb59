// newtop view: reading a trajectory CSV and writing the self-contained page (viewer/page.hpp).

#include "page.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "assets.hpp"
#include "newtop/exact/mass_models.hpp"
#include "newtop/io/json.hpp"

namespace newtop::viewer {
namespace {

const std::vector<std::string> kStateColumns{"t", "p", "q", "r", "gamma1", "gamma2", "gamma3"};
const std::vector<std::string> kAttitudeColumns{"q0", "q1", "q2", "q3"};
/// The integral columns of docs/cli.md, drawn as drift curves when present (on an orbit the Jacobi
/// integral and the Casimirs' error; H_nu of an ellipse is not conserved).
const std::vector<std::string> kIntegralColumns{"energy",   "area",   "geometric",    "brun",
                                                "lagrange", "jacobi", "casimir_error"};
/// An orbit run's state (simulate --out on an orbit scenario, docs/orbit.md §12), after t[,nu].
const std::vector<std::string> kOrbitColumns{"omega1", "omega2",  "omega3",  "gamma1", "gamma2",
                                             "gamma3", "normal1", "normal2", "normal3"};
/// The angles relative to LVLH that an orbit run may carry (--euler 321), shown as numbers.
const std::vector<std::string> kLvlhAngles{"roll", "pitch", "yaw"};

bool starts_with(const std::vector<std::string>& names, std::size_t at,
                 const std::vector<std::string>& head) {
  return names.size() >= at + head.size() &&
         std::equal(head.begin(), head.end(), names.begin() + static_cast<std::ptrdiff_t>(at));
}

/// t, then nu on an ellipse, then the orbit state.
bool is_orbit_header(const std::vector<std::string>& names) {
  if (names.empty() || names[0] != "t") return false;
  return starts_with(names, names.size() > 1 && names[1] == "nu" ? 2 : 1, kOrbitColumns);
}

std::vector<std::string_view> split_fields(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    std::string_view f =
        line.substr(start, comma == std::string_view::npos ? line.npos : comma - start);
    while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
    while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
    out.push_back(f);
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

std::string where(const std::string& source, std::size_t line) {
  return source + ":" + std::to_string(line) + ": ";
}

std::string shortened(std::string_view s) {
  return std::string(s.size() > 80 ? std::string(s.substr(0, 77)) + "..." : std::string(s));
}

double parse_cell(std::string_view cell, const std::string& at, const std::string& name) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (cell.empty() || ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(v)) {
    throw InputError(at + "column " + name + ": expected a finite number, found '" +
                     shortened(cell) + "'");
  }
  return v;
}

void check_header(const std::vector<std::string>& names, const std::string& source,
                  std::string_view header) {
  if (!starts_with(names, 0, kStateColumns) && !is_orbit_header(names)) {
    throw InputError(where(source, 1) +
                     "expected the header of a newtop trajectory CSV (newtop simulate --out), "
                     "starting t,p,q,r,gamma1,gamma2,gamma3 or, on an orbit, "
                     "t[,nu],omega1,omega2,omega3,gamma1,gamma2,gamma3,normal1,normal2,normal3, "
                     "found '" +
                     shortened(header) + "'");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
        names.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw InputError(where(source, 1) + "column " + names[i] + ": expected once, found twice");
    }
  }
  const auto present =
      std::count_if(kAttitudeColumns.begin(), kAttitudeColumns.end(), [&](const std::string& q) {
        return std::find(names.begin(), names.end(), q) != names.end();
      });
  if (present != 0 && present != 4) {
    throw InputError(where(source, 1) +
                     "attitude: expected all four columns q0,q1,q2,q3 or none, found " +
                     std::to_string(present));
  }
}

/// Rows must move forward in time and carry usable directions.
void check_row(const Trajectory& tr, const std::string& at) {
  const std::size_t k = tr.rows() - 1;
  const auto& t = tr.columns[0];
  if (k > 0 && !(t[k] > t[k - 1])) {
    throw InputError(at + "column t: expected a time greater than the previous row's " +
                     std::to_string(t[k - 1]) + ", found " + std::to_string(t[k]));
  }
  auto norm = [&](const std::vector<std::string>& names) {
    double s = 0.0;
    for (const auto& n : names) s += std::pow((*tr.column(n))[k], 2);
    return std::sqrt(s);
  };
  if (!(norm({"gamma1", "gamma2", "gamma3"}) > 0.0)) {
    throw InputError(at + "gamma1,gamma2,gamma3: expected a direction (non-zero vector), found 0");
  }
  if (tr.orbit() && !(norm({"normal1", "normal2", "normal3"}) > 0.0)) {
    throw InputError(at +
                     "normal1,normal2,normal3: expected a direction (non-zero vector), found 0");
  }
  if (tr.has_attitude() && !(norm(kAttitudeColumns) > 0.0)) {
    throw InputError(at + "q0,q1,q2,q3: expected a rotation (non-zero quaternion), found 0");
  }
}

io::Json vec_json(const Vec3& v) { return io::Json::array({v.x(), v.y(), v.z()}); }

/// The body's shape for the page, every coordinate in the principal axes (body frame).
io::Json shape_json(const io::Scenario& sc) {
  if (!sc.model.mass_model()) return {{"kind", "inertia_ellipsoid"}};
  const MassModel& mm = *sc.model.mass_model();
  const Mat3 to_body = sc.model.body().principal_axes().transpose();
  const double radius = max_radius(mm) > 0.0 ? max_radius(mm) : 1.0;
  return std::visit(
      [&](const auto& m) -> io::Json {
        using T = std::decay_t<decltype(m)>;
        io::Json j{{"radius", radius}};
        if constexpr (std::is_same_v<T, Polyhedron>) {
          j["kind"] = "mesh";
          io::Json v = io::Json::array(), f = io::Json::array();
          for (const Vec3& p : m.vertices())
            for (double c : Vec3(to_body * p)) v.push_back(c);
          for (const Triangle& tri : m.faces())
            for (int i : tri) f.push_back(i);
          j["vertices"] = std::move(v);
          j["faces"] = std::move(f);
        } else if constexpr (std::is_same_v<T, Ellipsoid>) {
          j["kind"] = "ellipsoid";
          j["semi_axes"] = vec_json(m.semi_axes);
          j["center"] = vec_json(m.center);
          j["to_body"] = {vec_json(to_body.row(0)), vec_json(to_body.row(1)),
                          vec_json(to_body.row(2))};
        } else {
          j["kind"] = "points";
          j["masses"] = m.masses();
          io::Json p = io::Json::array();
          for (const Vec3& x : m.positions())
            for (double c : Vec3(to_body * x)) p.push_back(c);
          j["positions"] = std::move(p);
        }
        return j;
      },
      mm);
}

io::Json body_json(const io::Scenario& sc) {
  const Body& b = sc.model.body();
  return {{"inertia", vec_json(b.inertia())},
          {"gyrostat", vec_json(b.gyrostat())},
          {"center_of_mass", vec_json(b.center_of_mass())},
          {"mass", b.mass()},
          {"shape", shape_json(sc)}};
}

void replace_once(std::string& page, const std::string& key, std::string_view value) {
  const std::size_t at = page.find(key);
  if (at == std::string::npos || page.find(key, at + key.size()) != std::string::npos) {
    throw std::logic_error("viewer/view.html: placeholder " + key + " must appear exactly once");
  }
  page.replace(at, key.size(), value);
}

}  // namespace

const std::vector<double>* Trajectory::column(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? nullptr : &columns[static_cast<std::size_t>(it - names.begin())];
}

Trajectory parse_trajectory(const std::string& text, const std::string& source) {
  Trajectory tr{source, {}, {}};
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line == "\r") continue;
    const auto fields = split_fields(line);
    if (tr.names.empty()) {
      for (auto f : fields) tr.names.emplace_back(f);
      check_header(tr.names, source, line);
      tr.columns.resize(tr.names.size());
      continue;
    }
    const std::string at = where(source, line_no);
    if (fields.size() != tr.names.size()) {
      throw InputError(at + "expected " + std::to_string(tr.names.size()) +
                       " fields as in the header, found " + std::to_string(fields.size()));
    }
    for (std::size_t i = 0; i < fields.size(); ++i)
      tr.columns[i].push_back(parse_cell(fields[i], at, tr.names[i]));
    check_row(tr, at);
  }
  if (tr.names.empty()) {
    throw InputError(source +
                     ": expected a newtop trajectory CSV (newtop simulate --out), "
                     "found an empty file");
  }
  if (tr.rows() == 0) throw InputError(source + ": expected at least one data row, found none");
  return tr;
}

std::vector<std::size_t> frame_rows(std::size_t n, std::size_t limit) {
  std::vector<std::size_t> rows;
  if (n <= limit || limit < 2) {
    for (std::size_t i = 0; i < n; ++i) rows.push_back(i);
    return rows;
  }
  for (std::size_t k = 0; k < limit; ++k) {
    rows.push_back(static_cast<std::size_t>(std::llround(
        static_cast<double>(k) * static_cast<double>(n - 1) / static_cast<double>(limit - 1))));
  }
  return rows;
}

namespace {

/// The page of a trajectory with the body's JSON (null without a scenario) and the scenario's name.
std::string page_with(const Trajectory& tr, io::Json body, io::Json scenario_name,
                      const PageOptions& options) {
  const std::vector<std::size_t> rows = frame_rows(tr.rows(), options.max_frames);
  auto pick = [&](const std::string& name) {
    io::Json a = io::Json::array();
    for (std::size_t r : rows) a.push_back((*tr.column(name))[r]);
    return a;
  };
  io::Json columns, integrals = io::Json::object();
  if (tr.orbit()) {
    // ω in the page's names p, q, r; n for the LVLH triad and the orbit's plane.
    for (int i = 0; i < 3; ++i) columns[std::string(1, "pqr"[i])] = pick(kOrbitColumns[i]);
    for (std::size_t i = 3; i < kOrbitColumns.size(); ++i) {
      columns[kOrbitColumns[i]] = pick(kOrbitColumns[i]);
    }
    columns["t"] = pick("t");
    for (const auto& n : kLvlhAngles)
      if (tr.column(n)) columns[n] = pick(n);
  } else {
    for (const auto& n : kStateColumns) columns[n] = pick(n);
  }
  if (tr.has_attitude())
    for (const auto& n : kAttitudeColumns) columns[n] = pick(n);
  for (const auto& n : kIntegralColumns)
    if (tr.column(n)) integrals[n] = pick(n);
  io::Json data{
      {"source", tr.source},           {"scenario", std::move(scenario_name)},
      {"rows_total", tr.rows()},       {"rows_shown", rows.size()},
      {"attitude", tr.has_attitude()}, {"orbit", tr.orbit()},
      {"columns", std::move(columns)}, {"integrals", std::move(integrals)},
      {"body", std::move(body)},       {"three_js", std::string(assets::three_js_revision())}};
  std::string json = data.dump();
  // "</" may occur only inside JSON strings, where "<\/" means the same: no early </script>.
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 3))
    json.replace(at, 2, "<\\/");

  std::string page(assets::page_html());
  // Small placeholders first, the data last: nothing inserted is searched for a later key.
  replace_once(page, "@THREE_REVISION@", assets::three_js_revision());
  replace_once(page, "/*@VIEWER_JS@*/", assets::viewer_js());
  replace_once(page, "/*@DRIFT_JS@*/", assets::drift_js());
  replace_once(page, "/*@ORBIT_CONTROLS_JS@*/", assets::orbit_controls_js());
  replace_once(page, "/*@THREE_JS@*/", assets::three_js());
  replace_once(page, "/*@DATA@*/", json);
  return page;
}

}  // namespace

std::string make_page(const Trajectory& tr, const io::Scenario* scenario,
                      const PageOptions& options) {
  return page_with(tr, scenario ? body_json(*scenario) : io::Json(nullptr),
                   scenario ? io::Json(scenario->source) : io::Json(nullptr), options);
}

std::string make_page(const Trajectory& tr, const io::OrbitScenario& scenario,
                      const PageOptions& options) {
  const Body& b = scenario.body;
  io::Json body{{"inertia", vec_json(b.inertia())},
                {"gyrostat", vec_json(b.gyrostat())},
                {"center_of_mass", vec_json(b.center_of_mass())},
                {"mass", b.mass()},
                {"shape", {{"kind", "inertia_ellipsoid"}}}};
  return page_with(tr, std::move(body), scenario.source, options);
}

}  // namespace newtop::viewer
