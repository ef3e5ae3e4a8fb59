#pragma once
// Internal: newtop's strict readers of the mesh formats, each from the bytes of a file (`path`
// only names it in messages). Each returns a Mesh whose vertices are finite and whose indices are
// in range, or throws InputError "PATH[:LINE]: what".

#include <string>
#include <string_view>

#include "newtop/io/mesh.hpp"

namespace newtop::io::detail {

/// OFF (Princeton Shape Benchmark / Geomview): `[C][N]OFF`, `nv nf ne`, nv vertex lines, nf face
/// lines `n i1 … in [colour]`; `#` comments.
Mesh read_off(const std::string& path, std::string_view bytes);

/// PLY (Turk 1994): ascii, binary_little_endian or binary_big_endian 1.0; element vertex with x,
/// y, z and element face with the list vertex_indices (or vertex_index); other elements and
/// properties are read and skipped.
Mesh read_ply(const std::string& path, std::string_view bytes);

/// STL: binary (80-byte header, uint32 count, 50 bytes a facet) when the size says so, else ASCII
/// (`solid … facet normal … outer loop vertex ×3 endloop endfacet … endsolid`).
Mesh read_stl(const std::string& path, std::string_view bytes);

/// Wavefront OBJ, polygonal part: v and f (v, v/vt, v//vn, v/vt/vn, negative = relative); vt, vn,
/// vp, o, g, s, usemtl, mtllib, l and p are read and ignored; free-form geometry is refused.
Mesh read_obj(const std::string& path, std::string_view bytes);

/// TetGen pair: `node_path` (`count 3 attributes markers`, then `index x y z …`) and `face_path`
/// (`count markers`, then `index i j k [marker] [t1 t2]`).
Mesh read_tetgen(const std::string& node_path, std::string_view node_bytes,
                 const std::string& face_path, std::string_view face_bytes);

}  // namespace newtop::io::detail
