// Wavefront OBJ reader, polygonal part. `v x y z [w]` (w must be 1) or `v x y z r g b` (vertex
// colours), `f` (or the old `fo`) with corners `v`, `v/vt`, `v//vn` or `v/vt/vn` (1-based, negative
// counts back from the last vertex defined); every group and object goes into the one mesh.
// Texture and normal data, groups, smoothing, materials, points and lines do not shape a surface:
// they are read and ignored. Free-form curves and surfaces are refused.

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh_formats.hpp"
#include "mesh_input.hpp"

namespace newtop::io::detail {
namespace {

bool one_of(std::string_view kw, std::initializer_list<std::string_view> words) {
  return std::find(words.begin(), words.end(), kw) != words.end();
}

void read_vertex(const Where& at, const std::vector<std::string_view>& tok, Mesh& mesh) {
  const std::string what = "vertex " + std::to_string(mesh.vertices.size() + 1);
  if (tok.size() != 4 && tok.size() != 5 && tok.size() != 7) {
    fail(at, what + ": expected `v x y z [w]` or `v x y z r g b`, found " +
                 std::to_string(tok.size() - 1) + " values");
  }
  const Vec3 x(finite_number(at, what, tok[1]), finite_number(at, what, tok[2]),
               finite_number(at, what, tok[3]));
  if (tok.size() == 5) {
    const double w = finite_number(at, what + ": w", tok[4]);
    if (w != 1.0) fail(at, what + ": expected the weight w = 1, found " + format_number(w));
  }
  for (std::size_t k = 4; tok.size() == 7 && k < 7; ++k)
    (void)finite_number(at, what + ": colour", tok[k]);
  check_limit(at, "number of vertices", static_cast<std::int64_t>(mesh.vertices.size()) + 1,
              kMaxVertices);
  mesh.vertices.push_back(x);
}

/// The 0-based vertex of a corner `v[/vt[/vn]]`, the texture and normal parts checked to be
/// integers (or empty).
int corner(const Where& at, std::string_view t, std::int64_t nv) {
  std::array<std::string_view, 3> part{};
  std::size_t n = 0;
  for (std::size_t start = 0;; ++n) {
    const std::size_t slash = t.find('/', start);
    if (n == 3) fail(at, "face corner " + quote(t) + ": expected v, v/vt, v//vn or v/vt/vn");
    part[n] = t.substr(start, slash == std::string_view::npos ? slash : slash - start);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  for (std::size_t k = 1; k <= n; ++k) {
    if (!part[k].empty() && !parse_integer(part[k])) {
      fail(at, "face corner " + quote(t) + ": expected an integer index, found " + quote(part[k]));
    }
  }
  const auto v = parse_integer(part[0]);
  if (!v)
    fail(at, "face corner " + quote(t) + ": expected a vertex index, found " + quote(part[0]));
  if (*v == 0 || *v > nv || *v < -nv) {
    fail(at, "face: vertex index " + std::to_string(*v) + " out of range [1, " +
                 std::to_string(nv) + "] (or [-" + std::to_string(nv) + ", -1] from the end)");
  }
  return static_cast<int>(*v > 0 ? *v - 1 : nv + *v);
}

}  // namespace

Mesh read_obj(const std::string& path, std::string_view bytes) {
  Lines lines(bytes, '#');
  Mesh mesh;
  std::vector<std::string_view> tok;
  std::vector<int> polygon;
  while (const auto l = lines.next()) {
    const Where at{path, l->number};
    split(l->text, tok);
    const std::string_view kw = tok[0];
    if (kw == "v") {
      read_vertex(at, tok, mesh);
    } else if (kw == "f" || kw == "fo") {
      if (tok.size() < 4) {
        fail(at, "face: expected at least 3 corners, found " + std::to_string(tok.size() - 1));
      }
      const auto nv = static_cast<std::int64_t>(mesh.vertices.size());
      polygon.clear();
      for (std::size_t k = 1; k < tok.size(); ++k) polygon.push_back(corner(at, tok[k], nv));
      add_polygon(at, polygon, mesh.faces);
    } else if (one_of(kw, {"vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "l", "p",
                           "lod", "bevel", "c_interp", "d_interp", "usemap", "maplib", "shadow_obj",
                           "trace_obj"})) {
      continue;
    } else if (one_of(kw, {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim",
                           "hole", "scrv", "sp", "end", "con", "ctech", "stech"})) {
      fail(at, "free-form geometry (" + quote(kw) +
                   ") is not supported: newtop reads polygonal meshes (v and f)");
    } else {
      fail(at, "unknown OBJ statement " + quote(kw));
    }
  }
  join_identical_vertices(mesh);
  return mesh;
}

}  // namespace newtop::io::detail
