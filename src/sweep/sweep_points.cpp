// The points of a sweep: the base scenario with the swept keys set, and the quantities computed
// there (docs/sweep.md).

#include "sweep_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "../io/toml_parse.hpp"
#include "../io/toml_reader.hpp"
#include "newtop/analysis/equilibria.hpp"
#include "newtop/analysis/stability.hpp"
#include "newtop/analysis/stability_spin.hpp"
#include "newtop/integrate/run.hpp"
#include "newtop/model/integrals.hpp"
#include "newtop/phase/chaos.hpp"

namespace newtop::sweep {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// `section.key` or `section.key[i]` of the base scenario, located in its table.
struct KeyPath {
  std::string table, key;
  std::optional<std::size_t> index;
};

KeyPath split_key(const SweepFile& s, const std::string& key) {
  const std::size_t dot = key.find('.');
  KeyPath p;
  if (dot == std::string::npos || dot == 0 || dot + 1 == key.size()) {
    throw InputError(s.source + ": [[axes]] key '" + key +
                     "': expected section.key or section.key[i] (e.g. body.inertia[2])");
  }
  p.table = key.substr(0, dot);
  p.key = key.substr(dot + 1);
  if (const std::size_t open = p.key.find('['); open != std::string::npos) {
    const std::string digits = p.key.substr(open + 1, p.key.size() - open - 2);
    if (p.key.back() != ']' || digits.empty() ||
        digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6) {
      throw InputError(s.source + ": [[axes]] key '" + key + "': expected an index [i], found '" +
                       p.key.substr(open) + "'");
    }
    p.index = std::stoul(digits);
    p.key = p.key.substr(0, open);
  }
  return p;
}

/// The byte offset in `text` of a toml++ source position (1-based line, 1-based column counted in
/// code points).
std::size_t byte_offset(const std::string& text, const toml::source_position& pos) {
  std::size_t i = 0;
  for (toml::source_index line = 1; line < pos.line && i < text.size(); ++i) {
    if (text[i] == '\n') ++line;
  }
  for (toml::source_index column = 1; column < pos.column && i < text.size(); ++column) {
    ++i;  // past one code point: its lead byte and its continuation bytes
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
  }
  return i;
}

/// The base scenario's text with the swept scenario keys of point `values` written in place of
/// their values (17 significant digits): the rest of the file, its comments and its line numbers
/// stay as they are. toml++ locates each value (its source region).
std::string set_keys(const SweepFile& s, const std::vector<double>& values) {
  const toml::table base = io::parse_toml(s.base_text, s.base_source);
  std::vector<std::pair<std::size_t, std::size_t>> spans;  // [begin, end) of each value
  std::vector<std::string> texts;
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    const std::string& key = s.axes[k].key;
    if (key == "stability.omega") continue;
    const KeyPath p = split_key(s, key);
    const toml::table* t = base[p.table].as_table();
    const toml::node* n = t ? t->get(p.key) : nullptr;
    if (!n) {
      throw InputError(s.source + ": [[axes]] key '" + key + "': expected a key of " +
                       s.base_source + ", found no [" + p.table + "] " + p.key + " there");
    }
    if (p.index) {
      const toml::array* a = n->as_array();
      if (!a) {
        throw InputError(s.source + ": [[axes]] key '" + key + "': expected an array at [" +
                         p.table + "] " + p.key + ", found " + io::describe(*n));
      }
      if (*p.index >= a->size()) {
        throw InputError(s.source + ": [[axes]] key '" + key + "': expected an index below " +
                         std::to_string(a->size()) + ", found " + std::to_string(*p.index));
      }
      n = a->get(*p.index);
    }
    if (!n->is_number()) {
      throw InputError(s.source + ": [[axes]] key '" + key + "': expected a numeric key, found " +
                       io::describe(*n));
    }
    spans.emplace_back(byte_offset(s.base_text, n->source().begin),
                       byte_offset(s.base_text, n->source().end));
    // An integer key of the base (max_steps, every) keeps an integer literal for an integral
    // value: 1e6 is written 1000000, not 1e+06, which the scenario's integer keys would refuse.
    const double v = values[k];
    if (n->is_integer() && v == std::trunc(v) && std::abs(v) < 9007199254740992.0) {
      texts.push_back(std::to_string(static_cast<std::int64_t>(v)));
    } else {
      texts.push_back(format_number(v));
    }
  }
  // From the last value to the first, so that the earlier offsets stay valid.
  std::vector<std::size_t> order(spans.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return spans[a].first > spans[b].first; });
  std::string text = s.base_text;
  for (const std::size_t i : order) {
    text.replace(spans[i].first, spans[i].second - spans[i].first, texts[i]);
  }
  return text;
}

