#pragma once
/// \file
/// Mesh and point-mass files for the mass models of newtop/exact: OBJ, OFF, STL and PLY through
/// Assimp, TetGen .node/.face, and CSV point masses.

#include <string>
#include <vector>

#include "newtop/exact/mass_models.hpp"

namespace newtop::io {

/// Vertices and triangles as found in a file (0-based indices).
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> faces;
};

/// Reads a triangle mesh. `FILE.node` or `FILE.face` reads the TetGen pair FILE.node + FILE.face
/// (0- or 1-based, as the first node index says); other extensions go through Assimp (OBJ, OFF,
/// STL, PLY, …) with identical vertices joined and polygons triangulated. Throws InputError
/// naming the file and what is wrong.
Mesh read_mesh(const std::string& path);

/// The homogeneous polyhedron of a mesh file, with coordinates multiplied by `scale` and the
/// given density; mesh errors are reported as `FILE: mesh: …`.
Polyhedron load_polyhedron(const std::string& path, double density, double scale = 1.0,
                           Orientation orientation = Orientation::check);

/// Point masses from CSV lines `m, x, y, z` (blank lines, `#` comments and one header line of
/// names allowed). Throws InputError naming the file and line.
PointMasses read_point_masses(const std::string& path);

}  // namespace newtop::io
