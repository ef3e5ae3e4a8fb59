// OFF reader: Object File Format as written by Geomview, the Princeton Shape Benchmark, MeshLab.
// One header keyword ([C][N]OFF), the counts `nv nf ne` (on the keyword's line or the next), nv
// vertex lines `x y z [nx ny nz] [r g b [a]]` and nf face lines `n i1 … in [r g b [a]]`; `#`
// starts a comment. The counts must match the data exactly: missing or extra lines are refused.

#include <cstdint>
#include <string>
#include <vector>

#include "mesh_formats.hpp"
#include "mesh_input.hpp"

namespace newtop::io::detail {
namespace {

struct OffLayout {
  bool normals = false;  // NOFF: x y z nx ny nz
  bool colours = false;  // COFF: x y z … r g b [a]
};

OffLayout keyword(const Where& at, std::string_view kw) {
  if (kw == "OFF") return {};
  if (kw == "COFF") return {false, true};
  if (kw == "NOFF") return {true, false};
  if (kw == "CNOFF") return {true, true};
  if (kw.size() > 3 && kw.substr(kw.size() - 3) == "OFF") {
    fail(at, "unsupported OFF variant " + quote(kw) + " (newtop reads OFF, COFF, NOFF, CNOFF)");
  }
  fail(at, "expected the keyword OFF, found " + quote(kw));
}

std::string count_of(std::int64_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

struct OffHeader {
  OffLayout layout;
  std::int64_t nv = 0, nf = 0;
  int line = 0;  // of the counts
};

/// The keyword and the counts, which follow the keyword on its line or make up the next line.
OffHeader read_header(const std::string& path, Lines& lines, std::vector<std::string_view>& tok) {
  const auto first = lines.next();
  if (!first) fail({path}, "expected the keyword OFF, found an empty file");
  split(first->text, tok);
  OffHeader h;
  h.layout = keyword({path, first->number}, tok[0]);
  if (tok.size() > 1 && tok[1] == "BINARY") {
    fail({path, first->number}, "binary OFF is not supported (write it as text)");
  }
  h.line = first->number;
  tok.erase(tok.begin());
  if (tok.empty()) {
    const auto next = lines.next();
    if (!next) fail({path, lines.line()}, "expected the counts `nv nf ne`, found the end of file");
    h.line = next->number;
    split(next->text, tok);
  }
  const Where at{path, h.line};
  if (tok.size() != 3) {
    fail(at, "expected the counts `nv nf ne`, found " + std::to_string(tok.size()) + " values");
  }
  h.nv = integer_in(at, "vertex count", tok[0], 0, kMaxVertices);
  h.nf = integer_in(at, "face count", tok[1], 0, kMaxFaces);
  (void)integer_in(at, "edge count", tok[2], 0, INT64_MAX);
  return h;
}

/// The next data line, the k-th of `count` the header announces.
TextLine next_line(const std::string& path, Lines& lines, const OffHeader& h, std::int64_t k,
                   std::int64_t count, const std::string& one, const std::string& many) {
  const auto l = lines.next();
  if (!l) {
    fail({path, lines.line()}, "the header (line " + std::to_string(h.line) + ") announces " +
                                   count_of(count, one, many) + ", the file ends after " +
                                   std::to_string(k));
  }
  return *l;
}

void read_vertex(const Where& at, std::int64_t i, const std::vector<std::string_view>& tok,
                 const OffLayout& layout, Mesh& mesh) {
  const std::size_t coords = 3 + (layout.normals ? 3 : 0);
  const bool fits = tok.size() == coords ||
                    (layout.colours && (tok.size() == coords + 3 || tok.size() == coords + 4));
  const std::string what = "vertex " + std::to_string(i);
  if (!fits) {
    fail(at, what + ": expected " + std::to_string(coords) +
                 (layout.colours ? " numbers and 3 or 4 colour values" : " numbers") + ", found " +
                 std::to_string(tok.size()) + " values");
  }
  for (std::size_t k = 3; k < tok.size(); ++k) (void)finite_number(at, what, tok[k]);
  mesh.vertices.emplace_back(finite_number(at, what, tok[0]), finite_number(at, what, tok[1]),
                             finite_number(at, what, tok[2]));
}

/// A face line `n i1 … in [r g b [a]]`.
void read_face(const Where& at, std::int64_t f, const std::vector<std::string_view>& tok,
               std::int64_t nv, std::vector<int>& polygon, Mesh& mesh) {
  const std::string what = "face " + std::to_string(f);
  const auto n =
      static_cast<std::size_t>(integer_in(at, what + ": vertex count", tok[0], 3, kMaxVertices));
  if (tok.size() < 1 + n || tok.size() > 1 + n + 4) {
    fail(at, what + ": expected " + std::to_string(n) +
                 " vertex indices and up to 4 colour values, found " +
                 std::to_string(tok.size() - 1) + " values");
  }
  polygon.clear();
  for (std::size_t k = 1; k <= n; ++k) {
    polygon.push_back(index_in(at, what + ": vertex index", tok[k], 0, nv));
  }
  for (std::size_t k = 1 + n; k < tok.size(); ++k) {
    (void)finite_number(at, what + ": colour", tok[k]);
  }
  add_polygon(at, polygon, mesh.faces);
}

}  // namespace

Mesh read_off(const std::string& path, std::string_view bytes) {
  Lines lines(bytes, '#');
  std::vector<std::string_view> tok;
  const OffHeader h = read_header(path, lines, tok);
  Mesh mesh;
  for (std::int64_t i = 0; i < h.nv; ++i) {
    const TextLine l = next_line(path, lines, h, i, h.nv, "vertex", "vertices");
    split(l.text, tok);
    read_vertex({path, l.number}, i, tok, h.layout, mesh);
  }
  std::vector<int> polygon;
  for (std::int64_t f = 0; f < h.nf; ++f) {
    const TextLine l = next_line(path, lines, h, f, h.nf, "face", "faces");
    split(l.text, tok);
    read_face({path, l.number}, f, tok, h.nv, polygon, mesh);
  }
  if (const auto extra = lines.next()) {
    split(extra->text, tok);
    fail({path, extra->number}, "expected the end of the file after the " +
                                    count_of(h.nf, "face", "faces") + " the header (line " +
                                    std::to_string(h.line) + ") announces, found " + quote(tok[0]));
  }
  join_identical_vertices(mesh);
  return mesh;
}

}  // namespace newtop::io::detail
