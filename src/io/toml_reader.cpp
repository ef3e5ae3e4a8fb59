#include "toml_reader.hpp"

#include <cmath>
#include <sstream>

namespace newtop::io {

std::string describe(const toml::node& node) {
  std::ostringstream os;
  if (node.is_array()) {
    os << "an array of " << node.as_array()->size();
  } else if (node.is_table()) {
    os << "a table";
  } else if (node.is_string()) {
    os << "the string \"" << node.as_string()->get() << "\"";
  } else if (node.is_boolean()) {
    os << "the boolean " << (node.as_boolean()->get() ? "true" : "false");
  } else if (node.is_integer()) {
    os << node.as_integer()->get();
  } else if (node.is_floating_point()) {
    os << format_number(node.as_floating_point()->get());
  } else {
    os << "a " << node.type();
  }
  return os.str();
}

TableReader::TableReader(const toml::table& table, std::string source, std::string section)
    : table_(table), source_(std::move(source)), section_(std::move(section)) {}

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

double TableReader::as_number(const std::string& key, const toml::node& node) const {
  if (!node.is_number()) fail(key, "expected a number, found " + describe(node));
  const double x = node.value<double>().value();
  if (!std::isfinite(x)) fail(key, "expected a finite number, found " + format_number(x));
  return x;
}

double TableReader::number(const std::string& key) { return as_number(key, require(key)); }

std::optional<double> TableReader::optional_number(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return number(key);
}

std::int64_t TableReader::integer(const std::string& key) {
  const toml::node& n = require(key);
  if (!n.is_integer()) fail(key, "expected an integer, found " + describe(n));
  return n.as_integer()->get();
}

std::optional<std::int64_t> TableReader::optional_integer(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return integer(key);
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
    const toml::node& e = *a->get(i);
    if (!e.is_number()) {
      fail(key, "expected an array of 3 numbers, found element " + std::to_string(i + 1) + " = " +
                    describe(e));
    }
    v[static_cast<Eigen::Index>(i)] = e.value<double>().value();
  }
  if (!v.allFinite()) fail(key, "expected finite numbers, found " + format_vector(v));
  return v;
}

std::optional<Vec3> TableReader::optional_vec3(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return vec3(key);
}

std::vector<std::vector<double>> TableReader::rows(const std::string& key, std::size_t row_length) {
  const toml::node& n = require(key);
  const toml::array* a = n.as_array();
  if (!a) fail(key, "expected an array of arrays of numbers, found " + describe(n));
  std::vector<std::vector<double>> out;
  for (std::size_t r = 0; r < a->size(); ++r) {
    const toml::array* row = a->get(r)->as_array();
    if (!row || (row_length && row->size() != row_length)) {
      fail(key, "expected row " + std::to_string(r + 1) + " to be an array of " +
                    (row_length ? std::to_string(row_length) + " " : "") + "numbers, found " +
                    describe(*a->get(r)));
    }
    std::vector<double> vals;
    for (std::size_t c = 0; c < row->size(); ++c) {
      const toml::node& e = *row->get(c);
      if (!e.is_number()) {
        fail(key, "expected numbers, found " + describe(e) + " at row " + std::to_string(r + 1) +
                      ", column " + std::to_string(c + 1));
      }
      const double x = e.value<double>().value();
      if (!std::isfinite(x)) {
        fail(key, "expected finite numbers, found " + format_number(x) + " at row " +
                      std::to_string(r + 1) + ", column " + std::to_string(c + 1));
      }
      vals.push_back(x);
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

void TableReader::finish(const std::vector<std::string>& also_allowed) const {
  for (const auto& [k, node] : table_) {
    const std::string key(k.str());
    std::set<std::string> allowed = known_;
    allowed.insert(also_allowed.begin(), also_allowed.end());
    if (allowed.count(key)) continue;
    std::string known;
    for (const auto& a : allowed) known += (known.empty() ? "" : ", ") + a;
    throw InputError(where(&node) + ": " + label(key) + ": unknown key" +
                     (known.empty() ? std::string() : " (expected one of: " + known + ")"));
  }
}

}  // namespace newtop::io
