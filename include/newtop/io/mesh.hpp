#pragma once
/// \file
/// Mesh and point-mass files for the mass models of newtop/exact: OBJ, OFF, PLY (ASCII and binary),
/// STL (ASCII and binary), TetGen .node/.face, and CSV point masses. Every format is read by a
/// strict reader of newtop's own (docs/fuzzing.md says why): any bytes give a result or one
/// InputError naming the file, the line (or record) and what was expected and found.

#include <cstdint>
#include <string>
#include <vector>

#include "newtop/exact/mass_models.hpp"

namespace newtop::io {

/// Largest file any reader of this header accepts: 1 GiB.
inline constexpr std::int64_t kMaxInputBytes = std::int64_t{1} << 30;
/// Most vertices (or TetGen nodes) a mesh file may hold: 2^24 = 16,777,216.
inline constexpr std::int64_t kMaxVertices = std::int64_t{1} << 24;
/// Most triangles a mesh may hold, counted after polygons are split: 2^25 = 33,554,432.
inline constexpr std::int64_t kMaxFaces = std::int64_t{1} << 25;
/// Most point masses a CSV file may hold: 2^24.
inline constexpr std::int64_t kMaxPointMasses = std::int64_t{1} << 24;

/// Vertices and triangles as found in a file (0-based indices). Every vertex is finite and every
/// index in range.
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> faces;
};

/// Reads a triangle mesh, the format chosen by the extension (any case): `.off` (OFF, COFF, NOFF,
/// CNOFF), `.ply` (ASCII, binary little or big endian), `.stl` (ASCII or binary), `.obj` (v and f
/// statements), or `.node` / `.face` for the TetGen pair FILE.node + FILE.face (0- or 1-based, as
/// the first node index says). Polygons are split into fans from their first vertex; in OFF, PLY
/// and OBJ, faces are made to refer to the first of the vertices with identical coordinates, and
/// an STL file's repeated corners become one vertex. Limits: kMaxInputBytes, kMaxVertices,
/// kMaxFaces. Throws InputError naming the file and what is wrong.
Mesh read_mesh(const std::string& path);

/// The homogeneous polyhedron of a mesh file, with coordinates multiplied by `scale` and the
/// given density; mesh errors are reported as `FILE: mesh: …`.
Polyhedron load_polyhedron(const std::string& path, double density, double scale = 1.0,
                           Orientation orientation = Orientation::check);

/// Point masses from CSV lines `m, x, y, z` (fields separated by commas, or by blanks on a line
/// without commas; blank lines and `#` comments allowed). The first line may be a header of four
/// names (fields that begin with a letter and are not numbers such as `inf`); every other field is
/// a finite number. At most kMaxPointMasses rows. Throws InputError naming the file, line and
/// column.
PointMasses read_point_masses(const std::string& path);

}  // namespace newtop::io
