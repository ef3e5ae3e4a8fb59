// STL reader. Binary: an 80-byte header, a little-endian uint32 facet count, then 50 bytes a facet
// (normal, three corners as float32, a uint16 attribute). ASCII: `solid NAME`, facets `facet
// normal nx ny nz / outer loop / vertex x y z (three times) / endloop / endfacet`, `endsolid
// NAME`; several solids may follow each other; keywords in any case. A file is binary when its
// size is exactly 84 + 50 × count; otherwise it must begin with `solid`. The normals are checked
// to be numbers and ignored (the orientation comes from the order of the corners).

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh_formats.hpp"
#include "mesh_input.hpp"

namespace newtop::io::detail {
namespace {

constexpr std::size_t kHeader = 80, kPrefix = 84, kFacet = 50;

std::uint32_t u32_le(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + i])) << (8 * i);
  return v;
}

Mesh read_binary(const std::string& path, std::string_view b, std::uint32_t count) {
  check_limit({path}, "facet count", count, kMaxFaces);
  Mesh mesh;
  mesh.vertices.reserve(3 * static_cast<std::size_t>(count));  // the size was checked: 50 B each
  mesh.faces.reserve(count);
  for (std::uint32_t f = 0; f < count; ++f) {
    const std::size_t at = kPrefix + kFacet * static_cast<std::size_t>(f);
    for (int c = 0; c < 3; ++c) {
      Vec3 x;
      for (int k = 0; k < 3; ++k) {
        x[k] = std::bit_cast<float>(u32_le(b, at + 12 + 12 * c + 4 * k));
      }
      if (!x.allFinite()) {
        fail({path}, "facet " + std::to_string(f) + " (byte " + std::to_string(at) + "): corner " +
                         std::to_string(c) + ": expected finite coordinates, found " +
                         format_vector(x));
      }
      mesh.vertices.push_back(x);
    }
    const int v = 3 * static_cast<int>(f);
    mesh.faces.push_back({v, v + 1, v + 2});
  }
  return mesh;
}

/// The whitespace-separated tokens of an ASCII STL file with their line numbers.
class Tokens {
 public:
  Tokens(const std::string& path, std::string_view text) : path_(path), lines_(text, '\0') {}

  /// The next token, or an empty view at the end of the file.
  std::string_view next() {
    while (next_ >= tok_.size()) {
      const auto l = lines_.next();
      if (!l) return {};
      line_ = l->number;
      split(l->text, tok_);
      next_ = 0;
    }
    return tok_[next_++];
  }
  /// Drops the rest of the current line (a solid's name).
  void skip_line() { next_ = tok_.size(); }
  /// The next token, which must be `word` (in any case).
  void expect(std::string_view word) {
    const std::string_view t = next();
    if (!same(t, word)) {
      fail("expected `" + std::string(word) + "`, found " +
           (t.empty() ? std::string("the end of the file") : quote(t)));
    }
  }
  static bool same(std::string_view t, std::string_view word) {
    if (t.size() != word.size()) return false;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (std::tolower(static_cast<unsigned char>(t[i])) != word[i]) return false;
    }
    return true;
  }
  Where where() const { return {path_, line_}; }
  [[noreturn]] void fail(const std::string& what) const { detail::fail(where(), what); }

 private:
  const std::string& path_;
  Lines lines_;
  std::vector<std::string_view> tok_;
  std::size_t next_ = 0;
  int line_ = 0;
};

void read_facet(Tokens& in, Mesh& mesh) {
  const std::string what = "facet " + std::to_string(mesh.faces.size());
  in.expect("normal");
  for (int k = 0; k < 3; ++k) {
    const std::string_view t = in.next();
    if (!parse_double(t)) in.fail(what + ": normal: expected a number, found " + quote(t));
  }
  in.expect("outer");
  in.expect("loop");
  for (int c = 0; c < 3; ++c) {
    in.expect("vertex");
    Vec3 x;
    for (int k = 0; k < 3; ++k) x[k] = finite_number(in.where(), what, in.next());
    mesh.vertices.push_back(x);
  }
  in.expect("endloop");
  in.expect("endfacet");
  check_limit(in.where(), "number of facets", static_cast<std::int64_t>(mesh.faces.size()) + 1,
              kMaxFaces);
  const int v = static_cast<int>(mesh.vertices.size()) - 3;
  mesh.faces.push_back({v, v + 1, v + 2});
}

Mesh read_ascii(const std::string& path, std::string_view text) {
  Tokens in(path, text);
  Mesh mesh;
  for (std::string_view t = in.next(); !t.empty(); t = in.next()) {
    if (!Tokens::same(t, "solid")) in.fail("expected `solid`, found " + quote(t));
    in.skip_line();
    while (true) {
      t = in.next();
      if (Tokens::same(t, "endsolid")) break;
      if (!Tokens::same(t, "facet")) {
        in.fail("expected `facet` or `endsolid`, found " +
                (t.empty() ? std::string("the end of the file") : quote(t)));
      }
      read_facet(in, mesh);
    }
    in.skip_line();
  }
  return mesh;
}

}  // namespace

Mesh read_stl(const std::string& path, std::string_view bytes) {
  Mesh mesh;
  const bool sized = bytes.size() >= kPrefix;
  const std::uint64_t count = sized ? u32_le(bytes, kHeader) : 0;
  if (sized && bytes.size() == kPrefix + kFacet * count) {
    mesh = read_binary(path, bytes, static_cast<std::uint32_t>(count));
  } else {
    const std::size_t first = std::min(bytes.find_first_not_of(" \t\r\n\v\f"), bytes.size());
    if (!Tokens::same(bytes.substr(first, 5), "solid")) {
      fail({path}, sized ? "not an STL file: a binary STL of " + std::to_string(count) +
                               " facets has " + std::to_string(kPrefix + kFacet * count) +
                               " bytes, the file " + std::to_string(bytes.size()) +
                               ", and it does not begin with `solid`"
                         : "not an STL file: it does not begin with `solid` and is shorter than "
                           "the 84 bytes of a binary STL");
    }
    mesh = read_ascii(path, bytes);
  }
  merge_identical_vertices(mesh);
  check_limit({path}, "number of distinct vertices",
              static_cast<std::int64_t>(mesh.vertices.size()), kMaxVertices);
  return mesh;
}

}  // namespace newtop::io::detail
