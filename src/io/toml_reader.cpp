#include "toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "newtop/io/suggest.hpp"
#include "toml_parse.hpp"

namespace newtop::io {
namespace {

// A float written without a fractional part still reads as one: "3.0", not "3".
std::string float_text(double x) {
  std::string s = format_number(x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

// The double equal to n, if there is one (every integer up to 2^53, then fewer and fewer).
std::optional<double> exact_double(std::int64_t n) {
  const double d = static_cast<double>(n);
  if (d >= 0x1p63) return std::nullopt;  // n < 2^63 rounded up to 2^63
  if (static_cast<std::int64_t>(d) != n) return std::nullopt;
  return d;
}

std::string list(const std::vector<std::string>& names, const char* open, const char* close) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + std::string(open) + n + close;
  return out;
}

}  // namespace

std::string describe(const toml::node& node) {
  std::ostringstream os;
  if (node.is_array()) {
    os << "an array of " << node.as_array()->size();
  } else if (node.is_table()) {
    os << "a table";
  } else if (node.is_string()) {
    os << "the string \"" << printable(node.as_string()->get()) << "\"";
  } else if (node.is_boolean()) {
    os << "the boolean " << (node.as_boolean()->get() ? "true" : "false");
  } else if (node.is_integer()) {
    os << "the integer " << node.as_integer()->get();
  } else if (node.is_floating_point()) {
    os << "the float " << float_text(node.as_floating_point()->get());
  } else {
    os << "a " << node.type();  // date, time, date-time
  }
  return os.str();
}

TableReader::TableReader(const toml::table& table, std::string source, std::string section)
    : table_(table), source_(std::move(source)), section_(std::move(section)) {}

void TableReader::check_keys(const std::vector<std::string>& vocabulary) const {
  for (const auto& [k, node] : table_) {
    const std::string key(k.str());
    if (std::find(vocabulary.begin(), vocabulary.end(), key) != vocabulary.end()) continue;
    const auto close = closest_name(key, vocabulary);
    std::string msg;
    if (section_.empty() && node.is_table()) {
      msg = "unknown section [" + printable(key) + "]" +
            (close ? " — did you mean [" + *close + "]?"
                   : " (expected " + list(vocabulary, "[", "]") + ")");
    } else {
      msg = "unknown key '" + printable(key) + "' " +
            (section_.empty() ? "at the top level" : "in [" + section_ + "]") +
            (close              ? " — did you mean '" + *close + "'?"
             : section_.empty() ? " (expected the sections " + list(vocabulary, "[", "]") + ")"
                                : " (expected one of " + list(vocabulary, "", "") + ")");
    }
    std::ostringstream at;  // the key's own position
    at << source_;
    if (k.source().begin.line > 0)
      at << ":" << k.source().begin.line << ":" << k.source().begin.column;
    throw InputError(at.str() + ": " + msg);
  }
}

void TableReader::only(const std::vector<std::string>& allowed,
                       const std::vector<std::string>& vocabulary,
                       const std::string& reason) const {
  for (const auto& key : vocabulary) {
    if (!table_.contains(key) || std::find(allowed.begin(), allowed.end(), key) != allowed.end()) {
      continue;
    }
    std::vector<std::string> takes;
    for (const auto& a : allowed) {
      if (a != "kind") takes.push_back(a);
    }
    fail(key, "conflicts with " + reason +
                  (takes.empty() ? std::string() : " (which takes " + list(takes, "", "") + ")"));
  }
}

bool TableReader::has(const std::string& key) const {
  known_.insert(key);
  return table_.contains(key);
}

std::string TableReader::where(const toml::node* node) const {
  const auto& src = node ? node->source() : table_.source();
  std::ostringstream os;
  os << source_;
  if (src.begin.line > 0) os << ":" << src.begin.line << ":" << src.begin.column;
  return os.str();
}

std::string TableReader::label(const std::string& key) const {
  return section_.empty() ? key : "[" + section_ + "] " + key;
}

void TableReader::fail(const std::string& key, const std::string& what) const {
  throw InputError(where(table_.get(key)) + ": " + label(key) + ": " + what);
}

void TableReader::fail_at(const toml::node& node, const std::string& name,
                          const std::string& what) const {
  throw InputError(where(&node) + ": " + label(name) + ": " + what);
}

void TableReader::relocate(const InputError& e) const {
  const std::string msg = e.what();
  const auto colon = msg.find(": ");
  const std::string key = msg.substr(0, colon);
  const bool is_key =
      colon != std::string::npos && !key.empty() &&
      key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789") ==
          std::string::npos;
  if (!is_key) throw e;
  fail(key, msg.substr(colon + 2));
}

const toml::node& TableReader::require(const std::string& key) {
  known_.insert(key);
  const toml::node* node = table_.get(key);
  if (!node) throw InputError(where(nullptr) + ": " + label(key) + ": missing (required)");
  return *node;
}

double TableReader::element_number(const std::string& key, const toml::node& node,
                                   const std::string& what) const {
  const std::string at = what.empty() ? "" : what + ": ";
  if (const auto* i = node.as_integer()) {
    const auto d = exact_double(i->get());
    if (!d) {
      fail_at(node, key,
              at + "expected a number that a double holds exactly, found the integer " +
                  std::to_string(i->get()) + " (the nearest double is " +
                  float_text(static_cast<double>(i->get())) +
                  "; write it with a decimal point to accept the rounding)");
    }
    return *d;
  }
  const auto* f = node.as_floating_point();
  if (!f) fail_at(node, key, at + "expected a number, found " + describe(node));
  if (!std::isfinite(f->get())) {
    fail_at(node, key, at + "expected a finite number, found " + format_number(f->get()));
  }
  return f->get();
}

double TableReader::number(const std::string& key) { return element_number(key, require(key), ""); }

std::optional<double> TableReader::optional_number(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return number(key);
}

std::int64_t TableReader::integer(const std::string& key, std::int64_t lo, std::int64_t hi) {
  const toml::node& n = require(key);
  const auto* i = n.as_integer();
  if (!i || i->get() < lo || i->get() > hi) {
    fail(key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                  "], found " + describe(n));
  }
  return i->get();
}

bool TableReader::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const toml::node& n = require(key);
  if (!n.is_boolean()) fail(key, "expected true or false, found " + describe(n));
  return n.as_boolean()->get();
}

std::string TableReader::string(const std::string& key) {
  const toml::node& n = require(key);
  if (!n.is_string()) fail(key, "expected a string, found " + describe(n));
  return n.as_string()->get();
}

std::optional<std::string> TableReader::optional_string(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return string(key);
}

Vec3 TableReader::vec3(const std::string& key) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a || a->size() != 3) fail(key, "expected an array of 3 numbers, found " + describe(n));
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i) {
    v[static_cast<Eigen::Index>(i)] =
        element_number(key, *a->get(i), "element " + std::to_string(i + 1));
  }
  return v;
}