std::string point_label(const SweepFile& s, std::size_t index) {
  const std::vector<double> v = point_values(s, index);
  std::string label = "point " + std::to_string(index + 1);
  for (std::size_t k = 0; k < v.size(); ++k) {
    label += (k ? ", " : " (") + s.axes[k].key + " = " + format_number(v[k]);
  }
  return label + (v.empty() ? "" : ")");
}

/// The state `stability` analyses: the spin about the axis at Ω, or the scenario's own state
/// polished to a fixed point. Throws InputError when it is not a fixed point.
State stability_state(const io::Scenario& sc, const StabilityOptions& o) {
  if (o.axis) {
    const State x = principal_spin(sc.model.body(), *o.axis, o.omega);
    const double res = fixed_point_residual(sc.model, x);
    if (!(res <= kFixedPointTolerance)) {
      throw InputError(std::string("stability: the spin about ") + "xyz"[*o.axis] +
                       " is not a permanent rotation (residual " + format_number(res) +
                       "; M g r0 is not along the axis)");
    }
    return x;
  }
  const PolishedFixedPoint p = polish_fixed_point(sc.model, sc.initial);
  if (!p.converged) {
    throw InputError("stability: [initial] is not an equilibrium or a permanent rotation " +
                     std::string("(residual ") + format_number(p.residual_given) +
                     "); give [stability] axis");
  }
  return p.state;
}

bool wants(const SweepFile& s, const std::string& q) {
  return std::find(s.quantities.begin(), s.quantities.end(), q) != s.quantities.end();
}

/// One run of the point's scenario: the final state and the drift of the integrals.
struct RunResult {
  Outcome outcome;
  IntegralsDrift drift;
};

RunResult run(const SweepFile& s, const io::Scenario& sc) {
  const MethodSettings method = io::resolve_method(sc, s.integrate);
  const double t1 = io::resolve_t_end(sc, s.integrate);
  IntegrateOptions options;
  if (sc.integrate.max_steps) options.max_steps = *sc.integrate.max_steps;
  RunResult r;
  r.drift.observe(integrals(sc.model, sc.initial));
  auto observe = [&](double, const State& x) { r.drift.observe(integrals(sc.model, x)); };
  r.outcome = run_method(method, sc.model, sc.initial, sc.integrate.t0, t1, options, observe);
  return r;
}

}  // namespace

std::vector<std::string> quantity_columns(const SweepFile& s) {
  std::vector<std::string> c;
  for (const std::string& q : s.quantities) {
    if (q == "stability")
      c.insert(c.end(), {"linearly_stable", "lyapunov_stable", "max_real_part"});
    if (q == "drift") c.insert(c.end(), {"drift_energy", "drift_area", "drift_geometric"});
    if (q == "equilibria") c.insert(c.end(), {"equilibria_count", "minima", "saddles", "maxima"});
    if (q == "final_state") c.insert(c.end(), {"t", "p", "q", "r", "gamma1", "gamma2", "gamma3"});
    if (q == "megno") c.push_back("megno");
    if (q == "lyapunov_max") c.push_back("lyapunov_max");
  }
  return c;
}

/// Moves the initial state onto the sweep's energy level: ω_i with ½ I_i ω_i² = h − V(γ) −
/// ½ Σ_{j≠i} I_j ω_j², of the sign asked for (m_i = I_i ω_i + k_i). A level out of reach at this
/// point (the right side negative) leaves a non-finite state: the point is `off_level`.
void move_onto_level(const EnergyLevel& level, io::Scenario& sc) {
  const Body& body = sc.model.body();
  const int i = level.component;
  const Vec3 w = omega(body, sc.initial);
  double rest = level.energy - potential(sc.model, sc.initial.gamma);
  for (int j = 0; j < 3; ++j) {
    if (j != i) rest -= 0.5 * body.inertia()[j] * w[j] * w[j];
  }
  const double wi2 = 2.0 * rest / body.inertia()[i];
  if (!(wi2 >= 0.0)) {
    sc.initial.m.setConstant(kNaN);
    return;
  }
  sc.initial.m[i] = body.inertia()[i] * (level.sign * std::sqrt(wi2)) + body.gyrostat()[i];
}

