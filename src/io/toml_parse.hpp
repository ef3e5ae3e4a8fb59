#pragma once
// Internal: TOML text to a toml::table, bounded before the parser sees it.
//
// toml++ (3.3) is trusted only inside these bounds. Checked first, in one pass over the bytes:
// - size: at most kMaxTomlBytes;
// - nesting: arrays and inline tables at most kMaxTomlNesting deep, dotted keys of at most
//   kMaxTomlKeyParts parts (a 50,000-part dotted key overflows the stack inside toml++);
// - characters: non-ASCII only inside strings and comments, and never where toml++ 3.3 asks
//   whether it is whitespace (after a value or key, after a backslash in a multi-line basic
//   string, or where a line-ending backslash trims): there its generated whitespace table reaches
//   __builtin_unreachable for U+00A1–U+0499, U+2C3E–U+3037 and U+FC26–U+FEFE. TOML allows no
//   non-ASCII character outside strings and comments, and none where whitespace is expected, so
//   valid files lose nothing.

#include <toml++/toml.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace newtop::io {

inline constexpr std::size_t kMaxTomlBytes = std::size_t{4} << 20;  // 4 MiB
inline constexpr int kMaxTomlNesting = 16;
inline constexpr int kMaxTomlKeyParts = 8;

/// Throws InputError `SOURCE:LINE:COL: malformed TOML: …` when the text breaks one of the bounds
/// above; otherwise returns and the text is safe to give to toml::parse.
void check_toml_bounds(std::string_view text, const std::string& source);

/// Text from a file made fit for a one-line message: control characters escaped (\n, \xNN) and
/// anything beyond `max_chars` bytes cut to "…".
std::string printable(std::string_view text, std::size_t max_chars = 64);

/// check_toml_bounds, then toml::parse; a parse error becomes InputError
/// `SOURCE:LINE:COL: malformed TOML: …`.
toml::table parse_toml(std::string_view text, const std::string& source);

}  // namespace newtop::io
