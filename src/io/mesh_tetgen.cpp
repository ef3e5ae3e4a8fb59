// TetGen .node/.face reader (TetGen manual, §5.2). `.node`: `count 3 attributes markers` (markers
// 0 or 1), then `count` lines `index x y z [attributes…] [marker]`, the indices consecutive from
// 0 or 1 (the base); `.face`: `count markers`, then `count` lines `index i j k [marker]` (also
// with the two adjacent tetrahedra that `tetgen -nn` appends), the faces numbered consecutively
// and their nodes in the .node file's numbering. `#` starts a comment. Every integer is read
// exactly (a value outside its range is reported as written); counts must match the data.

#include <cstdint>
#include <string>
#include <vector>

#include "mesh_formats.hpp"
#include "mesh_input.hpp"

namespace newtop::io::detail {
namespace {

// An attribute count beyond this is no TetGen file; it keeps the expected line length small.
constexpr std::int64_t kMaxAttributes = 1024;

struct TetgenHeader {
  std::int64_t count = 0;
  std::vector<std::int64_t> values;  // the other header integers
  int line = 0;
};

TetgenHeader read_tetgen_header(const std::string& path, Lines& lines, std::size_t n,
                                std::int64_t limit, const char* form) {
  const auto l = lines.next();
  if (!l) fail({path}, std::string("expected a header `") + form + "`, found nothing");
  std::vector<std::string_view> tok;
  split(l->text, tok);
  const Where at{path, l->number};
  if (tok.size() != n) {
    fail(at, std::string("expected a header `") + form + "`, found " + std::to_string(tok.size()) +
                 " values");
  }
  TetgenHeader h;
  h.line = l->number;
  h.count = integer_in(at, "count", tok[0], 0, limit);
  for (std::size_t k = 1; k < n; ++k) {
    h.values.push_back(integer(at, std::string(form), tok[k]));
  }
  return h;
}

/// The index of the k-th node or face: base + k (TetGen numbers them consecutively).
void expect_label(const Where& at, const std::string& what, std::string_view token,
                  std::int64_t base, std::int64_t k) {
  const std::int64_t v = integer(at, what + " index", token);
  if (v != base + k) {
    fail(at, what + " index: expected " + std::to_string(base + k) +
                 " (numbered consecutively from " + std::to_string(base) + "), found " +
                 std::to_string(v));
  }
}

void check_tetgen_end(const std::string& path, Lines& lines, std::int64_t count, const char* what) {
  if (const auto extra = lines.next()) {
    fail({path, extra->number}, "expected the end of the file after the " + std::to_string(count) +
                                    " " + what + " the header announces, found more data");
  }
}

/// The nodes; `base` receives the first node's index (0 or 1).
std::vector<Vec3> read_nodes(const std::string& path, std::string_view bytes, std::int64_t& base) {
  Lines lines(bytes, '#');
  const TetgenHeader h =
      read_tetgen_header(path, lines, 4, kMaxVertices, "count 3 attributes markers");
  const Where at_head{path, h.line};
  if (h.values[0] != 3)
    fail(at_head, "dimension: expected 3, found " + std::to_string(h.values[0]));
  if (h.values[1] < 0 || h.values[1] > kMaxAttributes) {
    fail(at_head, "attributes: expected an integer in [0, " + std::to_string(kMaxAttributes) +
                      "], found " + std::to_string(h.values[1]));
  }
  if (h.values[2] != 0 && h.values[2] != 1) {
    fail(at_head, "markers: expected 0 or 1, found " + std::to_string(h.values[2]));
  }
  const auto width = static_cast<std::size_t>(4 + h.values[1] + h.values[2]);
  std::vector<Vec3> nodes;
  std::vector<std::string_view> tok;
  for (std::int64_t k = 0; k < h.count; ++k) {
    const auto l = lines.next();
    if (!l) {
      fail({path, lines.line()}, "the header announces " + std::to_string(h.count) +
                                     " nodes, the file ends after " + std::to_string(k));
    }
    const Where at{path, l->number};
    split(l->text, tok);
    if (tok.size() != width) {
      fail(at, "expected " + std::to_string(width) + " values (index x y z, " +
                   std::to_string(h.values[1]) + " attributes, " + std::to_string(h.values[2]) +
                   " marker), found " + std::to_string(tok.size()));
    }
    if (k == 0) base = integer_in(at, "first node index", tok[0], 0, 1);
    expect_label(at, "node", tok[0], base, k);
    const std::string what = "node " + std::to_string(base + k);
    nodes.emplace_back(finite_number(at, what, tok[1]), finite_number(at, what, tok[2]),
                       finite_number(at, what, tok[3]));
    for (std::size_t c = 4; c < tok.size(); ++c) (void)finite_number(at, what, tok[c]);
  }
  check_tetgen_end(path, lines, h.count, "nodes");
  return nodes;
}

}  // namespace

Mesh read_tetgen(const std::string& node_path, std::string_view node_bytes,
                 const std::string& face_path, std::string_view face_bytes) {
  Mesh mesh;
  std::int64_t base = 0;
  mesh.vertices = read_nodes(node_path, node_bytes, base);
  const auto nv = static_cast<std::int64_t>(mesh.vertices.size());
  Lines lines(face_bytes, '#');
  const TetgenHeader h = read_tetgen_header(face_path, lines, 2, kMaxFaces, "count markers");
  if (h.values[0] != 0 && h.values[0] != 1) {
    fail({face_path, h.line}, "markers: expected 0 or 1, found " + std::to_string(h.values[0]));
  }
  const auto width = static_cast<std::size_t>(4 + h.values[0]);
  std::vector<std::string_view> tok;
  std::int64_t first = 0;
  for (std::int64_t k = 0; k < h.count; ++k) {
    const auto l = lines.next();
    if (!l) {
      fail({face_path, lines.line()}, "the header announces " + std::to_string(h.count) +
                                          " faces, the file ends after " + std::to_string(k));
    }
    const Where at{face_path, l->number};
    split(l->text, tok);
    if (tok.size() != width && tok.size() != width + 2) {
      fail(at, "expected " + std::to_string(width) + " values (index i j k" +
                   (width > 4 ? " marker" : "") + ", optionally 2 adjacent tetrahedra), found " +
                   std::to_string(tok.size()));
    }
    if (k == 0) first = integer_in(at, "first face index", tok[0], 0, 1);
    expect_label(at, "face", tok[0], first, k);
    const std::string what = "face " + std::to_string(first + k) + ": node index";
    mesh.faces.push_back({index_in(at, what, tok[1], base, nv),
                          index_in(at, what, tok[2], base, nv),
                          index_in(at, what, tok[3], base, nv)});
    for (std::size_t c = 4; c < tok.size(); ++c) {
      (void)integer(at, "face " + std::to_string(first + k), tok[c]);
    }
  }
  check_tetgen_end(face_path, lines, h.count, "faces");
  return mesh;
}

}  // namespace newtop::io::detail