io::Scenario point_scenario(const SweepFile& s, std::size_t index, StabilityOptions* options) {
  const std::vector<double> values = point_values(s, index);
  const std::string text = set_keys(s, values);
  if (options) {
    *options = s.stability;
    for (std::size_t k = 0; k < s.axes.size(); ++k) {
      if (s.axes[k].key == "stability.omega") options->omega = values[k];
    }
  }
  try {
    io::Scenario sc = io::parse_scenario(text, s.base_source);
    if (s.level) move_onto_level(*s.level, sc);
    return sc;
  } catch (const InputError& e) {
    // The column may have moved where a value was rewritten on the line: name the file alone.
    std::string what = e.what();
    const std::string prefix = s.base_source + ":";
    if (what.rfind(prefix, 0) == 0) {
      const std::size_t end = what.find_first_not_of("0123456789:", prefix.size());
      if (end != std::string::npos && end > prefix.size()) {
        what = s.base_source + ":" + what.substr(end);
      }
    }
    throw InputError(s.source + ": " + point_label(s, index) + ": " + what);
  }
}

void check_points(SweepFile& s) {
  const std::size_t n = point_count(s);
  for (std::size_t i = 0; i < n; ++i) {
    StabilityOptions o;
    const io::Scenario sc = point_scenario(s, i, &o);
    if (i == 0) {
      s.input_files = {s.source};
      s.input_files.insert(s.input_files.end(), sc.input_files.begin(), sc.input_files.end());
    }
    if (s.level && !is_finite(sc.initial)) continue;  // off the level: reported per point
    try {
      if (wants(s, "stability")) stability_state(sc, o);
      if (wants(s, "megno") || wants(s, "lyapunov_max")) {
        phase::check_tangent_method(io::resolve_method(sc, s.integrate));
      }
      if (wants(s, "drift") || wants(s, "final_state") || wants(s, "megno") ||
          wants(s, "lyapunov_max")) {
        io::resolve_method(sc, s.integrate);
        const double t1 = io::resolve_t_end(sc, s.integrate);
        check_time_span(sc.integrate.t0, t1);
        if (t1 == sc.integrate.t0) {  // no run: its drift and indicators would be zeros
          throw InputError(
              "t_end: expected a time different from t0 = " + format_number(sc.integrate.t0) +
              ", found " + format_number(t1) + " (a run of no length)");
        }
      }
    } catch (const InputError& e) {
      throw InputError(s.source + ": " + point_label(s, i) + ": " + e.what());
    }
  }
}

PointResult evaluate_point(const SweepFile& s, std::size_t index) {
  StabilityOptions o;
  const io::Scenario sc = point_scenario(s, index, &o);
  PointResult r{"ok", {}};
  if (s.level && !is_finite(sc.initial)) return {"off_level", {}};
  std::optional<phase::ChaosResult> chaos;
  if (wants(s, "megno") || wants(s, "lyapunov_max")) {  // one tangent run for both (newtop chaos)
    const MethodSettings method = io::resolve_method(sc, s.integrate);
    const double t1 = io::resolve_t_end(sc, s.integrate);
    IntegrateOptions options;
    if (sc.integrate.max_steps) options.max_steps = *sc.integrate.max_steps;
    chaos = phase::chaos_run(method, sc.model, sc.initial, sc.integrate.t0, t1, options, false);
    if (chaos->outcome.status != Status::finished) {
      return {std::string(to_string(chaos->outcome.status)), {}};
    }
  }
  std::optional<RunResult> traj;
  if (wants(s, "drift") || wants(s, "final_state")) {
    traj = run(s, sc);
    if (traj->outcome.status != Status::finished)
      return {std::string(to_string(traj->outcome.status)), {}};
  }
  for (const std::string& q : s.quantities) {
    if (q == "stability") {
      const Spectrum sp = linear_stability(sc.model, stability_state(sc, o));
      r.values.push_back(sp.linearly_stable ? 1.0 : 0.0);
      r.values.push_back(sp.lyapunov_stable ? (*sp.lyapunov_stable ? 1.0 : 0.0) : kNaN);
      r.values.push_back(sp.max_real_part);
    } else if (q == "drift") {
      r.values.insert(r.values.end(), {traj->drift.max_drift.energy, traj->drift.max_drift.area,
                                       traj->drift.max_drift.geometric});
    } else if (q == "equilibria") {
      const EquilibriumSet e = find_equilibria(sc.model);
      r.values.insert(r.values.end(),
                      {static_cast<double>(e.equilibria.size()), static_cast<double>(e.minima),
                       static_cast<double>(e.saddles), static_cast<double>(e.maxima)});
    } else if (q == "megno") {
      r.values.push_back(chaos->indicators.megno);
    } else if (q == "lyapunov_max") {
      r.values.push_back(chaos->indicators.lyapunov_max);
    } else if (q == "final_state") {
      const State& x = traj->outcome.state;
      const Vec3 w = omega(sc.model.body(), x);
      r.values.insert(r.values.end(), {traj->outcome.t, w.x(), w.y(), w.z(), x.gamma.x(),
                                       x.gamma.y(), x.gamma.z()});
    }
  }
  return r;
}

}  // namespace newtop::sweep
