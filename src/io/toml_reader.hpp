#pragma once
// Internal: typed, checked access to one TOML table, with messages that name the file, the
// position, the section and the key; unknown keys (typos) and conflicting keys are reported
// before anything is read.

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

  /// Throws for the first key of the table that is none of `vocabulary` (every key the section can
  /// ever hold): `unknown key 'inertai' in [body] — did you mean 'inertia'?`, or the list of
  /// allowed keys when none is close. At the top level the vocabulary names sections.
  void check_keys(const std::vector<std::string>& vocabulary) const;

  /// Throws for the first key present that is in `vocabulary` but not in `allowed`:
  /// `[field] g: conflicts with kind = "brun" (which takes N, plane_offset)`, `reason` being
  /// `kind = "brun"`.
  void only(const std::vector<std::string>& allowed, const std::vector<std::string>& vocabulary,
            const std::string& reason) const;

  bool has(const std::string& key) const;

  /// A number; an integer must convert to a double exactly (|n| ≤ 2^53 or a multiple of the
  /// spacing of doubles there), so that 9007199254740993 is refused rather than rounded.
  double number(const std::string& key);
  std::optional<double> optional_number(const std::string& key);
  /// An integer (a float such as 3.0 is refused), in [lo, hi].
  std::int64_t integer(const std::string& key, std::int64_t lo, std::int64_t hi);
  /// The value of a number node inside `key` (an array element): exact for integers, finite;
  /// `what` locates it in messages ("row 2, column 1").
  double element_number(const std::string& key, const toml::node& node,
                        const std::string& what) const;
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::optional<std::string> optional_string(const std::string& key);
  Vec3 vec3(const std::string& key);
  std::optional<Vec3> optional_vec3(const std::string& key);
  Mat3 mat3(const std::string& key);
  /// A non-empty array of numbers (each finite, integers exact).
  std::vector<double> numbers(const std::string& key);
  /// An array of exactly `length` numbers.
  std::vector<double> numbers(const std::string& key, std::size_t length);
  /// A non-empty array of strings.
  std::vector<std::string> strings(const std::string& key);
  /// An array of arrays of numbers, each row of length row_length (0: any).
  std::vector<std::vector<double>> rows(const std::string& key, std::size_t row_length);
  /// A sub-table; nullptr if absent. Throws if the key holds something else.
  const toml::table* table(const std::string& key);

  /// Throws InputError naming the first key that was never asked about (a key the section's
  /// reading left unused).
  void finish() const;

  /// An InputError for `key` located at its node (or at the table when absent).
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  /// An InputError labelled `name` (e.g. "terms[2]") located at `node`.
  [[noreturn]] void fail_at(const toml::node& node, const std::string& name,
                            const std::string& what) const;

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

  const std::string& section() const { return section_; }

 private:
  const toml::node& require(const std::string& key);
  std::string where(const toml::node* node) const;
  std::string label(const std::string& key) const;

  const toml::table& table_;
  std::string source_;
  std::string section_;
  mutable std::set<std::string> known_;  // every key asked about
};

/// Describes a TOML node's type and value for "found …" in messages.
std::string describe(const toml::node& node);

}  // namespace newtop::io
