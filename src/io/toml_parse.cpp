#include "toml_parse.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>

#include "newtop/core/types.hpp"

namespace newtop::io {
namespace {

const char* const kAfterLineEnding =
    " right after a line-ending backslash (not read there: toml++ 3.3 mishandles it)";

bool is_ascii_space(unsigned char c) { return c == ' ' || c == '\t'; }
bool is_line_space(unsigned char c) { return is_ascii_space(c) || c == '\r' || c == '\n'; }

// Characters that may continue a dotted key (bare-key characters, blanks, dots; a quoted part is
// handled by the caller). A float such as 1.5e+3 is one such run with one dot.
bool continues_dotted_run(unsigned char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '+' || is_ascii_space(c);
}

/// One pass over the bytes in the lexical states of TOML that matter to the bounds: outside
/// strings, comments, and the four kinds of string. Tracks toml++'s own reading of the text up to
/// the first error toml++ would report: what lies beyond that error toml++ never reads.
class BoundsScanner {
 public:
  BoundsScanner(std::string_view text, const std::string& source) : t_(text), source_(source) {}

  void run() {
    if (t_.size() >= 3 && t_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // byte-order mark
    while (i_ < t_.size()) outside();
  }

 private:
  unsigned char at(std::size_t k = 0) const {
    return i_ + k < t_.size() ? static_cast<unsigned char>(t_[i_ + k]) : 0;
  }

  std::size_t run_of(char q) const {
    std::size_t k = 0;
    while (i_ + k < t_.size() && t_[i_ + k] == q) ++k;
    return k;
  }

  // "U+00E9", or the byte when it does not start a valid UTF-8 sequence.
  std::string character() const {
    const unsigned char c = at();
    const int len = c >= 0xF0 && c < 0xF5 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c < 0xE0 ? 2 : 0;
    char buf[32];
    unsigned cp = len == 2 ? c & 0x1Fu : len == 3 ? c & 0x0Fu : c & 0x07u;
    for (int k = 1; k < len; ++k) {
      if ((at(static_cast<std::size_t>(k)) & 0xC0u) != 0x80u) {
        cp = ~0u;
        break;
      }
      cp = (cp << 6) | (at(static_cast<std::size_t>(k)) & 0x3Fu);
    }
    if (len == 0 || cp == ~0u) {
      std::snprintf(buf, sizeof buf, "the byte 0x%02X (not UTF-8)", c);
    } else {
      std::snprintf(buf, sizeof buf, "the character U+%04X", cp);
    }
    return buf;
  }

  [[noreturn]] void fail(const std::string& what) const {
    const std::size_t end = std::min(i_, t_.size());
    const std::size_t line_start = t_.rfind('\n', end == 0 ? 0 : end - 1);
    const std::size_t from = line_start == std::string_view::npos || end == 0 ? 0 : line_start + 1;
    const long line = 1 + std::count(t_.begin(), t_.begin() + static_cast<long>(from), '\n');
    long column = 1;
    for (std::size_t k = from; k < end; ++k) column += (t_[k] & 0xC0) != 0x80 ? 1 : 0;
    std::ostringstream os;
    os << source_ << ":" << line << ":" << column << ": malformed TOML: " << what;
    throw InputError(os.str());
  }

  void outside() {
    const unsigned char c = at();
    if (c >= 0x80) fail(character() + " outside a string or comment");
    if (value_ && !is_line_space(c) && c != '"' && c != '\'' && c != '[' && c != '{' && c != '#') {
      bare_value();
    } else if (c == '#') {
      while (i_ < t_.size() && t_[i_] != '\n') ++i_;
      parts_ = 1;
    } else if (c == '"' || c == '\'') {
      const bool was_value = value_;
      value_ = false;
      if (run_of(static_cast<char>(c)) >= 3) {
        i_ += 3;
        c == '"' ? multi_line_basic() : multi_line_literal();
        parts_ = 1;
      } else {
        ++i_;
        single_line(static_cast<char>(c));  // may be a quoted part of a dotted key
        if (was_value) parts_ = 1;
      }
    } else if (c == '[' || c == '{') {
      if (++depth_ > kMaxTomlNesting) {
        fail("arrays and inline tables nested more than " + std::to_string(kMaxTomlNesting) +
             " deep");
      }
      // An array's elements are values; a table header's and an inline table's parts are keys.
      open_.push_back(c == '[' && value_ ? '[' : c == '[' ? 'h' : '{');
      value_ = open_.back() == '[';
      parts_ = 1;
      ++i_;
    } else if (c == ']' || c == '}') {
      depth_ = std::max(0, depth_ - 1);
      if (!open_.empty()) open_.pop_back();
      value_ = false;
      parts_ = 1;
      ++i_;
    } else if (c == '=') {
      value_ = true;
      parts_ = 1;
      ++i_;
    } else if (c == ',') {
      value_ = !open_.empty() && open_.back() == '[';
      parts_ = 1;
      ++i_;
    } else if (c == '\n') {
      if (open_.empty() || open_.back() != '[') value_ = false;
      parts_ = 1;
      ++i_;
    } else if (c == '.') {
      if (++parts_ > kMaxTomlKeyParts) {
        fail("a dotted key of more than " + std::to_string(kMaxTomlKeyParts) + " parts");
      }
      ++i_;
    } else {
      if (!continues_dotted_run(c)) parts_ = 1;
      ++i_;
    }
  }

  // A value that starts with neither a quote nor a bracket: toml++ 3.3 reads it as one token up to
  // a blank, a line break, `,`, `]`, `}` or `#`, whatever lies between — quotes included (they do
  // not start a string there) — asking of each character whether it ends the token, through the
  // whitespace table that is undefined for some non-ASCII characters.
  void bare_value() {
    while (i_ < t_.size()) {
      const unsigned char c = at();
      if (is_line_space(c) || c == ',' || c == ']' || c == '}' || c == '#') break;
      if (c >= 0x80) fail(character() + " in a value (numbers, booleans and dates are ASCII)");
      ++i_;
    }
    value_ = false;
    parts_ = 1;
  }

  void single_line(char quote) {
    while (i_ < t_.size() && t_[i_] != '\n') {
      if (quote == '"' && t_[i_] == '\\') {
        i_ += 2;  // toml++ checks nothing about the escaped character here but its escape code
        continue;
      }
      if (t_[i_++] == quote) return;
    }
  }

  // After `"""`. A backslash is followed by an escape or, with blanks up to the line break, trims
  // the following blanks and line breaks; toml++ asks whether the character after the backslash,
  // and the first one after the trimmed blanks, is whitespace.
  void multi_line_basic() {
    while (i_ < t_.size()) {
      if (t_[i_] == '\\') {
        ++i_;
        if (is_line_space(at())) {
          while (is_ascii_space(at())) ++i_;
          if (at() >= 0x80) fail(character() + kAfterLineEnding);
          while (is_line_space(at())) ++i_;
          if (at() >= 0x80) fail(character() + kAfterLineEnding);
        } else if (at() >= 0x80) {
          fail(character() + " after a backslash (not an escape sequence)");
        } else {
          ++i_;
        }
        continue;
      }
      if (close_multi_line('"')) return;
    }
  }

  void multi_line_literal() {
    while (i_ < t_.size()) {
      if (close_multi_line('\'')) return;
    }
  }

  // Three to five quotes close a multi-line string (the first one or two belong to it); fewer
  // are content. Returns true when closed; otherwise steps over the current byte(s).
  bool close_multi_line(char quote) {
    const std::size_t k = run_of(quote);
    if (k >= 3) {
      i_ += std::min<std::size_t>(k, 5);
      return true;
    }
    i_ += std::max<std::size_t>(k, 1);
    return false;
  }

  std::string_view t_;
  const std::string& source_;
  std::size_t i_ = 0;
  int depth_ = 0;
  int parts_ = 1;
  bool value_ = false;  ///< the next token is a value (after `=`, or an array's `[` or `,`)
  std::string open_;    ///< open brackets: '[' array, '{' inline table, 'h' table header
};

}  // namespace

std::string printable(std::string_view text, std::size_t max_chars) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const auto c = static_cast<unsigned char>(text[k]);
    // Cut only where a character starts.
    if (out.size() >= max_chars && (c & 0xC0u) != 0x80u) return out + "…";
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

void check_toml_bounds(std::string_view text, const std::string& source) {
  if (text.size() > kMaxTomlBytes) {
    throw InputError(source + ": malformed TOML: " + std::to_string(text.size()) +
                     " bytes, more than the " + std::to_string(kMaxTomlBytes) +
                     " bytes newtop reads from a TOML file");
  }
  BoundsScanner(text, source).run();
}

toml::table parse_toml(std::string_view text, const std::string& source) {
  check_toml_bounds(text, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source << ":" << e.source().begin.line << ":" << e.source().begin.column
       << ": malformed TOML: " << printable(e.description(), 200);
    throw InputError(os.str());
  }
}

}  // namespace newtop::io
