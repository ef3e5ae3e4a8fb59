#pragma once
// Internal: typed, checked access to one TOML table, with messages that name the file, the
// position, the section and the key, and a final check for unknown keys (typos).

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "newtop/core/types.hpp"

namespace newtop::io {

class TableReader {
 public:
  /// section: e.g. "body" (messages say "[body]"); empty for the top level.
  TableReader(const toml::table& table, std::string source, std::string section);

  bool has(const std::string& key) const;

  double number(const std::string& key);
  std::optional<double> optional_number(const std::string& key);
  std::int64_t integer(const std::string& key);
  std::optional<std::int64_t> optional_integer(const std::string& key);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::optional<std::string> optional_string(const std::string& key);
  Vec3 vec3(const std::string& key);
  std::optional<Vec3> optional_vec3(const std::string& key);
  Mat3 mat3(const std::string& key);
  /// An array of arrays of numbers, each row of length row_length (0: any).
  std::vector<std::vector<double>> rows(const std::string& key, std::size_t row_length);
  /// A sub-table; nullptr if absent. Throws if the key holds something else.
  const toml::table* table(const std::string& key);

  /// Throws InputError naming the first key that was never asked about (a typo or unknown key).
  void finish(const std::vector<std::string>& also_allowed = {}) const;

  /// An InputError for `key` located at its node (or at the table when absent).
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

  /// Re-raises an InputError of the library, whose message reads `key: what`, located at that key
  /// of this table; a message without such a key (e.g. already located) is re-raised unchanged.
  [[noreturn]] void relocate(const InputError& e) const;

  /// Calls make(); an InputError it throws is relocated to its key in this table.
  template <class F>
  auto checked(F&& make) const {
    try {
      return make();
    } catch (const InputError& e) {
      relocate(e);
    }
  }

 private:
  const toml::node& require(const std::string& key);
  std::string where(const toml::node* node) const;
  std::string label(const std::string& key) const;
  double as_number(const std::string& key, const toml::node& node) const;

  const toml::table& table_;
  std::string source_;
  std::string section_;
  mutable std::set<std::string> known_;  // every key asked about: the allowed keys
};

/// Describes a TOML node's type and value for "found …" in messages.
std::string describe(const toml::node& node);

}  // namespace newtop::io
