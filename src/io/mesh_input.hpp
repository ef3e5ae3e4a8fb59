#pragma once
// Internal: the pieces every strict file reader of io/ shares (meshes, TetGen, point-mass CSV):
// bounded reading of regular files, lines and tokens, exact numbers, located one-line errors.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "newtop/io/mesh.hpp"

namespace newtop::io::detail {

/// The bytes of a regular file of at most kMaxInputBytes. Refuses, in one line naming the file,
/// a missing or unreadable file, a directory, a device, a FIFO or a socket (never blocks on them).
std::string read_input_file(const std::string& path);

/// Throws what read_input_file would about the file itself (missing, unreadable, not a regular
/// file, too large) without reading it.
void check_input_file(const std::string& path);

/// A token fit for a one-line message: quoted, bytes outside printable ASCII as \xHH, cut after 40
/// characters.
std::string quote(std::string_view token);

/// "PATH:LINE" (line > 0) or "PATH"; the prefix of every located message.
struct Where {
  const std::string& path;
  int line = 0;
  std::string str() const;
};

/// Throws InputError "WHERE: what".
[[noreturn]] void fail(const Where& at, const std::string& what);

/// One line of a text file: its 1-based number and its text without the line break.
struct TextLine {
  int number = 0;
  std::string_view text;
};

/// The lines of a text (split at '\n'; a '\r' before it dropped), each cut at `comment` when that
/// is not '\0'. next() yields only lines holding a token.
class Lines {
 public:
  Lines(std::string_view text, char comment) : text_(text), comment_(comment) {}
  /// The next line holding a token (after the comment is cut), or nullopt at the end.
  std::optional<TextLine> next();
  /// The next line whatever it holds, or nullopt at the end.
  std::optional<TextLine> next_raw();
  /// Number of the last line read (the line count at the end).
  int line() const { return line_; }
  /// The bytes not read yet.
  std::string_view rest() const {
    return pos_ < text_.size() ? text_.substr(pos_) : std::string_view();
  }

 private:
  std::string_view text_;
  char comment_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

/// Whitespace between tokens: space, \t, \r, \v, \f.
bool is_space(char c);

/// The whitespace-separated tokens of a line, into `out` (cleared first).
void split(std::string_view line, std::vector<std::string_view>& out);

/// The whole token as a double (an optional '+' sign; "inf" and "nan" are read as such; a value
/// below the smallest subnormal is read as 0); nullopt for anything else or a magnitude overflowing
/// a double.
std::optional<double> parse_double(std::string_view token);

/// The whole token as a decimal integer (optional sign); nullopt for anything else or a value
/// outside the 64-bit range.
std::optional<std::int64_t> parse_integer(std::string_view token);

/// parse_double, finite, or InputError "WHERE: what: expected a finite number, found TOKEN".
double finite_number(const Where& at, const std::string& what, std::string_view token);

/// parse_integer, or InputError "WHERE: what: expected an integer, found TOKEN".
std::int64_t integer(const Where& at, const std::string& what, std::string_view token);

/// parse_integer in [lo, hi], or InputError naming `what`, the bounds and the token or its value.
std::int64_t integer_in(const Where& at, const std::string& what, std::string_view token,
                        std::int64_t lo, std::int64_t hi);

/// A 0-based index from `token`, read in [base, base + count) and returned minus base, or
/// InputError "WHERE: what V out of range [base, base + count)" (the exact value) or "WHERE: what:
/// expected an integer, found TOKEN".
int index_in(const Where& at, const std::string& what, std::string_view token, std::int64_t base,
             std::int64_t count);

/// Throws "WHERE: what: COUNT exceeds the limit of LIMIT" when count > limit.
void check_limit(const Where& at, const std::string& what, std::int64_t count, std::int64_t limit);

/// Appends the fan (v0, v_k, v_k+1) of a polygon of at least 3 vertex indices to `faces`, within
/// kMaxFaces.
void add_polygon(const Where& at, const std::vector<int>& polygon, std::vector<Triangle>& faces);

/// Makes every face refer to the first of the vertices with identical coordinates (+0 and −0
/// equal), the vertex list unchanged: a surface written with repeated vertices (seams of per-face
/// attributes) is closed as its coordinates say. O(n log n) whatever the input.
void join_identical_vertices(Mesh& mesh);

/// Keeps one copy of each distinct vertex (in order of first appearance) and renumbers the faces:
/// for formats that store each triangle's coordinates (STL).
void merge_identical_vertices(Mesh& mesh);

}  // namespace newtop::io::detail
