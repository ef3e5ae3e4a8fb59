// The swept values of a point written into the base scenario's text (docs/sweep.md): scenario
// keys `section.key[i]` in place, the inertia ratios body.k_R, body.k_Y as the three moments.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "../io/toml_parse.hpp"
#include "../io/toml_reader.hpp"
#include "newtop/orbit/debra_delp.hpp"
#include "sweep_points.hpp"

namespace newtop::sweep {
namespace {

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

std::string values_label(const SweepFile& s, const std::vector<double>& v, std::size_t index) {
  std::string label = "point " + std::to_string(index + 1);
  for (std::size_t k = 0; k < v.size(); ++k) {
    label += (k ? ", " : " (") + s.axes[k].key + " = " + format_number(v[k]);
  }
  return label + (v.empty() ? "" : ")");
}

bool is_ratio_key(const std::string& key) { return key == "body.k_R" || key == "body.k_Y"; }

/// The inertia ratios k_R = (B − C)/A, k_Y = (B − A)/C of the point (docs/orbit.md §8; the base's
/// for a ratio not swept) as the three moments of [body] inertia, B kept: the spans of the three
/// numbers and their new texts. Nothing when no ratio is swept.
void set_ratios(const SweepFile& s, const toml::table& base, std::size_t index,
                const std::vector<double>& values,
                std::vector<std::pair<std::size_t, std::size_t>>& spans,
                std::vector<std::string>& texts) {
  std::optional<double> k_R, k_Y;
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    if (s.axes[k].key == "body.k_R") k_R = values[k];
    if (s.axes[k].key == "body.k_Y") k_Y = values[k];
  }
  if (!k_R && !k_Y) return;
  const toml::array* a = base["body"]["inertia"].as_array();
  const char* key = k_R ? "body.k_R" : "body.k_Y";
  if (!a || a->size() != 3) {
    throw InputError(s.source + ": [[axes]] key '" + key +
                     "': expected [body] inertia = [A, B, C] (roll, pitch, yaw) in " +
                     s.base_source + ", found " +
                     (a ? io::describe(*a) : std::string("no [body] inertia")));
  }
  Vec3 I;
  for (int i = 0; i < 3; ++i) {
    const toml::node& n = *a->get(static_cast<std::size_t>(i));
    if (!n.is_number()) {
      throw InputError(s.source + ": [[axes]] key '" + key +
                       "': expected [body] inertia of three numbers, found " + io::describe(n));
    }
    I[i] = n.value<double>().value();
    spans.emplace_back(byte_offset(s.base_text, n.source().begin),
                       byte_offset(s.base_text, n.source().end));
  }
  Vec3 moments;
  try {
    moments = I[1] * inertia_from_ratios(k_R.value_or((I[1] - I[2]) / I[0]),
                                         k_Y.value_or((I[1] - I[0]) / I[2]));
  } catch (const InputError& e) {
    throw InputError(s.source + ": " + values_label(s, values, index) + ": " + e.what());
  }
  for (int i = 0; i < 3; ++i) texts.push_back(format_number(moments[i]));
}

}  // namespace

/// The base scenario's text with the swept scenario keys of point `values` written in place of
/// their values (17 significant digits): the rest of the file, its comments and its line numbers
/// stay as they are. toml++ locates each value (its source region).
std::string set_keys(const SweepFile& s, std::size_t index) {
  const std::vector<double> values = point_values(s, index);
  const toml::table base = io::parse_toml(s.base_text, s.base_source);
  std::vector<std::pair<std::size_t, std::size_t>> spans;  // [begin, end) of each value
  std::vector<std::string> texts;
  set_ratios(s, base, index, values, spans, texts);
  for (std::size_t k = 0; k < s.axes.size(); ++k) {
    const std::string& key = s.axes[k].key;
    if (key == "stability.omega" || is_ratio_key(key)) continue;
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
  return values_label(s, point_values(s, index), index);
}

bool wants(const SweepFile& s, const std::string& q) {
  return std::find(s.quantities.begin(), s.quantities.end(), q) != s.quantities.end();
}

void rethrow_for_point(const SweepFile& s, std::size_t index, const InputError& e) {
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

}  // namespace newtop::sweep
