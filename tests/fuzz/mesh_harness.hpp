#pragma once
// Shared by the mesh harnesses (fuzz_mesh_*.cpp, fuzz_tetgen.cpp): the reader's result must keep
// its promises (finite vertices, indices in range, counts within the limits), and the polyhedron
// built from it must be a result or an InputError too. A broken promise aborts, which libFuzzer and
// the corpus replay report like a crash.

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "harness.hpp"
#include "newtop/io/mesh.hpp"

namespace newtop::fuzz {

inline void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "a reader broke its promise: %s\n", what);
    std::abort();
  }
}

/// Checks what read_mesh promises about its result, then builds the polyhedron (reoriented, so
/// that the orientation repair runs too).
inline void check_mesh(const io::Mesh& m) {
  const auto nv = static_cast<std::int64_t>(m.vertices.size());
  require(nv <= io::kMaxVertices, "vertex count within kMaxVertices");
  require(static_cast<std::int64_t>(m.faces.size()) <= io::kMaxFaces,
          "face count within kMaxFaces");
  for (const Vec3& v : m.vertices) require(v.allFinite(), "finite vertices");
  for (const Triangle& t : m.faces) {
    for (const int c : t) require(c >= 0 && c < nv, "face indices in range");
  }
  (void)Polyhedron::make(m.vertices, m.faces, 1.0, Orientation::reorient);
}

/// The input as a mesh file with the given extension, through read_mesh.
inline int fuzz_mesh_file(const std::uint8_t* data, std::size_t size, std::string_view extension) {
  const TempFile file(std::string_view(reinterpret_cast<const char*>(data), size), extension);
  expect_result_or_input_error([&] { check_mesh(io::read_mesh(file.path())); });
  return 0;
}

}  // namespace newtop::fuzz