std::vector<double> TableReader::numbers(const std::string& key, std::size_t length) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a || a->size() != length) {
    fail(key, "expected an array of " + std::to_string(length) + " numbers, found " + describe(n));
  }
  std::vector<double> v(length);
  for (std::size_t i = 0; i < length; ++i) {
    v[i] = element_number(key, *a->get(i), "element " + std::to_string(i + 1));
  }
  return v;
}

std::optional<Vec3> TableReader::optional_vec3(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return vec3(key);
}

std::vector<double> TableReader::numbers(const std::string& key) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a || a->empty()) fail(key, "expected a non-empty array of numbers, found " + describe(n));
  std::vector<double> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    out.push_back(element_number(key, *a->get(i), "element " + std::to_string(i + 1)));
  }
  return out;
}

std::vector<std::string> TableReader::strings(const std::string& key) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a || a->empty()) fail(key, "expected a non-empty array of strings, found " + describe(n));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const auto* v = a->get(i)->as_string();
    if (!v) {
      fail_at(*a->get(i), key + "[" + std::to_string(i) + "]",
              "expected a string, found " + describe(*a->get(i)));
    }
    out.push_back(v->get());
  }
  return out;
}

std::vector<std::vector<double>> TableReader::rows(const std::string& key, std::size_t row_length) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a) fail(key, "expected an array of arrays of numbers, found " + describe(n));
  std::vector<std::vector<double>> out;
  for (std::size_t r = 0; r < a->size(); ++r) {
    const toml::array* row = a->get(r)->as_array();
    if (!row || (row_length && row->size() != row_length)) {
      fail(key, "row " + std::to_string(r + 1) + ": expected an array of " +
                    (row_length ? std::to_string(row_length) + " " : "") + "numbers, found " +
                    describe(*a->get(r)));
    }
    std::vector<double> vals;
    for (std::size_t c = 0; c < row->size(); ++c) {
      vals.push_back(element_number(
          key, *row->get(c), "row " + std::to_string(r + 1) + ", column " + std::to_string(c + 1)));
    }
    out.push_back(std::move(vals));
  }
  return out;
}

Mat3 TableReader::mat3(const std::string& key) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a || a->size() != 3) fail(key, "expected a 3×3 array of numbers, found " + describe(n));
  const auto r = rows(key, 3);
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[static_cast<size_t>(i)][static_cast<size_t>(j)];
  return m;
}

const toml::table* TableReader::table(const std::string& key) {
  if (!has(key)) return nullptr;
  const toml::node& n = require(key);
  if (!n.is_table()) fail(key, "expected a table, found " + describe(n));
  return n.as_table();
}

void TableReader::finish() const {
  for (const auto& [k, node] : table_) {
    const std::string key(k.str());
    if (!known_.count(key)) {
      throw InputError(where(&node) + ": " + label(printable(key)) + ": not used by this section");
    }
  }
}

}  // namespace newtop::io
